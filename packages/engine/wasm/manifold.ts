// The manifold a narrow-phase function writes (wasm/collide-*.ts), in the NARROW_PHASE_SCRATCH
// region at `m` (layout: src/dynamics/narrow-phase-scratch.ts): up to two points sharing one
// normal, each a world position midway between the two surfaces, a separation (m, negative when
// overlapping, rounding radii included) and a feature id that matches points across steps.
// updateManifold (update-manifold.ts) moves it into the contact's slot.
//
// A transform is 4 doubles (x, y, cos, sin) at the offsets of a body's pose in the body memory
// (B_X, B_Y, B_C, B_S, src/dynamics/body-memory.ts): the narrow phase reads the bodies' poses in
// place.
import {
  B_C,
  B_S,
  B_X,
  B_Y,
  MP_ID,
  MP_SEPARATION,
  MP_X,
  MP_Y,
  M_COUNT,
  M_NORMAL_X,
  M_NORMAL_Y,
  M_POINTS,
  M_POINT_STRIDE,
  M_SPECULATIVE_DISTANCE,
} from './contact-layout';
import { ld, st } from './load-store';

/** Feature key for a pair of features (reference edge or vertex index, incident index). */
export function makeFeatureId(a: i32, b: i32): i32 {
  return ((a & 0xff) << 8) | (b & 0xff);
}

/** The speculative distance the caller set (m): points at least this far apart are dropped. */
export function speculativeDistanceOf(m: usize): f64 {
  return ld(m, M_SPECULATIVE_DISTANCE);
}

export function setPointCount(m: usize, count: i32): void {
  st(m, M_COUNT, <f64>count);
}

export function pointCountOf(m: usize): i32 {
  return <i32>ld(m, M_COUNT);
}

/** Stores the normal (world frame), given in A's frame: turned by A's rotation. */
export function writeNormal(m: usize, nx: f64, ny: f64, xfA: usize): void {
  const c = ld(xfA, B_C);
  const s = ld(xfA, B_S);
  st(m, M_NORMAL_X, c * nx - s * ny);
  st(m, M_NORMAL_Y, s * nx + c * ny);
}

/** Stores the normal already in the world frame. */
export function writeWorldNormal(m: usize, nx: f64, ny: f64): void {
  st(m, M_NORMAL_X, nx);
  st(m, M_NORMAL_Y, ny);
}

/** Where point `index` (0 or 1) of the manifold starts. */
export function pointAt(m: usize, index: i32): usize {
  return m + ((<usize>(M_POINTS + index * M_POINT_STRIDE)) << 3);
}

/**
 * Stores point `index` given in A's local frame (m): turned by A's rotation (the point relative
 * to A's origin), then moved by A's origin into the world.
 */
export function writePoint(
  m: usize,
  index: i32,
  localX: f64,
  localY: f64,
  separation: f64,
  id: i32,
  xfA: usize,
): void {
  const c = ld(xfA, B_C);
  const s = ld(xfA, B_S);
  const anchorX = c * localX - s * localY;
  const anchorY = s * localX + c * localY;
  writeWorldPoint(m, index, anchorX + ld(xfA, B_X), anchorY + ld(xfA, B_Y), separation, id);
}

/** Stores point `index` in the world frame. */
export function writeWorldPoint(
  m: usize,
  index: i32,
  x: f64,
  y: f64,
  separation: f64,
  id: i32,
): void {
  const p = pointAt(m, index);
  st(p, MP_X, x);
  st(p, MP_Y, y);
  st(p, MP_SEPARATION, separation);
  st(p, MP_ID, <f64>id);
}
