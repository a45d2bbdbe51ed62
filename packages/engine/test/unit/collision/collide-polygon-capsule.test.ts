import { describe, expect, it } from 'vitest';
import { collidePolygonAndCapsule, Manifold } from './kernel-collide.ts';
import { makeCapsule } from '../../../src/geometry/capsule.ts';
import { makeBox } from '../../../src/geometry/polygon.ts';
import { Transform } from '../../../src/math/transform.ts';

function xf(x: number, y: number, angle = 0): Transform {
  return new Transform().set(x, y, angle);
}

const pill = makeCapsule(-1, 0, 1, 0, 0.25, 'a');
const ground = makeBox(5, 0.5, 0, 0, 0, 0, 'g');

describe('collidePolygonAndCapsule', () => {
  it('gives two points under a pill lying flat on a box, at its end centres', () => {
    const m = new Manifold();
    collidePolygonAndCapsule(ground, xf(0, 0), pill, xf(0.3, 0.74), m);
    expect(m.pointCount).toBe(2);
    expect(m.normalY).toBeCloseTo(1, 14);
    const xs = [m.points[0].x, m.points[1].x].sort((a, b) => a - b);
    expect(xs[0]).toBeCloseTo(-0.7, 12);
    expect(xs[1]).toBeCloseTo(1.3, 12);
    for (const p of m.points) expect(p.separation).toBeCloseTo(-0.01, 12);
  });

  it('gives one point under a standing pill, at its lower end', () => {
    const m = new Manifold();
    collidePolygonAndCapsule(ground, xf(0, 0), pill, xf(0, 1.74, Math.PI / 2), m);
    const deepest = Math.min(...m.points.slice(0, m.pointCount).map((p) => p.separation));
    expect(deepest).toBeCloseTo(-0.01, 12);
    expect(m.normalY).toBeCloseTo(1, 14);
  });

  it('rounds both: a rounded box corner against a pill end measures the true distance', () => {
    const rounded = makeBox(0.5, 0.5, 0, 0, 0, 0.1, 'r');
    const m = new Manifold();
    m.speculativeDistance = 1;
    // Pill along the diagonal, its near end centre at (1, 1): the core gap is |(0.5, 0.5)|.
    const d = Math.SQRT1_2;
    collidePolygonAndCapsule(rounded, xf(0, 0), pill, xf(1 + d, 1 + d, Math.PI / 4), m);
    expect(m.pointCount).toBe(1);
    expect(m.points[0].separation).toBeCloseTo(Math.SQRT1_2 - 0.35, 9);
    expect(m.normalX).toBeCloseTo(d, 9);
  });
});
