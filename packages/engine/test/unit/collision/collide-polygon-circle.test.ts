import { describe, expect, it } from 'vitest';
import { SPECULATIVE_DISTANCE } from '../../../src/core/constants.ts';
import { collidePolygonAndCircle, Manifold } from './kernel-collide.ts';
import { makeCircle } from '../../../src/geometry/circle.ts';
import { makeBox } from '../../../src/geometry/polygon.ts';
import { Transform } from '../../../src/math/transform.ts';

function xf(x: number, y: number, angle = 0): Transform {
  return new Transform().set(x, y, angle);
}

describe('collidePolygonAndCircle', () => {
  const box = makeBox(1, 1, 0, 0, 0, 0, 'a');

  it('uses the face normal when the centre is over a face', () => {
    const manifold = new Manifold();
    collidePolygonAndCircle(box, xf(0, 0), makeCircle(0, 0, 0.5, 'b'), xf(0.3, 1.4), manifold);
    expect(manifold.pointCount).toBe(1);
    expect(manifold.normalX).toBeCloseTo(0, 14);
    expect(manifold.normalY).toBeCloseTo(1, 14);
    expect(manifold.points[0].separation).toBeCloseTo(-0.1, 14);
    expect(manifold.points[0].x).toBeCloseTo(0.3, 14);
    expect(manifold.points[0].y).toBeCloseTo(0.95, 14);
  });

  it('uses the vertex-to-centre normal in a corner region', () => {
    const manifold = new Manifold();
    collidePolygonAndCircle(box, xf(0, 0), makeCircle(0, 0, 0.6, 'b'), xf(1.3, 1.4), manifold);
    expect(manifold.pointCount).toBe(1);
    expect(manifold.normalX).toBeCloseTo(0.6, 14);
    expect(manifold.normalY).toBeCloseTo(0.8, 14);
    const point = manifold.points[0];
    expect(point.separation).toBeCloseTo(-0.1, 14);
    expect(point.x).toBeCloseTo(1 - 0.05 * 0.6, 14);
    expect(point.y).toBeCloseTo(1 - 0.05 * 0.8, 14);
  });

  it('gives no point beyond the speculative distance, at a face or a corner', () => {
    const manifold = new Manifold();
    manifold.pointCount = 1;
    const circle = makeCircle(0, 0, 0.5, 'b');
    collidePolygonAndCircle(
      box,
      xf(0, 0),
      circle,
      xf(0, 1.5 + SPECULATIVE_DISTANCE + 1e-3),
      manifold,
    );
    expect(manifold.pointCount).toBe(0);
    // Over the corner the face gap is only 0.01, but the true distance is 0.01 * sqrt(2) + ... > 0.02.
    const diagonal = 1 + (0.5 + 0.021) / Math.SQRT2;
    manifold.pointCount = 1;
    collidePolygonAndCircle(box, xf(0, 0), circle, xf(diagonal, diagonal), manifold);
    expect(manifold.pointCount).toBe(0);
  });

  it('keeps a speculative point', () => {
    const manifold = new Manifold();
    collidePolygonAndCircle(box, xf(0, 0), makeCircle(0, 0, 0.5, 'b'), xf(1.51, 0), manifold);
    expect(manifold.pointCount).toBe(1);
    expect(manifold.points[0].separation).toBeCloseTo(0.01, 14);
    expect(manifold.normalX).toBeCloseTo(1, 14);
  });

  it('pushes a centre that is inside the polygon out through the nearest face', () => {
    const manifold = new Manifold();
    collidePolygonAndCircle(box, xf(0, 0), makeCircle(0, 0, 0.25, 'b'), xf(-0.1, -0.8), manifold);
    expect(manifold.normalX).toBeCloseTo(0, 14);
    expect(manifold.normalY).toBeCloseTo(-1, 14);
    expect(manifold.points[0].separation).toBeCloseTo(-0.45, 14);
  });

  it('includes the polygon radius', () => {
    const manifold = new Manifold();
    const rounded = makeBox(1, 1, 0, 0, 0, 0.1, 'a');
    collidePolygonAndCircle(rounded, xf(0, 0), makeCircle(0, 0, 0.5, 'b'), xf(0, 1.5), manifold);
    expect(manifold.points[0].separation).toBeCloseTo(-0.1, 14);
    expect(manifold.points[0].y).toBeCloseTo(1.05, 14);
  });

  it('gives the same contact in any rigid frame', () => {
    const circle = makeCircle(0.2, -0.1, 0.6, 'b');
    const base = new Manifold();
    collidePolygonAndCircle(box, xf(0, 0), circle, xf(1.1, 1.5), base);
    const angle = 2.1;
    const c = Math.cos(angle);
    const s = Math.sin(angle);
    const moved = new Manifold();
    const xfA = xf(-30, 12, angle);
    const xfB = xf(-30 + c * 1.1 - s * 1.5, 12 + s * 1.1 + c * 1.5, angle);
    collidePolygonAndCircle(box, xfA, circle, xfB, moved);
    expect(moved.pointCount).toBe(1);
    expect(moved.normalX).toBeCloseTo(c * base.normalX - s * base.normalY, 12);
    expect(moved.normalY).toBeCloseTo(s * base.normalX + c * base.normalY, 12);
    const p = base.points[0];
    expect(moved.points[0].x).toBeCloseTo(-30 + c * p.x - s * p.y, 12);
    expect(moved.points[0].y).toBeCloseTo(12 + s * p.x + c * p.y, 12);
    expect(moved.points[0].separation).toBeCloseTo(p.separation, 12);
  });

  it('keeps its id under small motion', () => {
    const manifold = new Manifold();
    const circle = makeCircle(0, 0, 0.5, 'b');
    collidePolygonAndCircle(box, xf(0, 0), circle, xf(0.3, 1.4), manifold);
    const id = manifold.points[0].id;
    collidePolygonAndCircle(box, xf(0, 0), circle, xf(0.301, 1.399), manifold);
    expect(manifold.points[0].id).toBe(id);
  });
});
