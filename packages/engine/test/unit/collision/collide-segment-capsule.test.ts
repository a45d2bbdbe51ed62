import { describe, expect, it } from 'vitest';
import { collideSegmentAndCapsule, Manifold } from './kernel-collide.ts';
import { makeCapsule } from '../../../src/geometry/capsule.ts';
import { makeSegment } from '../../../src/geometry/segment.ts';
import { Transform } from '../../../src/math/transform.ts';

function xf(x: number, y: number, angle = 0): Transform {
  return new Transform().set(x, y, angle);
}

const pill = makeCapsule(-1, 0, 1, 0, 0.25, 'a');
// Positive normal (y2 - y1, -(x2 - x1)) / length: (0, 1) for right-to-left.
const oneSidedUp = makeSegment(3, 0, -3, 0, true, 'w');
const twoSided = makeSegment(-3, 0, 3, 0, false, 'w');

describe('collideSegmentAndCapsule', () => {
  it('gives two points for a pill lying on a two-sided wall, from either side', () => {
    for (const side of [1, -1]) {
      const m = new Manifold();
      collideSegmentAndCapsule(twoSided, xf(0, 0), pill, xf(0.5, side * 0.24), m);
      expect(m.pointCount).toBe(2);
      expect(m.normalY).toBeCloseTo(side, 14);
      for (const p of m.points) expect(p.separation).toBeCloseTo(-0.01, 12);
    }
  });

  it('one-sided: contacts from the front, none from behind', () => {
    const m = new Manifold();
    collideSegmentAndCapsule(oneSidedUp, xf(0, 0), pill, xf(0, 0.24), m);
    expect(m.pointCount).toBe(2);
    expect(m.normalY).toBeCloseTo(1, 14);
    for (const p of m.points) expect(p.separation).toBeCloseTo(-0.01, 12);
    collideSegmentAndCapsule(oneSidedUp, xf(0, 0), pill, xf(0, -0.24), m);
    expect(m.pointCount).toBe(0);
  });
});
