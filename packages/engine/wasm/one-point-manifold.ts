// What the one-point narrow phases (a circle against a capsule, a segment or a polygon) share:
// the circle's centre in A's frame, and the manifold written from A's frame.
import { B_C, B_S, B_X, B_Y, G_VERTICES } from './contact-layout';
import { ld } from './load-store';
import { makeFeatureId, setPointCount, writeNormal, writePoint } from './manifold';

/** Circle B's centre (geometry row `b`) in A's frame, c = RA^T (RB cb + pB - pA): x. */
export function circleCenterInAX(b: usize, xfA: usize, xfB: usize): f64 {
  const wx = circleWorldX(b, xfA, xfB);
  const wy = circleWorldY(b, xfA, xfB);
  return ld(xfA, B_C) * wx + ld(xfA, B_S) * wy;
}

/** The same centre's y. */
export function circleCenterInAY(b: usize, xfA: usize, xfB: usize): f64 {
  const wx = circleWorldX(b, xfA, xfB);
  const wy = circleWorldY(b, xfA, xfB);
  return -ld(xfA, B_S) * wx + ld(xfA, B_C) * wy;
}

function circleWorldX(b: usize, xfA: usize, xfB: usize): f64 {
  const x = ld(b, G_VERTICES);
  const y = ld(b, G_VERTICES + 1);
  return ld(xfB, B_C) * x - ld(xfB, B_S) * y + ld(xfB, B_X) - ld(xfA, B_X);
}

function circleWorldY(b: usize, xfA: usize, xfB: usize): f64 {
  const x = ld(b, G_VERTICES);
  const y = ld(b, G_VERTICES + 1);
  return ld(xfB, B_S) * x + ld(xfB, B_C) * y + ld(xfB, B_Y) - ld(xfA, B_Y);
}

/**
 * Writes the one-point manifold whose point (px, py), unit normal (nx, ny, from A to B) and
 * separation (m) are in A's frame: the normal and the point turned into the world frame, feature
 * id 0.
 */
export function writeOnePoint(
  m: usize,
  px: f64,
  py: f64,
  nx: f64,
  ny: f64,
  separation: f64,
  xfA: usize,
): void {
  writeNormal(m, nx, ny, xfA);
  setPointCount(m, 1);
  writePoint(m, 0, px, py, separation, makeFeatureId(0, 0), xfA);
}
