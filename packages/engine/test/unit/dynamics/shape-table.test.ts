import { describe, expect, it } from 'vitest';
import { World, box, particle, restoreSnapshot, takeSnapshot, wall } from '@physical/engine';

// The narrow phase decides most contacts from flat copies of the shapes' boxes (shape-table.ts)
// and the bodies' own numbers (body-memory.ts, read in place). A stale copy would skip a contact that touches, so
// every path that moves a box must write the copy too, and a shape that left its world must not.

type Internals = ReturnType<World['internals']>;

function expectCopiesMatch(world: World): number {
  const { shapesById, shapeTable } = world.internals() as Internals;
  let checked = 0;
  for (const shape of shapesById) {
    if (shape === null) continue;
    const p = shape.id * 8;
    const copy = Array.from(shapeTable.data.subarray(p, p + 8));
    const { aabb, fatAABB } = shape;
    expect(copy).toEqual([
      aabb.minX,
      aabb.minY,
      aabb.maxX,
      aabb.maxY,
      fatAABB.minX,
      fatAABB.minY,
      fatAABB.maxX,
      fatAABB.maxY,
    ]);
    const f = Array.from(shapeTable.filters.subarray(shape.id * 4, shape.id * 4 + 4));
    expect(f).toEqual([
      shape.categoryBits | 0,
      shape.maskBits | 0,
      shape.groupIndex,
      shape.sensor ? 1 : 0,
    ]);
    expect(shapeTable.geometries[shape.id]).toBe(shape.geometry);
    checked++;
  }
  return checked;
}

function pile(): World {
  const world = new World({ gravity: { x: 0, y: 9.81 } });
  world.add(wall({ from: { x: -5, y: 3 }, to: { x: 5, y: 3 } }));
  for (let i = 0; i < 12; i++) {
    world.add(
      i % 3 === 0
        ? particle({ position: { x: -2 + 0.37 * i, y: -0.6 * i }, radius: 0.2 })
        : box({ position: { x: -2 + 0.41 * i, y: -0.6 * i }, width: 0.4, height: 0.3 }),
    );
  }
  return world;
}

describe("the contact loops' shape table (boxes, filters, geometries)", () => {
  it('equals every shape after steps, teleports, filter changes, removals, adds and a restore', () => {
    const world = pile();
    for (let step = 0; step < 90; step++) world.step(1 / 60);
    expect(expectCopiesMatch(world)).toBe(13);

    // A body moved between steps by a setter, another removed, and a new one taking its id.
    const [, first, second] = world.bodies;
    first!.position = { x: 4, y: -1 };
    first!.angle = 0.7;
    first!.shapes[0]!.filter = { category: 0x80000000, mask: 0xfffffffe, group: -3 };
    world.remove(second!);
    world.add(box({ position: { x: 0, y: -3 }, width: 1, height: 0.2 }));
    expectCopiesMatch(world);
    for (let step = 0; step < 30; step++) world.step(1 / 60);
    expectCopiesMatch(world);

    const restored = restoreSnapshot(takeSnapshot(world));
    expect(expectCopiesMatch(restored)).toBe(13);
  });

  it('is not written by a shape that left its world, even when its id is reused', () => {
    const world = pile();
    world.step(1 / 60);
    const removed = world.bodies[3]!;
    const oldId = removed.shapes[0]!.id;
    world.remove(removed);
    const newcomer = world.add(box({ position: { x: 1, y: -4 }, width: 0.5, height: 0.5 }));
    expect(newcomer.shapes[0]!.id).toBe(oldId);
    // The removed body still works as an object: reading its bounds recomputes its box.
    removed.position = { x: 100, y: 100 };
    removed.shapes[0]!.getBounds();
    expectCopiesMatch(world);
  });

  it('a body teleported onto another between steps touches it at the next step', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const a = world.add(box({ position: { x: 0, y: 0 }, width: 1, height: 1 }));
    const b = world.add(box({ position: { x: 10, y: 0 }, width: 1, height: 1 }));
    const touching = (): number => {
      let count = 0;
      world.forEachContact((c) => {
        if ((c.bodyA === a && c.bodyB === b) || (c.bodyA === b && c.bodyB === a)) count++;
      });
      return count;
    };
    world.step(1 / 60);
    expect(touching()).toBe(0);
    b.position = { x: 0.9, y: 0 }; // 0.1 m of overlap
    world.step(1 / 60);
    expect(touching()).toBe(1);
    expect(b.position.x - a.position.x).toBeGreaterThan(0.9);
  });
});
