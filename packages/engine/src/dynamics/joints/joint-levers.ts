import { DP_X, DP_Y, Q_C, Q_S } from '../body-state.ts';
import { DELTA_CENTER_X, DELTA_CENTER_Y } from './joint-record.ts';

// The preamble every joint pass shares, written once: a vector of the record (a lever from a
// centre to an anchor at the step's start, joint-record.ts, or the prismatic joint's axis) turned
// by a body's rotation since then, and the centres' shift that the anchors' separation starts
// from. Each returns one double: these are small enough that V8 inlines them at every call site
// (checked with --trace-turbo-inlining in the passes of every kind), so the numbers stay in
// registers and none is boxed (dynamics/README.md: no fractional values across calls V8 does not
// inline). A first version wrote them into a scratch array, one call per joint: joint_grid took
// 1.11 times main's CPU time per step (medians of 12 alternating runs, machine shared): V8 does not
// forward a typed array's stores to the loads that follow.

/**
 * @internal x of the vector at `v` in `d` (x, then y) turned by the rotation this step of the
 * state at `at` in `s`.
 */
export function turnedX(s: Float64Array, at: number, d: Float64Array, v: number): number {
  return s[at + Q_C]! * d[v]! - s[at + Q_S]! * d[v + 1]!;
}

/** @internal y of the same (see turnedX). */
export function turnedY(s: Float64Array, at: number, d: Float64Array, v: number): number {
  return s[at + Q_S]! * d[v]! + s[at + Q_C]! * d[v + 1]!;
}

/**
 * @internal x of how far B's centre is from A's now: their motion this step (states at `a` and
 * `b`) plus their offset at its start (the record at `o`). The anchors' separation adds the turned
 * levers' difference to it, in that order (`shiftX(...) + rBx - rAx`; the recorded results depend
 * on the order of the sums).
 */
export function shiftX(s: Float64Array, a: number, b: number, d: Float64Array, o: number): number {
  return s[b + DP_X]! - s[a + DP_X]! + d[o + DELTA_CENTER_X]!;
}

/** @internal y of the same (see shiftX). */
export function shiftY(s: Float64Array, a: number, b: number, d: Float64Array, o: number): number {
  return s[b + DP_Y]! - s[a + DP_Y]! + d[o + DELTA_CENTER_Y]!;
}
