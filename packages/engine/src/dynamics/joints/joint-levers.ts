import { DP_X, DP_Y, Q_C, Q_S } from '../body-state.ts';
import { DELTA_CENTER_X, DELTA_CENTER_Y, R_AX, R_AY, R_BX, R_BY } from './joint-record.ts';

// The preamble every joint pass shares, written once: the record's levers (from the centres to
// the anchors at the step's start, joint-record.ts) turned by each body's rotation since then, and
// the anchors' separation now. The passes read them from a scratch array (`levers`, at these
// offsets) rather than as return values: only integers cross the call, so nothing is boxed even
// where V8 does not inline it (dynamics/README.md).

/** A's lever now, x and y (m). */
export const LEVER_AX = 0;
export const LEVER_AY = 1;
/** B's lever now. */
export const LEVER_BX = 2;
export const LEVER_BY = 3;
/** B's anchor minus A's now (takeSeparation). */
export const SEPARATION_X = 4;
export const SEPARATION_Y = 5;

/** Where a kind's own preamble may write its numbers (prismatic-joint-solver.ts: axis and arms). */
export const LEVERS_END = 6;

/** @internal The scratch the preamble writes into (one for all passes: they run one at a time). */
export const levers = /* @__PURE__ */ new Float64Array(LEVERS_END + 6);

/**
 * @internal Turns the levers of the record at `o` in `d` by the rotations of the states at `a`
 * and `b` in `s` since the step's start, into `p` (LEVER_AX ... LEVER_BY).
 */
export function turnLevers(
  s: Float64Array,
  a: number,
  b: number,
  d: Float64Array,
  o: number,
  p: Float64Array,
): void {
  const qAc = s[a + Q_C]!;
  const qAs = s[a + Q_S]!;
  const qBc = s[b + Q_C]!;
  const qBs = s[b + Q_S]!;
  p[0] = qAc * d[o + R_AX]! - qAs * d[o + R_AY]!;
  p[1] = qAs * d[o + R_AX]! + qAc * d[o + R_AY]!;
  p[2] = qBc * d[o + R_BX]! - qBs * d[o + R_BY]!;
  p[3] = qBs * d[o + R_BX]! + qBc * d[o + R_BY]!;
}

/**
 * @internal turnLevers, then the separation of the anchors (B's minus A's) into `p`
 * (SEPARATION_X, SEPARATION_Y): the centres' motion this step, plus the centres' offset at its
 * start, plus the levers' difference, summed in that order (the recorded results depend on it).
 */
export function takeSeparation(
  s: Float64Array,
  a: number,
  b: number,
  d: Float64Array,
  o: number,
  p: Float64Array,
): void {
  turnLevers(s, a, b, d, o, p);
  p[4] = s[b + DP_X]! - s[a + DP_X]! + d[o + DELTA_CENTER_X]! + p[2]! - p[0]!;
  p[5] = s[b + DP_Y]! - s[a + DP_Y]! + d[o + DELTA_CENTER_Y]! + p[3]! - p[1]!;
}
