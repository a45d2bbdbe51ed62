import { describe, expect, it } from 'vitest';
import { World, particle } from '@physical/engine';
import { bodyStates, hashWorld } from '@physical/scenes';

function oneBall(x: number): World {
  const world = new World();
  world.add(particle({ position: { x, y: 0 }, radius: 0.5 }));
  return world;
}

describe('hashWorld', () => {
  it('records position, angle and both velocities of every body', () => {
    const world = oneBall(1.5);
    world.bodies[0]!.linearVelocity = { x: 2, y: 3 };
    world.bodies[0]!.angularVelocity = 4;
    expect(Array.from(bodyStates(world))).toEqual([1.5, 0, 0, 2, 3, 4]);
  });

  it('changes when a single bit of one coordinate changes', () => {
    const x = 1.5;
    const next = x + Number.EPSILON; // the next float64 after 1.5
    expect(next).not.toBe(x);
    expect(hashWorld(oneBall(next))).not.toBe(hashWorld(oneBall(x)));
  });

  it('is 32-bit FNV-1a of the state bytes: an empty world hashes to the offset basis', () => {
    expect(hashWorld(new World())).toBe('811c9dc5');
  });
});
