import { describe, expect, it } from 'vitest';
import { SPECULATIVE_DISTANCE } from '../../../src/core/constants.ts';
import { collideCircles, Manifold } from './kernel-collide.ts';
import { makeCircle } from '../../../src/geometry/circle.ts';
import { Transform } from '../../../src/math/transform.ts';

function xf(x: number, y: number, angle = 0): Transform {
  return new Transform().set(x, y, angle);
}

describe('collideCircles', () => {
  const big = makeCircle(0, 0, 1, 'a');
  const small = makeCircle(0, 0, 0.5, 'b');

  it('gives no point beyond the speculative distance', () => {
    const manifold = new Manifold();
    manifold.pointCount = 2;
    collideCircles(big, xf(0, 0), small, xf(1.5 + SPECULATIVE_DISTANCE + 0.001, 0), manifold);
    expect(manifold.pointCount).toBe(0);
  });

  it('keeps a speculative point with positive separation', () => {
    const manifold = new Manifold();
    collideCircles(big, xf(0, 0), small, xf(1.51, 0), manifold);
    expect(manifold.pointCount).toBe(1);
    expect(manifold.points[0].separation).toBeCloseTo(0.01, 12);
  });

  it('places an overlap point midway between the surfaces on the line of centres', () => {
    const manifold = new Manifold();
    const xfA = xf(2, 3);
    const xfB = xf(2 + 0.72, 3 + 0.96);
    collideCircles(big, xfA, small, xfB, manifold);
    expect(manifold.pointCount).toBe(1);
    expect(manifold.normalX).toBeCloseTo(0.6, 14);
    expect(manifold.normalY).toBeCloseTo(0.8, 14);
    const point = manifold.points[0];
    expect(point.separation).toBeCloseTo(-0.3, 14);
    // A's surface at distance 1, B's at 1.2 - 0.5 = 0.7 along the normal: midway 0.85.
    expect(point.x).toBeCloseTo(2 + 0.85 * 0.6, 14);
    expect(point.y).toBeCloseTo(3 + 0.85 * 0.8, 14);
    expect(point.id).toBe(0);
  });

  it('uses local centres through rotated transforms', () => {
    const manifold = new Manifold();
    const offset = makeCircle(1, 0, 0.5, 'a');
    // A's centre lands at (0, 1), B's at (0, 1.8).
    collideCircles(offset, xf(0, 0, Math.PI / 2), offset, xf(1, 1.8, Math.PI), manifold);
    expect(manifold.pointCount).toBe(1);
    expect(manifold.normalX).toBeCloseTo(0, 14);
    expect(manifold.normalY).toBeCloseTo(1, 14);
    expect(manifold.points[0].separation).toBeCloseTo(-0.2, 14);
    expect(manifold.points[0].y).toBeCloseTo(1.4, 14);
  });

  it('reverses the normal when the roles swap', () => {
    const ab = new Manifold();
    const ba = new Manifold();
    collideCircles(big, xf(0, 0), small, xf(1, 0.5), ab);
    collideCircles(small, xf(1, 0.5), big, xf(0, 0), ba);
    expect(ba.normalX).toBeCloseTo(-ab.normalX, 14);
    expect(ba.normalY).toBeCloseTo(-ab.normalY, 14);
    expect(ba.points[0].x).toBeCloseTo(ab.points[0].x, 14);
    expect(ba.points[0].y).toBeCloseTo(ab.points[0].y, 14);
    expect(ba.points[0].separation).toBeCloseTo(ab.points[0].separation, 14);
  });

  it('picks a fixed finite normal for coincident centres', () => {
    const manifold = new Manifold();
    collideCircles(big, xf(4, 4), small, xf(4, 4), manifold);
    expect(manifold.pointCount).toBe(1);
    expect(manifold.normalX).toBe(1);
    expect(manifold.normalY).toBe(0);
    expect(manifold.points[0].separation).toBeCloseTo(-1.5, 14);
    expect(Number.isFinite(manifold.points[0].x)).toBe(true);
  });
});
