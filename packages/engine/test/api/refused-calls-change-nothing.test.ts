import { describe, expect, it } from 'vitest';
import { World, box, particle, takeSnapshot, restoreSnapshot } from '@physical/engine';
import type { Vec2Like } from '@physical/engine';
import { physicalErrorOf } from './expect-physical-error.ts';

// Check, then change: a refused call leaves the world bit-for-bit as it was (its snapshot is
// unchanged) and the world keeps stepping and saving.

function scene(): { world: World; body: ReturnType<typeof box> } {
  const world = new World();
  const body = world.add(box({ position: { x: 0, y: 0 }, width: 1, height: 1 }));
  world.step();
  return { world, body };
}

function expectUnchanged(world: World, action: () => unknown): void {
  const before = JSON.stringify(takeSnapshot(world));
  physicalErrorOf(action);
  expect(JSON.stringify(takeSnapshot(world))).toBe(before);
  world.step();
  expect(() => restoreSnapshot(takeSnapshot(world))).not.toThrow();
}

describe('a refused call changes nothing', () => {
  it('addShape of a segment on a dynamic body leaves the shapes as they were (finding 1)', () => {
    const { world, body } = scene();
    expectUnchanged(world, () =>
      body.addShape({ type: 'segment', from: { x: 0, y: 0 }, to: { x: 1, y: 0 } }),
    );
    expect(body.shapes.length).toBe(1);
  });

  it('addShape of a density-0 shape on a dynamic body is refused whole', () => {
    const { world, body } = scene();
    expectUnchanged(world, () => body.addShape({ type: 'circle', radius: 0.5, density: 0 }));
    expect(body.shapes.length).toBe(1);
  });

  it('removeShape of the last shape of a dynamic body keeps the shape and the mass (finding 2)', () => {
    const { world, body } = scene();
    const mass = body.mass;
    expectUnchanged(world, () => body.removeShape(body.shapes[0]!));
    expect(body.shapes.length).toBe(1);
    expect(body.mass).toBe(mass);
  });

  it('applyImpulse with a NaN point applies nothing (finding 5)', () => {
    const { world, body } = scene();
    expectUnchanged(world, () => body.applyImpulse({ x: 5, y: 0 }, { x: NaN, y: 0 }));
  });

  it('a mass setter whose mass is out of range changes nothing', () => {
    const { world, body } = scene();
    expectUnchanged(world, () => {
      body.mass = 1e-300;
    });
  });

  it('fixedRotation with a non-boolean changes nothing', () => {
    const { world, body } = scene();
    expectUnchanged(world, () => {
      (body as { fixedRotation: unknown }).fixedRotation = 'no';
    });
  });

  it('applyForce with a bad point attaches no force', () => {
    const { world, body } = scene();
    const point: Vec2Like = { x: Infinity, y: 0 };
    expectUnchanged(world, () => body.applyForce({ x: 1, y: 0 }, { point, duration: 'constant' }));
    expect(body.forces.length).toBe(0);
  });

  it('a particle with a bad option is never built', () => {
    physicalErrorOf(() => particle({ radius: 1, allowSleep: 'yes' as unknown as boolean }));
  });
});
