import { describe, expect, it } from 'vitest';
import {
  World,
  box,
  particle,
  restoreSnapshot,
  takeSnapshot,
  wall,
  type Shape,
} from '@physical/engine';
import { AABB } from '../../../src/geometry/aabb.ts';
import { computeCapsuleAABB } from '../../../src/geometry/capsule.ts';
import { computeCircleAABB } from '../../../src/geometry/circle.ts';
import { computePolygonAABB } from '../../../src/geometry/polygon-queries.ts';
import { computeSegmentAABB } from '../../../src/geometry/segment.ts';
import { GEOMETRY_STRIDE } from '../../../src/dynamics/shape-geometry.ts';

// A shape's numbers live once, in the shape table (shape-table.ts): the world's, at the row of
// its id, which the narrow phase reads without loading the Shape; or a table of its own outside a
// world. A stale box would skip a contact that touches, and a shape that left its world must not
// write the row its id now names for another shape.

type Internals = ReturnType<World['internals']>;

/** The tight box of `shape` at its body's pose, computed here from the geometry alone. */
function expectedTight(shape: Shape): number[] {
  const g = shape.geometry;
  const xf = shape.body.transform;
  const out = new AABB();
  if (g.kind === 'circle') computeCircleAABB(g, xf, out);
  else if (g.kind === 'polygon') computePolygonAABB(g, xf, out);
  else if (g.kind === 'capsule') computeCapsuleAABB(g, xf, out);
  else computeSegmentAABB(g, xf, out);
  return [out.minX, out.minY, out.maxX, out.maxY];
}

/**
 * The geometry row the kernel's narrow phase reads for `shape` (layout in shape-geometry.ts:
 * kind, radius, count, centroid, one-sided, then vertices and normals), from its geometry.
 */
function expectedGeometryRow(shape: Shape): number[] {
  const g = shape.geometry;
  const row = new Array<number>(GEOMETRY_STRIDE).fill(0);
  const points = (list: number[]): void => list.forEach((v, i) => (row[6 + i] = v));
  if (g.kind === 'circle') {
    row.splice(0, 3, 0, g.radius, 1);
    points([g.centerX, g.centerY]);
  } else if (g.kind === 'capsule') {
    row.splice(0, 3, 1, g.radius, 2);
    points([g.x1, g.y1, g.x2, g.y2]);
  } else if (g.kind === 'segment') {
    row.splice(0, 6, 3, 0, 2, 0, 0, g.oneSided ? 1 : 0);
    points([g.x1, g.y1, g.x2, g.y2]);
  } else {
    row.splice(0, 5, 2, g.radius, g.count, g.centroidX, g.centroidY);
    points(Array.from(g.vertices.subarray(0, 2 * g.count)));
    Array.from(g.normals.subarray(0, 2 * g.count)).forEach((v, i) => (row[22 + i] = v));
  }
  return row;
}

