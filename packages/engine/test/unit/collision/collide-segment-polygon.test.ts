import { describe, expect, it } from 'vitest';
import { SPECULATIVE_DISTANCE } from '../../../src/core/constants.ts';
import { collideSegmentAndPolygon, Manifold } from './kernel-collide.ts';
import { makeBox } from '../../../src/geometry/polygon.ts';
import { makeSegment } from '../../../src/geometry/segment.ts';
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

function pointsOf(manifold: Manifold): PointSummary[] {
  const list: PointSummary[] = [];
  for (let i = 0; i < manifold.pointCount; i++) {
    const p = manifold.points[i === 0 ? 0 : 1];
    list.push({ x: p.x, y: p.y, separation: p.separation, id: p.id });
  }
  return list.sort((a, b) => a.x - b.x || a.y - b.y);
}

// Positive normal (y2 - y1, -(x2 - x1)) / length: (0, -1) for `twoSided`, (0, 1) for `oneSidedUp`.
const twoSided = makeSegment(-2, 0, 2, 0, false, 'w');
const oneSidedUp = makeSegment(2, 0, -2, 0, true, 'w');
const box = makeBox(0.5, 0.5, 0, 0, 0, 0, 'b');

describe('collideSegmentAndPolygon', () => {
  it('gives two points under a box resting on a two-sided wall, from either side', () => {
    const above = new Manifold();
    collideSegmentAndPolygon(twoSided, xf(0, 0), box, xf(0.3, 0.45), above);
    expect(above.normalX).toBeCloseTo(0, 14);
    expect(above.normalY).toBeCloseTo(1, 14);
    const points = pointsOf(above);
    expect(points).toHaveLength(2);
    expect(points[0]!.x).toBeCloseTo(-0.2, 14);
    expect(points[1]!.x).toBeCloseTo(0.8, 14);
    for (const point of points) {
      expect(point.y).toBeCloseTo(-0.025, 14);
      expect(point.separation).toBeCloseTo(-0.05, 14);
    }
    const below = new Manifold();
    collideSegmentAndPolygon(twoSided, xf(0, 0), box, xf(0.3, -0.45), below);
    expect(below.normalY).toBeCloseTo(-1, 14);
    expect(below.pointCount).toBe(2);
  });

  it('gives no points beyond the speculative distance and speculative points within it', () => {
    const manifold = new Manifold();
    manifold.pointCount = 2;
    collideSegmentAndPolygon(
      twoSided,
      xf(0, 0),
      box,
      xf(0, 0.5 + SPECULATIVE_DISTANCE + 1e-3),
      manifold,
    );
    expect(manifold.pointCount).toBe(0);
    collideSegmentAndPolygon(
      oneSidedUp,
      xf(0, 0),
      box,
      xf(0, 0.5 + SPECULATIVE_DISTANCE + 1e-3),
      manifold,
    );
    expect(manifold.pointCount).toBe(0);
    for (const wall of [twoSided, oneSidedUp]) {
      collideSegmentAndPolygon(wall, xf(0, 0), box, xf(0, 0.51), manifold);
      expect(manifold.pointCount).toBe(2);
      expect(manifold.points[0].separation).toBeCloseTo(0.01, 14);
      expect(manifold.points[1].separation).toBeCloseTo(0.01, 14);
    }
  });

  it('ignores a box behind a one-sided wall', () => {
    const manifold = new Manifold();
    manifold.pointCount = 2;
    collideSegmentAndPolygon(oneSidedUp, xf(0, 0), box, xf(0, -0.45), manifold);
    expect(manifold.pointCount).toBe(0);
  });

  it('pushes a box only along a one-sided wall normal, clipped to the wall', () => {
    const manifold = new Manifold();
    collideSegmentAndPolygon(oneSidedUp, xf(0, 0), box, xf(2.3, 0.45), manifold);
    expect(manifold.normalX).toBeCloseTo(0, 14);
    expect(manifold.normalY).toBeCloseTo(1, 14);
    const points = pointsOf(manifold);
    expect(points).toHaveLength(2);
    expect(points[0]!.x).toBeCloseTo(1.8, 14);
    expect(points[1]!.x).toBeCloseTo(2, 14);
    expect(points[1]!.separation).toBeCloseTo(-0.05, 14);
    // Entirely beside the end: nothing, where a two-sided wall would push it sideways.
    collideSegmentAndPolygon(oneSidedUp, xf(0, 0), box, xf(2.51, 0.1), manifold);
    expect(manifold.pointCount).toBe(0);
    const sideways = new Manifold();
    collideSegmentAndPolygon(twoSided, xf(0, 0), box, xf(2.51, 0.1), sideways);
    expect(sideways.pointCount).toBeGreaterThan(0);
    expect(sideways.normalX).toBeCloseTo(1, 14);
  });

  it('includes the polygon radius', () => {
    const rounded = makeBox(0.5, 0.5, 0, 0, 0, 0.05, 'r');
    for (const wall of [twoSided, oneSidedUp]) {
      const manifold = new Manifold();
      collideSegmentAndPolygon(wall, xf(0, 0), rounded, xf(0, 0.52), manifold);
      expect(manifold.pointCount).toBe(2);
      expect(manifold.points[0].separation).toBeCloseTo(-0.03, 14);
      expect(manifold.points[0].y).toBeCloseTo(-0.015, 14);
    }
  });

  it('gives the same contact through rotated and translated transforms', () => {
    for (const wall of [twoSided, oneSidedUp]) {
      const base = new Manifold();
      collideSegmentAndPolygon(wall, xf(0, 0), box, xf(0.3, 0.46, 0.1), base);
      const angle = 1.3;
      const c = Math.cos(angle);
      const s = Math.sin(angle);
      const moved = new Manifold();
      const xfB = xf(-4 + c * 0.3 - s * 0.46, 9 + s * 0.3 + c * 0.46, angle + 0.1);
      collideSegmentAndPolygon(wall, xf(-4, 9, angle), box, xfB, moved);
      expect(moved.pointCount).toBe(base.pointCount);
      expect(moved.normalX).toBeCloseTo(c * base.normalX - s * base.normalY, 12);
      expect(moved.normalY).toBeCloseTo(s * base.normalX + c * base.normalY, 12);
      for (let i = 0; i < base.pointCount; i++) {
        const p = base.points[i === 0 ? 0 : 1];
        const q = moved.points[i === 0 ? 0 : 1];
        expect(q.x).toBeCloseTo(-4 + c * p.x - s * p.y, 12);
        expect(q.y).toBeCloseTo(9 + s * p.x + c * p.y, 12);
        expect(q.separation).toBeCloseTo(p.separation, 12);
        expect(q.id).toBe(p.id);
      }
    }
  });

  it('keeps feature ids under small motion', () => {
    for (const wall of [twoSided, oneSidedUp]) {
      const first = new Manifold();
      const second = new Manifold();
      collideSegmentAndPolygon(wall, xf(0, 0), box, xf(0.3, 0.49, 0.01), first);
      collideSegmentAndPolygon(wall, xf(0, 0), box, xf(0.302, 0.488, 0.011), second);
      expect(first.pointCount).toBe(2);
      expect(pointsOf(second).map((p) => p.id)).toEqual(pointsOf(first).map((p) => p.id));
    }
  });
});
