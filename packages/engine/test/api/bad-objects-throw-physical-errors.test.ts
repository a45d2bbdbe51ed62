import { describe, expect, it } from 'vitest';
import { World, box, particle, polygon, takeSnapshot, wall } from '@physical/engine';
import { physicalErrorOf } from './expect-physical-error.ts';

// Finding 13: a null, undefined or wrong object is a PhysicalError naming the field, never a bare
// TypeError from reading a property of it.

const world = (): World => {
  const w = new World();
  w.add(box({ width: 1, height: 1 }));
  return w;
};

describe('bad objects throw PhysicalErrors', () => {
  it.each([
    ['options', () => particle(undefined as never)],
    ['options', () => particle(null as never)],
    ['options', () => box(null as never)],
    ['options', () => polygon(undefined as never)],
    ['options', () => wall(null as never)],
    ['box', () => world().bodiesInAABB(null as never)],
    ['shape', () => world().shapeCast(null as never, { position: { x: 0, y: 0 } }, { x: 1, y: 0 })],
    ['pose', () => world().shapeCast({ type: 'circle', radius: 1 }, null as never, { x: 1, y: 0 })],
    ['shape', () => world().overlapShape(null as never, { position: { x: 0, y: 0 } })],
    ['world', () => takeSnapshot(null as never)],
    ['world', () => takeSnapshot({} as never)],
    ['point', () => world().bodyAt(null as never)],
    ['visitor', () => world().forEachContact(null as never)],
    ['force', () => particle({ radius: 1 }).removeForce(null as never)],
  ])('%s', (field, action) => {
    expect(physicalErrorOf(action).field).toBe(field);
  });

  it('has(null) is simply false', () => {
    expect(world().has(null as never)).toBe(false);
  });
});
