import { describe, expect, it } from 'vitest';
import { World, box, particle, restoreSnapshot, takeSnapshot } from '@physical/engine';
import type { WorldSnapshot } from '@physical/engine';
import { physicalErrorOf } from './expect-physical-error.ts';

// Finding 10: a message quotes at most a short, cut rendering of the bad value, never all of it.

const huge = 'x'.repeat(5_000_000);
const LIMIT = 400;

describe('error messages are short', () => {
  it.each([
    ['a shape type', () => box({ width: 1, height: 1 }).addShape({ type: huge } as never)],
    ['a number', () => particle({ radius: huge as unknown as number })],
    ['a body type', () => particle({ radius: 1, type: huge as never })],
    [
      'a duration',
      () => particle({ radius: 1 }).applyForce({ x: 1, y: 0 }, { duration: huge as never }),
    ],
    ['a vector', () => particle({ radius: 1, position: huge as never })],
    ['an event name', () => new World().on(huge as never, (() => {}) as never)],
    ['a flag', () => particle({ radius: 1, bullet: huge as never })],
    ['world options', () => new World(huge as never)],
    ['a body to add', () => new World().add(huge as never)],
  ])('%s', (_name, action) => {
    const error = physicalErrorOf(action);
    expect(error.message.length).toBeLessThan(LIMIT);
    expect(error.message).toContain('xxxx');
  });

  it('a snapshot with a huge string in it', () => {
    const world = new World();
    world.add(particle({ radius: 1 }));
    const snapshot = JSON.parse(JSON.stringify(takeSnapshot(world))) as Record<string, unknown>;
    snapshot['format'] = huge;
    const error = physicalErrorOf(() => restoreSnapshot(snapshot as unknown as WorldSnapshot));
    expect(error.message.length).toBeLessThan(LIMIT);
    const bodies = JSON.parse(JSON.stringify(takeSnapshot(world))) as {
      bodies: Record<string, unknown>[];
    };
    bodies.bodies[0]!['angle'] = huge;
    const second = physicalErrorOf(() => restoreSnapshot(bodies as unknown as WorldSnapshot));
    expect(second.message.length).toBeLessThan(LIMIT);
  });
});
