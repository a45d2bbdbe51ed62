import { describe, expect, it } from 'vitest';
import { SPECULATIVE_DISTANCE } from '../../../src/core/constants.ts';
import { collideSegmentAndCircle, Manifold } from './kernel-collide.ts';
import { makeCircle } from '../../../src/geometry/circle.ts';
import { makeSegment } from '../../../src/geometry/segment.ts';
import { Transform } from '../../../src/math/transform.ts';

function xf(x: number, y: number, angle = 0): Transform {
  return new Transform().set(x, y, angle);
}

// Positive normal (y2 - y1, -(x2 - x1)) / length: (0, -1) for this wall, (0, 1) for the reversed one.
const twoSided = makeSegment(-1, 0, 1, 0, false, 'w');
const oneSidedUp = makeSegment(1, 0, -1, 0, true, 'w');

describe('collideSegmentAndCircle', () => {
  it('pushes a circle off either side of a two-sided wall', () => {
    const above = new Manifold();
    collideSegmentAndCircle(twoSided, xf(0, 0), makeCircle(0, 0, 0.5, 'b'), xf(0.2, 0.4), above);
    expect(above.pointCount).toBe(1);
    expect(above.normalX).toBeCloseTo(0, 14);
    expect(above.normalY).toBeCloseTo(1, 14);
    expect(above.points[0].separation).toBeCloseTo(-0.1, 14);
    expect(above.points[0].x).toBeCloseTo(0.2, 14);
    expect(above.points[0].y).toBeCloseTo(-0.05, 14);
    const below = new Manifold();
    collideSegmentAndCircle(twoSided, xf(0, 0), makeCircle(0, 0, 0.5, 'b'), xf(0.2, -0.4), below);
    expect(below.normalY).toBeCloseTo(-1, 14);
    expect(below.points[0].separation).toBeCloseTo(-0.1, 14);
  });

  it('uses the end point beyond the ends of a two-sided wall', () => {
    const manifold = new Manifold();
    collideSegmentAndCircle(twoSided, xf(0, 0), makeCircle(0, 0, 0.6, 'b'), xf(1.3, 0.4), manifold);
    expect(manifold.normalX).toBeCloseTo(0.6, 14);
    expect(manifold.normalY).toBeCloseTo(0.8, 14);
    expect(manifold.points[0].separation).toBeCloseTo(-0.1, 14);
    expect(manifold.points[0].x).toBeCloseTo(1 - 0.05 * 0.6, 14);
  });

  it('uses the positive normal for a centre exactly on the wall', () => {
    const manifold = new Manifold();
    collideSegmentAndCircle(twoSided, xf(0, 0), makeCircle(0, 0, 0.3, 'b'), xf(0.5, 0), manifold);
    expect(manifold.normalX).toBeCloseTo(0, 14);
    expect(manifold.normalY).toBeCloseTo(-1, 14);
    expect(manifold.points[0].separation).toBeCloseTo(-0.3, 14);
  });

  it('gives no point beyond the speculative distance and a speculative one within it', () => {
    const manifold = new Manifold();
    manifold.pointCount = 1;
    const circle = makeCircle(0, 0, 0.5, 'b');
    collideSegmentAndCircle(
      twoSided,
      xf(0, 0),
      circle,
      xf(0, 0.5 + SPECULATIVE_DISTANCE + 1e-3),
      manifold,
    );
    expect(manifold.pointCount).toBe(0);
    collideSegmentAndCircle(twoSided, xf(0, 0), circle, xf(0, 0.51), manifold);
    expect(manifold.pointCount).toBe(1);
    expect(manifold.points[0].separation).toBeCloseTo(0.01, 14);
  });

  it('ignores circles behind a one-sided wall and pushes only along its normal in front', () => {
    const circle = makeCircle(0, 0, 0.6, 'b');
    const behind = new Manifold();
    behind.pointCount = 1;
    collideSegmentAndCircle(oneSidedUp, xf(0, 0), circle, xf(0, -0.4), behind);
    expect(behind.pointCount).toBe(0);
    const front = new Manifold();
    collideSegmentAndCircle(oneSidedUp, xf(0, 0), circle, xf(0.2, 0.4), front);
    expect(front.normalY).toBeCloseTo(1, 14);
    expect(front.points[0].separation).toBeCloseTo(-0.2, 14);
    // Beside the end: still the wall's normal, never sideways, with the true distance.
    const beside = new Manifold();
    collideSegmentAndCircle(oneSidedUp, xf(0, 0), circle, xf(1.3, 0.4), beside);
    expect(beside.pointCount).toBe(1);
    expect(beside.normalX).toBeCloseTo(0, 14);
    expect(beside.normalY).toBeCloseTo(1, 14);
    expect(beside.points[0].separation).toBeCloseTo(-0.1, 14);
  });

  it('gives the same contact through rotated and translated transforms', () => {
    const circle = makeCircle(0.1, 0, 0.5, 'b');
    const base = new Manifold();
    collideSegmentAndCircle(oneSidedUp, xf(0, 0), circle, xf(0.3, 0.4), base);
    const angle = -0.7;
    const c = Math.cos(angle);
    const s = Math.sin(angle);
    const moved = new Manifold();
    const xfA = xf(5, 6, angle);
    const xfB = xf(5 + c * 0.3 - s * 0.4, 6 + s * 0.3 + c * 0.4, angle);
    collideSegmentAndCircle(oneSidedUp, xfA, circle, xfB, moved);
    expect(moved.normalX).toBeCloseTo(-s, 12);
    expect(moved.normalY).toBeCloseTo(c, 12);
    const p = base.points[0];
    expect(moved.points[0].x).toBeCloseTo(5 + c * p.x - s * p.y, 12);
    expect(moved.points[0].y).toBeCloseTo(6 + s * p.x + c * p.y, 12);
    expect(moved.points[0].separation).toBeCloseTo(p.separation, 12);
  });

  it('keeps its id under small motion', () => {
    const circle = makeCircle(0, 0, 0.5, 'b');
    const first = new Manifold();
    const second = new Manifold();
    collideSegmentAndCircle(twoSided, xf(0, 0), circle, xf(0.2, 0.45), first);
    collideSegmentAndCircle(twoSided, xf(0, 0), circle, xf(0.202, 0.449), second);
    expect(second.points[0].id).toBe(first.points[0].id);
  });
});
