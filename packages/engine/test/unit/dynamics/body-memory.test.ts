import { describe, expect, it } from 'vitest';
import { World, box, particle, wall, type Body } from '@physical/engine';
import {
  BODY_STRIDE,
  B_ANGLE,
  B_AWAKE,
  B_INV_MASS,
  B_VX,
  B_W,
  B_X,
  B_Y,
} from '../../../src/dynamics/body-memory.ts';

// A body's numbers live in one place: the world's body memory (a region of its solver memory,
// by world index) while it is in a world, a small array of its own before and after. The Body is
// a handle over them. These tests check that a handle always reads and writes the one copy the
// step's passes use, across adds, removals (which shift later bodies down), memory growth and
// shrinking, and that a body leaving a world takes its numbers with it.

type Internals = ReturnType<World['internals']>;

/** The world's body memory (its solver memory's BODIES region) and its bodies. */
function memoryOf(world: World): { data: Float64Array; bodies: readonly Body[] } {
  const { bodies } = world.internals() as Internals;
  const data = bodies.length > 0 ? bodies[0]!.store.data : new Float64Array(0);
  return { data, bodies };
}

/** Every body reads its numbers at its own world index of the world's body memory. */
function expectHandlesInPlace(world: World): void {
  const { data, bodies } = memoryOf(world);
  bodies.forEach((body, index) => {
    expect(body.store).toBe(bodies[0]!.store);
    expect(body.base).toBe(index * BODY_STRIDE);
    const b = index * BODY_STRIDE;
    expect([data[b + B_X], data[b + B_Y], data[b + B_ANGLE]]).toEqual([
      body.position.x,
      body.position.y,
      body.angle,
    ]);
    expect([data[b + B_VX], data[b + B_W]]).toEqual([body.linearVelocity.x, body.angularVelocity]);
    expect(data[b + B_AWAKE]).toBe(body.isAwake ? 1 : 0);
  });
}

function pile(count: number): World {
  const world = new World({ gravity: { x: 0, y: 9.81 } });
  world.add(wall({ from: { x: -20, y: 3 }, to: { x: 20, y: 3 } }));
  for (let i = 0; i < count; i++) {
    world.add(
      box({
        position: { x: -15 + 0.45 * (i % 60), y: 2 - 0.5 * Math.floor(i / 60) },
        width: 0.4,
        height: 0.4,
        linearVelocity: { x: 0.1 * (i % 7), y: 0 },
      }),
    );
  }
  return world;
}

describe("a body's numbers live in its world's body memory", () => {
  it('are copied in on add: the handle then reads and writes the world memory in place', () => {
    const body = particle({
      position: { x: 1.25, y: -2.5 },
      radius: 0.5,
      angle: 0.75,
      linearVelocity: { x: 3, y: 4 },
    });
    const local = body.store;
    const world = new World();
    world.add(wall({ from: { x: -5, y: 3 }, to: { x: 5, y: 3 } }));
    world.add(body);
    expect(body.store).not.toBe(local);
    const { data } = memoryOf(world);
    const b = body.base;
    expect(b).toBe(BODY_STRIDE);
    expect([data[b + B_X], data[b + B_Y], data[b + B_ANGLE], data[b + B_VX]]).toEqual([
      1.25, -2.5, 0.75, 3,
    ]);
    // A write to the memory is what the handle reads, and a setter writes the memory.
    data[b + B_X] = 7.5;
    expect(body.position.x).toBe(7.5);
    body.linearVelocity = { x: -1, y: 0.5 };
    expect(data[b + B_VX]).toBe(-1);
    expect(data[b + B_INV_MASS]).toBe(1 / body.mass);
    world.step(1 / 60);
    expectHandlesInPlace(world);
  });

  it('follow their bodies when an earlier body leaves, and leave with a removed body', () => {
    const world = pile(30);
    for (let step = 0; step < 30; step++) world.step(1 / 60);
    const { bodies } = memoryOf(world);
    const removed = bodies[5]!;
    const after = bodies.slice(6).map((body) => [body.position.x, body.position.y, body.angle]);
    const kept = [removed.position.x, removed.position.y, removed.linearVelocity.y, removed.mass];
    world.remove(removed);
    // The removed body keeps its numbers in a store of its own; the world's memory no longer holds them.
    expect(removed.base).toBe(0);
    expect(removed.store.data.length).toBe(BODY_STRIDE);
    expect([
      removed.position.x,
      removed.position.y,
      removed.linearVelocity.y,
      removed.mass,
    ]).toEqual(kept);
    expect(
      memoryOf(world)
        .bodies.slice(5)
        .map((body) => [body.position.x, body.position.y, body.angle]),
    ).toEqual(after);
    expectHandlesInPlace(world);
    // Changing the removed body changes nothing in the world.
    const before = Array.from(memoryOf(world).data.subarray(0, 30 * BODY_STRIDE));
    removed.position = { x: 100, y: 100 };
    expect(Array.from(memoryOf(world).data.subarray(0, 30 * BODY_STRIDE))).toEqual(before);
    // And it can join again, with the numbers it left with.
    world.add(removed);
    expect(removed.position.x).toBe(100);
    world.step(1 / 60);
    expectHandlesInPlace(world);
  });

  it('survive the memory growing (views replaced) and shrinking after most bodies leave', () => {
    const world = pile(4);
    world.step(1 / 60);
    const first = memoryOf(world).bodies[1]!;
    const firstData = first.store.data;
    // 1,100 more bodies: the body region grows by doubling, and every view is replaced.
    for (let i = 0; i < 1100; i++) {
      world.add(
        particle({
          position: { x: (i % 100) * 0.3 - 15, y: -3 - 0.3 * Math.floor(i / 100) },
          radius: 0.1,
        }),
      );
    }
    expect(first.store.data).not.toBe(firstData);
    for (let step = 0; step < 2; step++) world.step(1 / 60);
    expectHandlesInPlace(world);
    // Removing most of them shrinks the memory (World.releaseMemory); the rest keep their numbers.
    const bodies = memoryOf(world).bodies;
    const big = bodies[0]!.store.data.length;
    const leaving = bodies.slice(100).reverse();
    const staying = bodies.slice(0, 100).map((body) => [body.position.x, body.position.y]);
    for (const body of leaving) world.remove(body);
    expect(memoryOf(world).data.length).toBeLessThan(big);
    expect(memoryOf(world).bodies.map((body) => [body.position.x, body.position.y])).toEqual(
      staying,
    );
    world.step(1 / 60);
    expectHandlesInPlace(world);
  });
});
