import { describe, expect, it } from 'vitest';
import { Body, PhysicalError, World, capsule, particle, polygon, wall } from '@physical/engine';
import type { Capsule, Polygon } from '@physical/engine';

// Capsules, rounded boxes and concave polygons as users see them: bad input gets a PhysicalError
// naming the field; good input gives bodies that queries and the step handle.

function errorOf(action: () => unknown): PhysicalError {
  try {
    action();
  } catch (error) {
    if (error instanceof PhysicalError) return error;
    throw new Error(`expected a PhysicalError, got ${String(error)}`, { cause: error });
  }
  throw new Error('expected a PhysicalError, but nothing was thrown');
}

const square = [
  { x: 0, y: 0 },
  { x: 1, y: 0 },
  { x: 1, y: 1 },
  { x: 0, y: 1 },
];

describe('capsule input', () => {
  it.each([
    ['length', () => capsule({ length: NaN, radius: 0.2 })],
    ['length', () => capsule({ length: 0, radius: 0.2 })],
    ['length', () => capsule({ length: -1, radius: 0.2 })],
    ['radius', () => capsule({ length: 1, radius: 0 })],
    ['radius', () => capsule({ length: 1, radius: Infinity })],
    ['density', () => capsule({ length: 1, radius: 0.2, density: 0 })],
    [
      'shapes[0].center1',
      () =>
        new Body({
          shapes: [{ type: 'capsule', center1: null as never, center2: { x: 1, y: 0 }, radius: 1 }],
        }),
    ],
    [
      'shapes[0].center2.y',
      () =>
        new Body({
          shapes: [
            { type: 'capsule', center1: { x: 0, y: 0 }, center2: { x: 1, y: NaN }, radius: 1 },
          ],
        }),
    ],
    [
      'shapes[0]',
      () =>
        new Body({
          shapes: [
            { type: 'capsule', center1: { x: 0, y: 0 }, center2: { x: 0, y: 0 }, radius: 1 },
          ],
        }),
    ],
  ])('names %s', (field, action) => {
    expect(errorOf(action).field).toBe(field);
  });

  it('suggests a particle for a capsule without length', () => {
    expect(errorOf(() => capsule({ length: 0, radius: 0.2 })).message).toMatch(/particle/);
  });

  it('is horizontal by default, turned by angle, and found by queries', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const pill = world.add(capsule({ position: { x: 2, y: 1 }, length: 2, radius: 0.5 }));
    const geometry = pill.shapes[0]!.geometry as Capsule;
    expect([geometry.kind, geometry.x1, geometry.x2, geometry.y1, geometry.y2]).toEqual([
      'capsule',
      -1,
      1,
      0,
      0,
    ]);
    expect(world.bodyAt({ x: 3.4, y: 1 })).toBe(pill);
    expect(world.bodyAt({ x: 3.4, y: 1.4 })).toBeNull();
    const hit = world.rayCast({ x: 10, y: 1 }, { x: 0, y: 1 });
    expect(hit?.body).toBe(pill);
    expect(hit?.point.x).toBeCloseTo(3.5, 12);
    const bounds = pill.shapes[0]!.getBounds();
    expect([bounds.minX, bounds.maxX, bounds.minY, bounds.maxY]).toEqual([0.5, 3.5, 0.5, 1.5]);
    const upright = capsule({ length: 2, radius: 0.5, angle: Math.PI / 2 });
    expect(upright.shapes[0]!.getBounds().maxY).toBeCloseTo(1.5, 12);
  });
});

