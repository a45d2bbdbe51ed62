import { describe, expect, it } from 'vitest';
import { SPECULATIVE_DISTANCE } from '../../../src/core/constants.ts';
import { collidePolygons, Manifold } from './kernel-collide.ts';
import { makeBox, makePolygon, type Polygon } from '../../../src/geometry/polygon.ts';
import { Transform } from '../../../src/math/transform.ts';

function xf(x: number, y: number, angle = 0): Transform {
  return new Transform().set(x, y, angle);
}

interface PointSummary {
  x: number;
  y: number;
  separation: number;
  id: number;
}

/** The manifold's points ordered by x then y, so tests do not depend on the point order. */
function pointsOf(manifold: Manifold): PointSummary[] {
  const list: PointSummary[] = [];
  for (let i = 0; i < manifold.pointCount; i++) {
    const p = manifold.points[i === 0 ? 0 : 1];
    list.push({ x: p.x, y: p.y, separation: p.separation, id: p.id });
  }
  return list.sort((a, b) => a.x - b.x || a.y - b.y);
}

function collide(a: Polygon, xfA: Transform, b: Polygon, xfB: Transform): Manifold {
  const manifold = new Manifold();
  collidePolygons(a, xfA, b, xfB, manifold);
  return manifold;
}

const unit = makeBox(0.5, 0.5, 0, 0, 0, 0, 'box');