/** Checks every shape of `world` against its row; returns how many it checked. */
function expectRowsMatch(world: World): number {
  const { shapesById, shapeTable, broadPhase } = world.internals() as Internals;
  let checked = 0;
  for (const shape of shapesById) {
    if (shape === null) continue;
    expect(shape.table).toBe(shapeTable);
    expect(shape.row).toBe(shape.id);
    const p = shape.id * 8;
    expect(Array.from(shapeTable.data.subarray(p, p + 4))).toEqual(expectedTight(shape));
    const fat = broadPhase.getFatAABB(shape.proxyKey, new AABB());
    expect(Array.from(shapeTable.data.subarray(p + 4, p + 8))).toEqual([
      fat.minX,
      fat.minY,
      fat.maxX,
      fat.maxY,
    ]);
    expect(shapeTable.geometries[shape.id]).toBe(shape.geometry);
    const g = shape.id * GEOMETRY_STRIDE;
    expect(Array.from(shapeTable.geometry.subarray(g, g + GEOMETRY_STRIDE))).toEqual(
      expectedGeometryRow(shape),
    );
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

describe('the shape table, where shapes keep their numbers', () => {
  it("holds every shape's boxes at its pose and fat box after steps, teleports, removals and a restore", () => {
    const world = pile();
    for (let step = 0; step < 90; step++) world.step(1 / 60);
    expect(expectRowsMatch(world)).toBe(13);

    // A body moved between steps by a setter, another removed, and a new one taking its id.
    const [, first, second] = world.bodies;
    first!.position = { x: 4, y: -1 };
    first!.angle = 0.7;
    world.remove(second!);
    world.add(box({ position: { x: 0, y: -3 }, width: 1, height: 0.2 }));
    expectRowsMatch(world);
    for (let step = 0; step < 30; step++) world.step(1 / 60);
    expectRowsMatch(world);

    const restored = restoreSnapshot(takeSnapshot(world));
    expect(expectRowsMatch(restored)).toBe(13);
  });

  it("keeps every row in the solver memory's shape regions as the world grows past their first room", () => {
    const world = pile();
    world.step(1 / 60);
    const { shapeTable } = world.internals() as Internals;
    expect(shapeTable.data.length).toBe(64 * 8);
    // 64 rows at first: 100 more shapes move the memory, and every view with it.
    for (let i = 0; i < 100; i++) {
      world.add(
        i % 2 === 0
          ? particle({ position: { x: -4 + 0.08 * i, y: -10 - (i % 5) }, radius: 0.05 })
          : box({ position: { x: -4 + 0.08 * i, y: -12 - (i % 7) }, width: 0.06, height: 0.05 }),
      );
    }
    // Room for all 113 rows (the world's foreseen room grows by half: 96, then 144 rows).
    expect(shapeTable.data.length).toBe(144 * 8);
    expect(shapeTable.geometry.buffer).toBe(shapeTable.data.buffer);
    expect(shapeTable.filters.buffer).toBe(shapeTable.data.buffer);
    expect(expectRowsMatch(world)).toBe(113);
    for (let step = 0; step < 20; step++) world.step(1 / 60);
    expect(expectRowsMatch(world)).toBe(113);
  });

  it('writes a filter into the row the narrow phase reads (bits as int32)', () => {
    const world = pile();
    world.step(1 / 60);
    const shape = world.bodies[2]!.shapes[0]!;
    shape.filter = { category: 0x80000000, mask: 0xfffffffe, group: -3 };
    const { shapeTable } = world.internals() as Internals;
    const p = shape.id * 4;
    expect(Array.from(shapeTable.filters.subarray(p, p + 4))).toEqual([
      0x80000000 | 0,
      0xfffffffe | 0,
      -3,
      0,
    ]);
    expect(shape.filter).toEqual({ category: 0x80000000, mask: 0xfffffffe, group: -3 });
  });

  it("keeps a shape's numbers through add and remove, in a table of its own outside a world", () => {
    const world = pile();
    const body = box({
      position: { x: 3, y: -2 },
      width: 0.5,
      height: 0.5,
      friction: 0.3,
      restitution: 0.45,
      density: 2.5,
      filter: { category: 4, mask: 0xfffffff0, group: 7 },
    });
    const shape = body.shapes[0]!;
    const geometry = shape.geometry;
    const own = shape.table;
    world.add(body);
    world.step(1 / 60);
    const { shapeTable } = world.internals() as Internals;
    expect(shape.table).toBe(shapeTable);
    shape.friction = 0.2;
    world.remove(body);
    expect(shape.table).not.toBe(shapeTable);
    expect(shape.table).not.toBe(own);
    expect(shape.row).toBe(0);
    expect([shape.friction, shape.restitution, shape.density]).toEqual([0.2, 0.45, 2.5]);
    expect(shape.filter).toEqual({ category: 4, mask: 0xfffffff0, group: 7 });
    expect(shape.sensor).toBe(false);
    expect(shape.geometry).toBe(geometry);
    // Added again, its numbers come with it.
    world.add(body);
    expect(shape.table).toBe(shapeTable);
    expect([shape.friction, shape.restitution, shape.density]).toEqual([0.2, 0.45, 2.5]);
    expect(shape.filter).toEqual({ category: 4, mask: 0xfffffff0, group: 7 });
  });

  it('is not written by a shape that left its world, even when its id is reused', () => {
    const world = pile();
    world.step(1 / 60);
    const removed = world.bodies[3]!;
    const oldId = removed.shapes[0]!.id;
    world.remove(removed);
    const newcomer = world.add(box({ position: { x: 1, y: -4 }, width: 0.5, height: 0.5 }));
    expect(newcomer.shapes[0]!.id).toBe(oldId);
    const { shapeTable } = world.internals() as Internals;
    const row = Array.from(shapeTable.data.subarray(oldId * 8, oldId * 8 + 8));
    // The removed body still works as an object: reading its bounds recomputes its box.
    removed.position = { x: 100, y: 100 };
    expect(removed.shapes[0]!.getBounds().minX).toBeGreaterThan(99);
    removed.shapes[0]!.friction = 0.1;
    expect(Array.from(shapeTable.data.subarray(oldId * 8, oldId * 8 + 8))).toEqual(row);
    expect(newcomer.shapes[0]!.friction).toBe(0.6);
    expectRowsMatch(world);
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