describe('polygon outlines', () => {
  it('names the field of a self-intersecting, repeated, flat or too long outline', () => {
    const bowTie = [
      { x: 0, y: 0 },
      { x: 1, y: 1 },
      { x: 1, y: 0 },
      { x: 0, y: 1 },
    ];
    expect(errorOf(() => polygon({ vertices: bowTie })).message).toMatch(/self-intersecting/);
    const pinched = [
      { x: 0, y: 0 },
      { x: 1, y: 1 },
      { x: 2, y: 0 },
      { x: 2, y: 2 },
      { x: 1, y: 1 },
      { x: 0, y: 2 },
    ];
    const repeated = errorOf(() => polygon({ vertices: pinched }));
    expect(repeated.field).toBe('vertices');
    expect(repeated.message).toMatch(/same point/);
    const flat = errorOf(() =>
      polygon({
        vertices: [
          { x: 0, y: 0 },
          { x: 1, y: 0 },
          { x: 2, y: 0 },
        ],
      }),
    );
    expect(flat.message).toMatch(/no area/);
    const tooMany = Array.from({ length: 300 }, (_, i) => ({
      x: Math.cos((2 * Math.PI * i) / 300),
      y: Math.sin((2 * Math.PI * i) / 300),
    }));
    expect(errorOf(() => polygon({ vertices: tooMany })).message).toMatch(/at most 256/);
    expect(
      errorOf(() => polygon({ vertices: [square[0]!, { x: NaN, y: 1 }, square[2]!] })).field,
    ).toBe('vertices[1].x');
  });

  it('splits a concave outline into convex shapes on one body, keeping the material', () => {
    const body = polygon({
      vertices: [
        { x: 0, y: 0 },
        { x: 3, y: 0 },
        { x: 3, y: 2 },
        { x: 2, y: 2 },
        { x: 2, y: 1 },
        { x: 1, y: 1 },
        { x: 1, y: 2 },
        { x: 0, y: 2 },
      ],
      friction: 0.3,
      restitution: 0.4,
    });
    expect(body.shapes.length).toBeGreaterThanOrEqual(3);
    for (const shape of body.shapes) {
      expect((shape.geometry as Polygon).kind).toBe('polygon');
      expect([shape.friction, shape.restitution]).toEqual([0.3, 0.4]);
    }
    expect(body.mass).toBeCloseTo(5, 12);
    // addShape returns the first part and adds them all.
    const compound = new Body({ shapes: [{ type: 'polygon', vertices: square }] });
    const first = compound.addShape({
      type: 'polygon',
      vertices: [
        { x: 2, y: 0 },
        { x: 4, y: 0 },
        { x: 4, y: 1 },
        { x: 3, y: 1 },
        { x: 3, y: 3 },
        { x: 2, y: 3 },
      ],
    });
    expect(compound.shapes.length).toBe(3);
    expect(compound.shapes[1]).toBe(first);
    expect(compound.mass).toBeCloseTo(5, 12);
  });

  it('adds every part of a concave shape to a body already in a world', () => {
    const world = new World();
    world.add(wall({ from: { x: -10, y: 0 }, to: { x: 10, y: 0 } }));
    const body = world.add(new Body({ position: { x: 0, y: -3 }, mass: 1 }));
    body.addShape({
      type: 'polygon',
      vertices: [
        { x: -1, y: 0 },
        { x: 1, y: 0 },
        { x: 1, y: 1 },
        { x: 0.8, y: 1 },
        { x: 0.8, y: 0.2 },
        { x: -0.8, y: 0.2 },
        { x: -0.8, y: 1 },
        { x: -1, y: 1 },
      ],
    });
    expect(body.shapes.length).toBe(3);
    for (let i = 0; i < 120; i++) world.step(1 / 60);
    // It landed on its two legs: the legs' feet (local y = 1) rest on the ground at y = 0.
    expect(body.position.y).toBeCloseTo(-1, 2);
    expect(world.bodyAt({ x: 0.9, y: -0.5 })).toBe(body);
    expect(world.bodyAt({ x: 0, y: -0.5 })).toBeNull();
  });

  it("splits the README's U bucket into three parts", () => {
    const bucket = polygon({
      position: { x: 0, y: 5 },
      vertices: [
        { x: -1, y: -0.5 },
        { x: -0.9, y: -0.5 },
        { x: -0.9, y: 0.4 },
        { x: 0.9, y: 0.4 },
        { x: 0.9, y: -0.5 },
        { x: 1, y: -0.5 },
        { x: 1, y: 0.5 },
        { x: -1, y: 0.5 },
      ],
    });
    expect(bucket.shapes.length).toBe(3);
    expect(bucket.mass).toBeCloseTo(2 * 0.1 * 0.9 + 2 * 0.1, 12);
  });

  it('rounds a convex polygon body, but not one it splits', () => {
    expect(polygon({ vertices: square, radius: 0.1 }).mass).toBeCloseTo(
      1 + 4 * 0.1 + Math.PI * 0.01,
      12,
    );
    const error = errorOf(() =>
      polygon({
        vertices: [
          { x: 0, y: 0 },
          { x: 2, y: 0 },
          { x: 1, y: 0.5 },
          { x: 2, y: 1 },
          { x: 0, y: 1 },
        ],
        radius: 0.1,
      }),
    );
    expect(error.field).toBe('radius');
  });

  it('steps a world of capsules, concave bodies and rounded boxes without NaN', () => {
    const world = new World();
    world.add(wall({ from: { x: -10, y: 0 }, to: { x: 10, y: 0 } }));
    for (let i = 0; i < 5; i++) {
      world.add(capsule({ position: { x: i - 2, y: -1 - i }, length: 0.6, radius: 0.2, angle: i }));
      world.add(particle({ position: { x: i - 2.3, y: -4 - i }, radius: 0.2 }));
    }
    world.add(
      polygon({
        position: { x: 0, y: -8 },
        vertices: [
          { x: 0, y: 0 },
          { x: 1, y: 0 },
          { x: 1, y: 0.3 },
          { x: 0.3, y: 0.3 },
          { x: 0.3, y: 1 },
          { x: 0, y: 1 },
        ],
      }),
    );
    for (let i = 0; i < 240; i++) world.step(1 / 60);
    for (const body of world.bodies) {
      expect(Number.isFinite(body.position.x) && Number.isFinite(body.position.y)).toBe(true);
      expect(body.position.y).toBeLessThan(0.01);
    }
  });
});