describe('collidePolygons', () => {
  it('gives no points beyond the speculative distance', () => {
    const manifold = new Manifold();
    manifold.pointCount = 2;
    collidePolygons(unit, xf(0, 0), unit, xf(0.2, 1 + SPECULATIVE_DISTANCE + 1e-3), manifold);
    expect(manifold.pointCount).toBe(0);
  });

  it('gives two face points midway between overlapping flat faces', () => {
    const xfA = xf(0, 0);
    const xfB = xf(0, 0.95);
    const manifold = collide(unit, xfA, unit, xfB);
    expect(manifold.normalX).toBeCloseTo(0, 14);
    expect(manifold.normalY).toBeCloseTo(1, 14);
    const points = pointsOf(manifold);
    expect(points).toHaveLength(2);
    for (const [index, x] of [-0.5, 0.5].entries()) {
      expect(points[index]!.x).toBeCloseTo(x, 14);
      expect(points[index]!.y).toBeCloseTo(0.475, 14);
      expect(points[index]!.separation).toBeCloseTo(-0.05, 14);
    }
    expect(points[0]!.id).not.toBe(points[1]!.id);
  });

  it('clips a wider incident face to the reference face, whichever body is wider', () => {
    const wide = makeBox(1, 0.5, 0, 0, 0, 0, 'wide');
    for (const [a, b] of [
      [unit, wide],
      [wide, unit],
    ] as const) {
      const manifold = collide(a, xf(0.1, 0), b, xf(0.1, 0.95));
      expect(manifold.normalY).toBeCloseTo(1, 14);
      const points = pointsOf(manifold);
      expect(points.map((p) => p.x)).toEqual([expect.closeTo(-0.4, 14), expect.closeTo(0.6, 14)]);
      expect(points.map((p) => p.y)).toEqual([
        expect.closeTo(0.475, 14),
        expect.closeTo(0.475, 14),
      ]);
    }
  });

  it('keeps speculative points with positive separation', () => {
    const manifold = collide(unit, xf(0, 0), unit, xf(0.3, 1.01));
    const points = pointsOf(manifold);
    expect(points).toHaveLength(2);
    expect(points[0]!.x).toBeCloseTo(-0.2, 14);
    expect(points[1]!.x).toBeCloseTo(0.5, 14);
    for (const point of points) {
      expect(point.separation).toBeCloseTo(0.01, 14);
      expect(point.y).toBeCloseTo(0.505, 14);
    }
  });

  it('drops the far end of a tilted incident face but keeps the near corner', () => {
    const angle = 0.2;
    // Lowest corner of B (local (-0.5, -0.5) turned by +0.2) sits 0.01 below A's top face.
    const lowX = -0.5 * Math.cos(angle) + 0.5 * Math.sin(angle);
    const lowY = -0.5 * Math.sin(angle) - 0.5 * Math.cos(angle);
    const manifold = collide(unit, xf(0, 0), unit, xf(0.1 - lowX, 0.49 - lowY, angle));
    expect(manifold.pointCount).toBe(1);
    expect(manifold.points[0].x).toBeCloseTo(0.1, 12);
    expect(manifold.points[0].y).toBeCloseTo(0.495, 12);
    expect(manifold.points[0].separation).toBeCloseTo(-0.01, 12);
  });

  it('takes the reference face from B when it separates more, with the normal still from A to B', () => {
    // A is a diamond whose lower corner is pushed 0.05 into B's top face: B owns the reference face.
    const xfA = xf(0.2, 0.5 + Math.SQRT1_2 - 0.05, Math.PI / 4);
    const xfB = xf(0, 0);
    const manifold = collide(unit, xfA, unit, xfB);
    expect(manifold.normalX).toBeCloseTo(0, 12);
    expect(manifold.normalY).toBeCloseTo(-1, 12);
    expect(manifold.pointCount).toBe(1);
    expect(manifold.points[0].x).toBeCloseTo(0.2, 12);
    expect(manifold.points[0].y).toBeCloseTo(0.475, 12);
    expect(manifold.points[0].separation).toBeCloseTo(-0.05, 12);
  });

  it('reverses the normal and keeps the points when the roles swap', () => {
    const triangle = makePolygon(
      [
        { x: -0.6, y: -0.3 },
        { x: 0.7, y: -0.4 },
        { x: 0.1, y: 0.8 },
      ],
      0,
      't',
    );
    const xfA = xf(0, 0, 0.1);
    const xfB = xf(0.3, 0.85, -0.05);
    const ab = collide(unit, xfA, triangle, xfB);
    const ba = collide(triangle, xfB, unit, xfA);
    expect(ab.pointCount).toBeGreaterThan(0);
    expect(ba.pointCount).toBe(ab.pointCount);
    expect(ba.normalX).toBeCloseTo(-ab.normalX, 12);
    expect(ba.normalY).toBeCloseTo(-ab.normalY, 12);
    const pointsAB = pointsOf(ab);
    const pointsBA = pointsOf(ba);
    for (let i = 0; i < pointsAB.length; i++) {
      expect(pointsBA[i]!.x).toBeCloseTo(pointsAB[i]!.x, 12);
      expect(pointsBA[i]!.y).toBeCloseTo(pointsAB[i]!.y, 12);
      expect(pointsBA[i]!.separation).toBeCloseTo(pointsAB[i]!.separation, 12);
    }
  });

  it('gives the same contact in any rigid frame, even far from the origin', () => {
    const base = collide(unit, xf(0, 0, 0.05), unit, xf(0.3, 0.97, 0.12));
    for (const [tx, ty, angle] of [
      [7, -3, 0.9],
      [1e5, -2e5, -2.4],
    ] as const) {
      const c = Math.cos(angle);
      const s = Math.sin(angle);
      const xfA = xf(tx, ty, angle + 0.05);
      const xfB = xf(tx + c * 0.3 - s * 0.97, ty + s * 0.3 + c * 0.97, angle + 0.12);
      const moved = collide(unit, xfA, unit, xfB);
      expect(moved.pointCount).toBe(base.pointCount);
      expect(moved.normalX).toBeCloseTo(c * base.normalX - s * base.normalY, 10);
      expect(moved.normalY).toBeCloseTo(s * base.normalX + c * base.normalY, 10);
      for (let i = 0; i < base.pointCount; i++) {
        const p = base.points[i === 0 ? 0 : 1];
        const q = moved.points[i === 0 ? 0 : 1];
        expect(q.x - tx).toBeCloseTo(c * p.x - s * p.y, 9);
        expect(q.y - ty).toBeCloseTo(s * p.x + c * p.y, 9);
        expect(q.separation).toBeCloseTo(p.separation, 10);
        expect(q.id).toBe(p.id);
      }
    }
  });

  it('keeps feature ids while the same faces stay in contact', () => {
    const first = pointsOf(collide(unit, xf(0, 0), unit, xf(0.2, 0.99, 0.01)));
    const second = pointsOf(collide(unit, xf(0, 0), unit, xf(0.203, 0.988, 0.012)));
    expect(first).toHaveLength(2);
    expect(second.map((p) => p.id)).toEqual(first.map((p) => p.id));
  });

  it('uses the vertex pair for corners that face each other across a gap', () => {
    const manifold = collide(unit, xf(0, 0), unit, xf(1.01, 1.01));
    expect(manifold.pointCount).toBe(1);
    expect(manifold.normalX).toBeCloseTo(Math.SQRT1_2, 12);
    expect(manifold.normalY).toBeCloseTo(Math.SQRT1_2, 12);
    expect(manifold.points[0].separation).toBeCloseTo(0.01 * Math.SQRT2, 12);
    expect(manifold.points[0].x).toBeCloseTo(0.505, 12);
    expect(manifold.points[0].y).toBeCloseTo(0.505, 12);
  });

  it('measures rounded boxes to their rounded surfaces, faces and corners', () => {
    const rounded = makeBox(0.5, 0.5, 0, 0, 0, 0.05, 'r');
    const face = pointsOf(collide(rounded, xf(0, 0), rounded, xf(0, 1.05)));
    expect(face).toHaveLength(2);
    for (const point of face) {
      expect(point.separation).toBeCloseTo(-0.05, 12);
      expect(point.y).toBeCloseTo(0.525, 12);
    }
    // Cores 0.15 apart on each axis: the face axes alone would say -0.05, the corners are apart.
    const cornerRadius = makeBox(0.5, 0.5, 0, 0, 0, 0.1, 'r');
    const corner = collide(cornerRadius, xf(0, 0), cornerRadius, xf(1.15, 1.15));
    expect(corner.pointCount).toBe(1);
    const gap = 0.15 * Math.SQRT2;
    expect(corner.points[0].separation).toBeCloseTo(gap - 0.2, 12);
    expect(corner.normalX).toBeCloseTo(Math.SQRT1_2, 12);
    const middle = 0.5 + (0.1 + 0.5 * (gap - 0.2)) * Math.SQRT1_2;
    expect(corner.points[0].x).toBeCloseTo(middle, 12);
    expect(corner.points[0].y).toBeCloseTo(middle, 12);
  });
});
