import { describe, expect, it } from 'vitest';
import { collideCapsules, Manifold } from './kernel-collide.ts';
import { makeCapsule } from '../../../src/geometry/capsule.ts';
import { Transform } from '../../../src/math/transform.ts';

function xf(x: number, y: number, angle = 0): Transform {
  return new Transform().set(x, y, angle);
}

const pill = makeCapsule(-1, 0, 1, 0, 0.25, 'a');

describe('collideCapsules', () => {
  it('gives two points, under the overlap, for a pill lying on another', () => {
    const m = new Manifold();
    // B shifted right by 0.5 and up by 0.49: the overlap along x is [-0.5, 1].
    collideCapsules(pill, xf(0, 0), pill, xf(0.5, 0.49), m);
    expect(m.pointCount).toBe(2);
    expect(m.normalX).toBeCloseTo(0, 14);
    expect(m.normalY).toBeCloseTo(1, 14);
    const xs = [m.points[0].x, m.points[1].x].sort((a, b) => a - b);
    expect(xs[0]).toBeCloseTo(-0.5, 12);
    expect(xs[1]).toBeCloseTo(1, 12);
    for (const p of m.points) {
      expect(p.separation).toBeCloseTo(0.49 - 0.5, 12);
      // Midway between the surfaces: A's top at 0.25, B's bottom at 0.24.
      expect(p.y).toBeCloseTo(0.245, 12);
    }
    expect(m.points[0].id).not.toBe(m.points[1].id);
  });

  it('gives one point along the line of centres for ends touching end to end', () => {
    const m = new Manifold();
    // Collinear: B starts 0.55 beyond A's end, so the core gap is 0.55 and separation 0.05.
    collideCapsules(pill, xf(0, 0), pill, xf(2.55, 0), m);
    expect(m.pointCount).toBe(0);
    m.speculativeDistance = 0.1;
    collideCapsules(pill, xf(0, 0), pill, xf(2.55, 0), m);
    expect(m.pointCount).toBe(1);
    expect(m.normalX).toBeCloseTo(1, 14);
    expect(m.points[0].separation).toBeCloseTo(0.05, 12);
    expect(m.points[0].x).toBeCloseTo(1.275, 12);
  });

  it('measures a crossing pair by the face it rests on', () => {
    const m = new Manifold();
    // B upright, its lower end 0.2 above A's axis: B's end circle sinks 0.3 into A.
    collideCapsules(pill, xf(0, 0), pill, xf(0.3, 1.2, Math.PI / 2), m);
    expect(m.pointCount).toBeGreaterThan(0);
    expect(m.normalY).toBeCloseTo(1, 12);
    const deepest = Math.min(...m.points.slice(0, m.pointCount).map((p) => p.separation));
    expect(deepest).toBeCloseTo(0.2 - 0.5, 12);
  });

  it('takes B as the reference face when A only touches it with an end', () => {
    const m = new Manifold();
    // A upright at x = 0 (its ends at y = +-1), B lying across under it, touching A's lower end.
    const upright = xf(0, 0, Math.PI / 2);
    collideCapsules(pill, upright, pill, xf(0.2, 1.45), m);
    expect(m.pointCount).toBeGreaterThan(0);
    expect(m.normalX).toBeCloseTo(0, 12);
    expect(m.normalY).toBeCloseTo(1, 12);
    const deepest = Math.min(...m.points.slice(0, m.pointCount).map((p) => p.separation));
    expect(deepest).toBeCloseTo(-0.05, 12);
  });

  it('is the same contact seen from either side', () => {
    const a = new Manifold();
    const b = new Manifold();
    collideCapsules(pill, xf(0, 0, 0.3), pill, xf(0.7, 0.4, -0.2), a);
    collideCapsules(pill, xf(0.7, 0.4, -0.2), pill, xf(0, 0, 0.3), b);
    expect(a.pointCount).toBeGreaterThan(0);
    expect(b.normalX).toBeCloseTo(-a.normalX, 9);
    expect(b.normalY).toBeCloseTo(-a.normalY, 9);
    const deepestA = Math.min(...a.points.slice(0, a.pointCount).map((p) => p.separation));
    const deepestB = Math.min(...b.points.slice(0, b.pointCount).map((p) => p.separation));
    expect(deepestB).toBeCloseTo(deepestA, 9);
  });

  it('never gives NaN for coincident capsules', () => {
    const m = new Manifold();
    collideCapsules(pill, xf(1, 1), pill, xf(1, 1), m);
    expect(m.pointCount).toBeGreaterThan(0);
    expect(Number.isFinite(m.normalX) && Number.isFinite(m.normalY)).toBe(true);
    expect(Number.isFinite(m.points[0].separation)).toBe(true);
  });
});
