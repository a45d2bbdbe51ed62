import { describe, expect, it } from 'vitest';
import { collideCapsuleAndCircle, Manifold } from './kernel-collide.ts';
import { makeCapsule } from '../../../src/geometry/capsule.ts';
import { makeCircle } from '../../../src/geometry/circle.ts';
import { Transform } from '../../../src/math/transform.ts';

function xf(x: number, y: number, angle = 0): Transform {
  return new Transform().set(x, y, angle);
}

const pill = makeCapsule(-1, 0, 1, 0, 0.25, 'a');
const ball = makeCircle(0, 0, 0.5, 'b');

describe('collideCapsuleAndCircle', () => {
  it('pushes along the side normal over the middle', () => {
    const m = new Manifold();
    collideCapsuleAndCircle(pill, xf(0, 0), ball, xf(0.4, 0.7), m);
    expect(m.pointCount).toBe(1);
    expect(m.normalX).toBeCloseTo(0, 14);
    expect(m.normalY).toBeCloseTo(1, 14);
    expect(m.points[0].separation).toBeCloseTo(-0.05, 12);
    expect(m.points[0].y).toBeCloseTo(0.225, 12);
  });

  it('pushes radially from the end centre past the end', () => {
    const m = new Manifold();
    collideCapsuleAndCircle(pill, xf(0, 0), ball, xf(1 + 0.6, 0.45), m);
    expect(m.normalX).toBeCloseTo(0.8, 12);
    expect(m.normalY).toBeCloseTo(0.6, 12);
    expect(m.points[0].separation).toBeCloseTo(0.75 - 0.75, 12);
  });

  it('works in a turned frame and gives nothing beyond the speculative distance', () => {
    const m = new Manifold();
    collideCapsuleAndCircle(pill, xf(2, 2, Math.PI / 2), ball, xf(2.7, 2.3), m);
    expect(m.normalX).toBeCloseTo(1, 12);
    expect(m.points[0].separation).toBeCloseTo(-0.05, 12);
    collideCapsuleAndCircle(pill, xf(2, 2, Math.PI / 2), ball, xf(3, 2.3), m);
    expect(m.pointCount).toBe(0);
  });

  it('uses the side normal for a centre on the core, never NaN', () => {
    const m = new Manifold();
    collideCapsuleAndCircle(pill, xf(0, 0), ball, xf(0.5, 0), m);
    expect(Math.abs(m.normalY)).toBeCloseTo(1, 14);
    expect(m.points[0].separation).toBeCloseTo(-0.75, 14);
  });
});
