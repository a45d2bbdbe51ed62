// The closest points of two segments, shared by the capsule and polygon narrow phases.

/**
 * In and out for {@link closestSegmentFractions}, in place of arguments and results: V8 boxes
 * (allocates) fractional numbers passed to or returned from a call it does not inline, and the
 * narrow phase must not allocate. In: segment 1 from p1 along d1, segment 2 from p2 along d2,
 * r = p1 - p2: at 0 d1 . d1, 1 d2 . d2, 2 d1 . d2, 3 r . d1, 4 r . d2. Out: at 5 the fraction f1
 * of the closest point along segment 1, at 6 f2 along segment 2, each in [0, 1].
 */
export const segmentFractions: Float64Array = new Float64Array(7);

/**
 * Fractions of the closest points of two segments of non-zero length (Ericson, Real-Time
 * Collision Detection, 5.1.9, ClosestPtSegmentSegment), from and into
 * {@link segmentFractions}. Parallel segments (a zero denominator) start from f1 = 0. The clamps
 * are written out: a helper call could box its argument and result.
 */
export function closestSegmentFractions(): void {
  const io = segmentFractions;
  const dd1 = io[0]!;
  const dd2 = io[1]!;
  const d12 = io[2]!;
  const rd1 = io[3]!;
  const rd2 = io[4]!;
  const denominator = dd1 * dd2 - d12 * d12;
  let f1 = 0;
  if (denominator > 0) {
    f1 = (d12 * rd2 - rd1 * dd2) / denominator;
    f1 = f1 < 0 ? 0 : f1 > 1 ? 1 : f1;
  }
  let f2 = (d12 * f1 + rd2) / dd2;
  if (f2 < 0) {
    f2 = 0;
    f1 = -rd1 / dd1;
  } else if (f2 > 1) {
    f2 = 1;
    f1 = (d12 - rd1) / dd1;
  }
  io[5] = f1 < 0 ? 0 : f1 > 1 ? 1 : f1;
  io[6] = f2;
}
