// The closest points of two segments, shared by the capsule and polygon narrow phases.
import { S_FRACTIONS } from './contact-layout';
import { st } from './load-store';

/**
 * Fractions of the closest points of two segments of non-zero length (Ericson, Real-Time
 * Collision Detection, 5.1.9, ClosestPtSegmentSegment): segment 1 from p1 along d1, segment 2
 * from p2 along d2, r = p1 - p2, given dd1 = d1 . d1, dd2 = d2 . d2, d12 = d1 . d2, rd1 = r . d1
 * and rd2 = r . d2. Writes f1 (along segment 1) and f2 (along segment 2), each in [0, 1], to the
 * scratch at `m` (S_FRACTIONS, S_FRACTIONS + 1). Parallel segments (a zero denominator) start
 * from f1 = 0.
 */
export function closestSegmentFractions(
  m: usize,
  dd1: f64,
  dd2: f64,
  d12: f64,
  rd1: f64,
  rd2: f64,
): void {
  const denominator = dd1 * dd2 - d12 * d12;
  let f1: f64 = 0;
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
  st(m, S_FRACTIONS, f1 < 0 ? 0 : f1 > 1 ? 1 : f1);
  st(m, S_FRACTIONS + 1, f2);
}
