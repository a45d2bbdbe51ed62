import { describe, expect, it } from 'vitest';
import { Manifold } from '../../../src/collision/manifold.ts';
import {
  circleCenterInA,
  onePoint,
  writeOnePoint,
} from '../../../src/collision/one-point-manifold.ts';
import { makeCircle } from '../../../src/geometry/circle.ts';
import { Transform } from '../../../src/math/transform.ts';

function xf(x: number, y: number, angle = 0): Transform {
  return new Transform().set(x, y, angle);
}

describe('circleCenterInA', () => {
  it('turns the centre into the frame of a rotated, moved A', () => {
    // A at (1, 2) turned a quarter turn; B's centre (offset 0.5 along B's x, B turned a half turn)
    // lies at (3.5, 2) - 0.5 (1, 0) = (3, 2) in the world, (2, 0) from A, (0, -2) in A's frame.
    circleCenterInA(makeCircle(0.5, 0, 0.25, 'b'), xf(1, 2, Math.PI / 2), xf(3.5, 2, Math.PI));
    expect(onePoint[0]).toBeCloseTo(0, 14);
    expect(onePoint[1]).toBeCloseTo(-2, 14);
  });
});

describe('writeOnePoint', () => {
  it('writes the point, normal and anchors in the world frame', () => {
    const m = new Manifold();
    // In A's frame (A at (1, 2), a quarter turn): point (0.5, 0), normal (1, 0), gap -0.01.
    onePoint.set([0.5, 0, 1, 0, -0.01]);
    writeOnePoint(m, xf(1, 2, Math.PI / 2), xf(1, 4));
    expect(m.pointCount).toBe(1);
    expect(m.normalX).toBeCloseTo(0, 14);
    expect(m.normalY).toBeCloseTo(1, 14);
    const p = m.points[0];
    expect(p.x).toBeCloseTo(1, 14);
    expect(p.y).toBeCloseTo(2.5, 14);
    expect(p.anchorAX).toBeCloseTo(0, 14);
    expect(p.anchorAY).toBeCloseTo(0.5, 14);
    expect(p.anchorBX).toBeCloseTo(0, 14);
    expect(p.anchorBY).toBeCloseTo(-1.5, 14);
    expect(p.separation).toBe(-0.01);
  });
});
