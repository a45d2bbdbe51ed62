// Where a constraint's numbers are, for every contact pass (contact-kernel.ts, circle-pairs.ts,
// shock-propagation.ts): the one definition of the paired layout's addressing in the kernel
// (src/dynamics/contact-constraint-layout.ts's constraintBase, in bytes).
import { MARK_STRIDE, POINTS, POINT_STRIDE, STATE_STRIDE, STRIDE } from './contact-layout';

/** Where constraint i starts (its number 0; number k is 16 k bytes on). */
export function constraintAt(cPtr: usize, i: i32): usize {
  return cPtr + ((<usize>(((i >> 1) * STRIDE) << 1)) << 3) + ((<usize>(i & 1)) << 3);
}

/** Where point j of the constraint at `c` starts. */
export function pointAt(c: usize, j: i32): usize {
  return c + ((<usize>(POINTS + j * POINT_STRIDE)) << 4);
}

/** Number k of the constraint or point at `p`. */
export function lc(p: usize, k: i32): f64 {
  return load<f64>(p + ((<usize>k) << 4));
}

export function sc(p: usize, k: i32, v: f64): void {
  store<f64>(p + ((<usize>k) << 4), v);
}

/** The impact mark and sub-step velocity change of the body at state offset `a` (body-state.ts). */
export function markOf(marksPtr: usize, a: i32): usize {
  return marksPtr + ((<usize>((a / STATE_STRIDE) * MARK_STRIDE)) << 3);
}
