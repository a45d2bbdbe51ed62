import { describe, expect, it } from 'vitest';
import {
  closestSegmentFractions,
  segmentFractions,
} from '../../../src/collision/closest-segment-fractions.ts';

/** Fractions of the closest points of segment p1 + f1 d1 and segment p2 + f2 d2. */
function fractions(
  p1: [number, number],
  d1: [number, number],
  p2: [number, number],
  d2: [number, number],
): [number, number] {
  const rx = p1[0] - p2[0];
  const ry = p1[1] - p2[1];
  const io = segmentFractions;
  io[0] = d1[0] * d1[0] + d1[1] * d1[1];
  io[1] = d2[0] * d2[0] + d2[1] * d2[1];
  io[2] = d1[0] * d2[0] + d1[1] * d2[1];
  io[3] = rx * d1[0] + ry * d1[1];
  io[4] = rx * d2[0] + ry * d2[1];
  closestSegmentFractions();
  return [io[5]!, io[6]!];
}

describe('closestSegmentFractions', () => {
  it('finds the crossing of two crossing segments', () => {
    // x axis from 0 to 4 and a vertical from (1, -1) to (1, 3): they cross at (1, 0).
    const [f1, f2] = fractions([0, 0], [4, 0], [1, -1], [0, 4]);
    expect(f1).toBeCloseTo(0.25, 15);
    expect(f2).toBeCloseTo(0.25, 15);
  });

  it('clamps to the nearer ends of segments that do not reach each other', () => {
    // x axis from 0 to 1 and a vertical from (3, 2) to (3, 5): closest are (1, 0) and (3, 2).
    const [f1, f2] = fractions([0, 0], [1, 0], [3, 2], [0, 3]);
    expect(f1).toBe(1);
    expect(f2).toBe(0);
  });

  it('gives a pair at the distance of parallel segments', () => {
    // Parallel at height 1, the second over [2, 3] of the first [0, 4]: any pair is 1 m apart.
    const [f1, f2] = fractions([0, 0], [4, 0], [2, 1], [1, 0]);
    const x1 = 4 * f1;
    const x2 = 2 + f2;
    expect(Math.abs(x2 - x1)).toBeCloseTo(0, 15);
    expect(f2).toBeGreaterThanOrEqual(0);
    expect(f2).toBeLessThanOrEqual(1);
  });
});
