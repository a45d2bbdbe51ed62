// The contact passes: prepare, warm start, solve and relax, store. The one source of each:
// scripts/contact-kernel-build.ts compiles this file to WebAssembly and turns the same optimised
// module into JavaScript (Binaryen's wasm2js) for hosts where WebAssembly cannot compile; both
// builds give bit-identical worlds. Written in AssemblyScript's portable subset: f64 and i32
// arithmetic, memory read and written only through load/store (ld/st below) at the byte offsets
// the solver passes in (solver-memory.ts), no allocation, no runtime. The layout constants come
// from contact-layout.ts, generated from the engine's definitions (contact-constraint-layout.ts,
// contact-data.ts, body-state.ts).
//
// Contact constraints of one step, prepared once into flat arrays so the sub-step loops touch only
// numbers (Box2D v3 prepares contact constraints the same way, "b2PrepareContactsTask").
//
// Sequential impulses (Catto, GDC 2006 "Fast and simple physics using sequential impulses") with
// accumulated, clamped impulses; soft contacts and sub-stepping (Catto, Box2D v3 "soft step") for
// position error: no separate position pass, anchors fixed for the step, the separation updated
// from the bodies' pose change. Normal first, then friction limited by the new normal impulse.
//
// Two-point manifolds (a face on a face) solve their two normal impulses together, as one 2x2
// block LCP (Box2D v2's block solver, Catto's b2ContactSolver, for the case enumeration), in the
// solve and relax passes and at the moment of impact. Why: point after point, the first point of
// a flat landing takes the whole impulse and the second a smaller one, so a box dropped flat picks
// up spin (9 rad/s and 19 m of rolling at e = 1); the block gives both points their exact share and
// a flat drop stays flat to the last bit (test/fidelity/symmetric-impacts.test.ts). Sequential
// stays for ill-conditioned blocks (points nearly on top of each other, where K^-1 trades huge
// opposite impulses), for mixed pairs (one point bouncing, the other not yet touching), and for
// friction: friction of a straight landing is zero at both points, and measured spin stays 0 with
// friction 0.6, so no symmetric friction pass was needed.
import {
  A_CONTACT_BIAS_RATE,
  A_CONTACT_HERTZ,
  A_CONTACT_IMPULSE_SCALE,
  A_CONTACT_MASS_SCALE,
  A_CONTACT_ZETA,
  A_DT,
  A_H,
  A_IMPACT_SPEED,
  A_INVERSE_H,
  A_LOAD_SPEED,
  A_MAX_PUSH_SPEED,
  A_RESTITUTION_THRESHOLD,
  A_STATIC_BIAS_RATE,
  A_STATIC_IMPULSE_SCALE,
  A_STATIC_MASS_SCALE,
  BASE_SEPARATION,
  BIAS_RATE,
  BLOCK,
  BLOCK_K11,
  BLOCK_K12,
  BLOCK_K22,
  CENTER_DX,
  CENTER_DY,
  CONTACT_STRIDE,
  C_BOUNCING_STEPS,
  C_FRICTION,
  C_MAX_NORMAL_IMPULSE,
  C_NORMAL_IMPULSE,
  C_NORMAL_X,
  C_NORMAL_Y,
  C_POINTS,
  C_POINT_COUNT,
  C_POINT_STRIDE,
  C_RADIUS_A,
  C_RADIUS_B,
  C_RELATIVE_VELOCITY,
  C_RESTITUTION,
  C_SEPARATION,
  C_STEP_NORMAL_IMPULSE,
  C_STEP_TANGENT_IMPULSE,
  C_TANGENT_IMPULSE,
  C_X,
  C_Y,
  DELTA_ANGLE,
  DP_X,
  DP_Y,
  FRICTION,
  IMPACT,
  IMPACT_CLOSE,
  IMPACT_CONTINUE,
  IMPACT_COUNT,
  IMPACT_OPEN,
  IMPACT_ROUND,
  IMPULSE_SCALE,
  INV_I_A,
  INV_I_B,
  INV_MASS_A,
  INV_MASS_B,
  KICK_VX,
  KICK_VY,
  KICK_W,
  LINEAR_SLOP,
  MARK,
  MASS_SCALE,
  MAX_CONDITION_NUMBER,
  MAX_NORMAL_IMPULSE,
  NORMAL_IMPULSE,
  NORMAL_MASS,
  NORMAL_X,
  NORMAL_Y,
  POINT_COUNT,
  POINT_STRIDE,
  PRESSED_AFTER_BOUNCING_STEPS,
  Q_C,
  Q_S,
  RADIUS_A,
  RADIUS_B,
  REF_DP_AX,
  REF_DP_AY,
  REF_DP_BX,
  REF_DP_BY,
  RELATIVE_VELOCITY,
  RESTITUTION,
  RN_A,
  RN_B,
  R_AX,
  R_AY,
  R_BX,
  R_BY,
  SHIFT_WEIGHT_A,
  SHIFT_WEIGHT_B,
  STATE_STRIDE,
  TABLE_CENTER_X,
  TABLE_CENTER_Y,
  TABLE_INV_I,
  TABLE_INV_MASS,
  TABLE_SLOT,
  TABLE_STRIDE,
  TANGENT_IMPULSE,
  TANGENT_MASS,
  TOTAL_NORMAL_IMPULSE,
  TOTAL_TANGENT_IMPULSE,
  V_X,
  V_Y,
  W,
} from './contact-layout';
import { LANES } from './contact-lanes';
import { ld, st } from './load-store';
import { constraintAt, lc, markOf, pointAt, sc } from './constraint-access';

// The body passes (integration, speed limits, finalize) are built into the same module: their
// source is body-passes.ts.
export {
  finalizeBodies,
  integratePositions,
  integrateVelocities,
  limitSpeeds,
} from './body-passes';
// The passes between the contact passes: the circle pairs' normals, the heavy-on-light sweep.
export { refreshCirclePairs } from './circle-pairs';
export { prepareShockSweep, shockSweep } from './shock-propagation';
// The engine's cosSin and hypot, for the tests (their source is src/math/).
export { cosSin, hypot } from './kernel-math';

// The narrow phase (issue #30): the gates over the contact slots and the manifolds they leave to
// compute, from the shapes' geometry rows.
export { collideContacts } from './contact-gates';
export { collidePair } from './update-manifold';
// The broad-phase boxes of finalize: shape-bounds.ts.
export { bodyBounds, shapeBounds } from './shape-bounds';

// The joints' passes (joint-passes.ts) are a module of their own over the same memory, built by
// the same script: apps without joints do not ship them.

// The constraints are stored in pairs, their numbers interleaved: number k of constraint i is at
// double (i >> 1) * 2 * STRIDE + 2 * k + (i & 1) of the constraint region, so constraints 2m and
// 2m + 1 have each number side by side, and the lanes (below) fetch both with one v128.load
// (Box2D v3 stores its SIMD constraints the same way, b2ContactConstraintSIMD). A scalar pass
// reads number k of a constraint or point at pointer + 16 k: lc and sc (constraint-access.ts,
// shared with the passes in files of their own: circle-pairs.ts, shock-propagation.ts).

/**
 * How much this sub-step's integration (gravity, forces) changed the approach along (nx, ny) at
 * the lever arms (bAx, bAy), (bBx, bBy) of the bodies whose marks are `kA`, `kB` (see markOf).
 */
function kickApproach(
  kA: usize,
  kB: usize,
  bAx: f64,
  bAy: f64,
  bBx: f64,
  bBy: f64,
  nx: f64,
  ny: f64,
): f64 {
  const wA = ld(kA, KICK_W);
  const wB = ld(kB, KICK_W);
  return (
    (ld(kB, KICK_VX) - wB * bBy - (ld(kA, KICK_VX) - wA * bAy)) * nx +
    (ld(kB, KICK_VY) + wB * bBx - (ld(kA, KICK_VY) + wA * bAx)) * ny
  );
}

/** kickApproach with the lever arms as cross products with the normal (rA x n, rB x n). */
function kickNormal(kA: usize, kB: usize, nx: f64, ny: f64, leverA: f64, leverB: f64): f64 {
  return (
    (ld(kB, KICK_VX) - ld(kA, KICK_VX)) * nx +
    (ld(kB, KICK_VY) - ld(kA, KICK_VY)) * ny +
    ld(kB, KICK_W) * leverB -
    ld(kA, KICK_W) * leverA
  );
}

/**
 * Before point `p` is warm-started: a bounce is a one-off impulse, not a contact force to carry
 * into the next sub-step; an impact of an earlier round neither (see impacts). One function for
 * the scalar pass and the lanes, so they cannot drift apart.
 */
function dropOneOffImpulse(p: usize): void {
  const impact = lc(p, IMPACT);
  if (impact == 2) {
    sc(p, IMPACT, 3);
    sc(p, NORMAL_IMPULSE, 0);
  } else if (impact == 6) {
    sc(p, IMPACT, 0);
    sc(p, NORMAL_IMPULSE, 0);
  }
}

function advancePose(k: usize, dx: f64, dy: f64, angle: f64): void {
  st(k, DP_X, ld(k, DP_X) + dx);
  st(k, DP_Y, ld(k, DP_Y) + dy);
  if (angle != 0) {
    st(k, DELTA_ANGLE, ld(k, DELTA_ANGLE) + angle);
    const qc = ld(k, Q_C);
    const qs = ld(k, Q_S);
    const c = qc - angle * qs;
    const sn = qs + angle * qc;
    const inverseLength = 1 / Math.sqrt(c * c + sn * sn);
    st(k, Q_C, c * inverseLength);
    st(k, Q_S, sn * inverseLength);
  }
}

// Contacts in lanes (WebAssembly build only, LANES): constraints 2m and 2m + 1, when visited one
// after the other and sharing no moving body, are solved side by side in the two lanes of an
// f64x2 (Box2D v3 solves graph colours in SIMD lanes, b2ContactConstraintSIMD). The solver pairs
// them before the step (src/dynamics/contact-pairing.ts) and stores their numbers interleaved
// (constraintAt above), so each number of both is one v128.load. Each lane does the scalar pass's
// f64 operations in the same order, and f64x2 operations round exactly as f64 ones, so a pair
// gives the bits of the two constraints solved one after the other, which is what the JavaScript
// build (LANES false, wasm2js cannot translate SIMD) does with the same order. Pairs take the
// common path only (equal point counts; in the solve pass no restitution and equal block flags,
// and a block case both lanes accept); any other pair goes through the scalar pass one
// constraint at a time.

/** Number k of two states as the lanes of an f64x2 (two loads: states are not paired). */
function lanes(p1: usize, p2: usize, k: i32): v128 {
  return f64x2.replace_lane(f64x2.splat(ld(p1, k)), 1, ld(p2, k));
}

/** Number k of the pair of constraints (or points) whose first is at `p`, one load for both. */
function lanesOf(p: usize, k: i32): v128 {
  return v128.load(p + ((<usize>k) << 4));
}

function stLanesOf(p: usize, k: i32, v: v128): void {
  v128.store(p + ((<usize>k) << 4), v);
}

/** A state's velocity, unless it is slot 0 (immovable: the shared identity state). */
function stVelocity(s: usize, lane: u8, vx: v128, vy: v128, w: v128): void {
  if (lane == 0) {
    st(s, V_X, f64x2.extract_lane(vx, 0));
    st(s, V_Y, f64x2.extract_lane(vy, 0));
    st(s, W, f64x2.extract_lane(w, 0));
  } else {
    st(s, V_X, f64x2.extract_lane(vx, 1));
    st(s, V_Y, f64x2.extract_lane(vy, 1));
    st(s, W, f64x2.extract_lane(w, 1));
  }
}

/** Whether constraints i1 and i2 share no moving body (state slot 0 is immovable). */
function independent(bodiesPtr: usize, i1: i32, i2: i32): bool {
  const a1 = load<i32>(bodiesPtr + ((<usize>i1) << 3));
  const b1 = load<i32>(bodiesPtr + ((<usize>i1) << 3), 4);
  const a2 = load<i32>(bodiesPtr + ((<usize>i2) << 3));
  const b2 = load<i32>(bodiesPtr + ((<usize>i2) << 3), 4);
  return (a1 == 0 || (a1 != a2 && a1 != b2)) && (b1 == 0 || (b1 != a2 && b1 != b2));
}

/** The warm start of independent constraints i1 and i1 + 1 in lanes; false (nothing done) off the common path. */
function warmStartPair(cPtr: usize, bodiesPtr: usize, sPtr: usize, i1: i32): bool {
  const i2 = i1 + 1;
  const c1 = constraintAt(cPtr, i1);
  const c2 = c1 + 8;
  const pointCount = <i32>lc(c1, POINT_COUNT);
  if (<i32>lc(c2, POINT_COUNT) != pointCount) return false;
  const a1 = load<i32>(bodiesPtr + ((<usize>i1) << 3));
  const b1 = load<i32>(bodiesPtr + ((<usize>i1) << 3), 4);
  const a2 = load<i32>(bodiesPtr + ((<usize>i2) << 3));
  const b2 = load<i32>(bodiesPtr + ((<usize>i2) << 3), 4);
  const sa1 = sPtr + ((<usize>a1) << 3);
  const sb1 = sPtr + ((<usize>b1) << 3);
  const sa2 = sPtr + ((<usize>a2) << 3);
  const sb2 = sPtr + ((<usize>b2) << 3);
  const mA = lanesOf(c1, INV_MASS_A);
  const iA = lanesOf(c1, INV_I_A);
  const mB = lanesOf(c1, INV_MASS_B);
  const iB = lanesOf(c1, INV_I_B);
  const nx = lanesOf(c1, NORMAL_X);
  const ny = lanesOf(c1, NORMAL_Y);
  const tx = ny;
  const ty = f64x2.neg(nx);
  let vAx = lanes(sa1, sa2, V_X);
  let vAy = lanes(sa1, sa2, V_Y);
  let wA = lanes(sa1, sa2, W);
  let vBx = lanes(sb1, sb2, V_X);
  let vBy = lanes(sb1, sb2, V_Y);
  let wB = lanes(sb1, sb2, W);
  const shiftA = lanesOf(c1, SHIFT_WEIGHT_A);
  const shiftB = lanesOf(c1, SHIFT_WEIGHT_B);
  const eAx = f64x2.sub(lanes(sa1, sa2, DP_X), lanesOf(c1, REF_DP_AX));
  const eAy = f64x2.sub(lanes(sa1, sa2, DP_Y), lanesOf(c1, REF_DP_AY));
  const eBx = f64x2.sub(lanes(sb1, sb2, DP_X), lanesOf(c1, REF_DP_BX));
  const eBy = f64x2.sub(lanes(sb1, sb2, DP_Y), lanesOf(c1, REF_DP_BY));
  const shiftX = f64x2.add(f64x2.mul(shiftA, eAx), f64x2.mul(shiftB, eBx));
  const shiftY = f64x2.add(f64x2.mul(shiftA, eAy), f64x2.mul(shiftB, eBy));
  const sAx = f64x2.sub(shiftX, eAx);
  const sAy = f64x2.sub(shiftY, eAy);
  const sBx = f64x2.sub(shiftX, eBx);
  const sBy = f64x2.sub(shiftY, eBy);
  const dnA = f64x2.sub(f64x2.mul(sAx, ny), f64x2.mul(sAy, nx));
  const dnB = f64x2.sub(f64x2.mul(sBx, ny), f64x2.mul(sBy, nx));
  const dtA = f64x2.neg(f64x2.add(f64x2.mul(sAx, nx), f64x2.mul(sAy, ny)));
  const dtB = f64x2.neg(f64x2.add(f64x2.mul(sBx, nx), f64x2.mul(sBy, ny)));
  for (let j = 0; j < pointCount; j++) {
    const p1 = pointAt(c1, j);
    const p2 = pointAt(c2, j);
    dropOneOffImpulse(p1);
    dropOneOffImpulse(p2);
    const pn = lanesOf(p1, NORMAL_IMPULSE);
    const pt = lanesOf(p1, TANGENT_IMPULSE);
    const px = f64x2.add(f64x2.mul(pn, nx), f64x2.mul(pt, tx));
    const py = f64x2.add(f64x2.mul(pn, ny), f64x2.mul(pt, ty));
    const rtA = f64x2.sub(
      dtA,
      f64x2.add(f64x2.mul(lanesOf(p1, R_AX), nx), f64x2.mul(lanesOf(p1, R_AY), ny)),
    );
    const rtB = f64x2.sub(
      dtB,
      f64x2.add(f64x2.mul(lanesOf(p1, R_BX), nx), f64x2.mul(lanesOf(p1, R_BY), ny)),
    );
    wA = f64x2.sub(
      wA,
      f64x2.mul(
        iA,
        f64x2.add(f64x2.mul(pn, f64x2.add(lanesOf(p1, RN_A), dnA)), f64x2.mul(pt, rtA)),
      ),
    );
    vAx = f64x2.sub(vAx, f64x2.mul(mA, px));
    vAy = f64x2.sub(vAy, f64x2.mul(mA, py));
    wB = f64x2.add(
      wB,
      f64x2.mul(
        iB,
        f64x2.add(f64x2.mul(pn, f64x2.add(lanesOf(p1, RN_B), dnB)), f64x2.mul(pt, rtB)),
      ),
    );
    vBx = f64x2.add(vBx, f64x2.mul(mB, px));
    vBy = f64x2.add(vBy, f64x2.mul(mB, py));
  }
  if (a1 != 0) stVelocity(sa1, 0, vAx, vAy, wA);
  if (b1 != 0) stVelocity(sb1, 0, vBx, vBy, wB);
  if (a2 != 0) stVelocity(sa2, 1, vAx, vAy, wA);
  if (b2 != 0) stVelocity(sb2, 1, vBx, vBy, wB);
  return true;
}

/** The separation of point p1/p2 now (see solve). */
function separationLanes(p: usize, dpn: v128, nAx: v128, nAy: v128, nBx: v128, nBy: v128): v128 {
  return f64x2.add(
    f64x2.sub(
      f64x2.add(dpn, f64x2.add(f64x2.mul(lanesOf(p, R_BX), nBx), f64x2.mul(lanesOf(p, R_BY), nBy))),
      f64x2.add(f64x2.mul(lanesOf(p, R_AX), nAx), f64x2.mul(lanesOf(p, R_AY), nAy)),
    ),
    lanesOf(p, BASE_SEPARATION),
  );
}

/** Stores the larger of v and number k, lane by lane (the scalar pass's `if (v > old) sc(v)`). */
function stMaxLanes(p: usize, k: i32, v: v128): void {
  const old = lanesOf(p, k);
  stLanesOf(p, k, v128.bitselect(v, old, f64x2.gt(v, old)));
}

/**
 * One solve (useBias) or relax pass of independent constraints i1 and i1 + 1 in lanes; false, with
 * nothing written, off the common path (see above).
 */
function solvePair(
  cPtr: usize,
  bodiesPtr: usize,
  sPtr: usize,
  i1: i32,
  inverseH: f64,
  maxPushSpeed: f64,
  useBias: bool,
): bool {
  const i2 = i1 + 1;
  const c1 = constraintAt(cPtr, i1);
  const c2 = c1 + 8;
  const pointCount = <i32>lc(c1, POINT_COUNT);
  const block = lc(c1, BLOCK) == 1;
  if (
    <i32>lc(c2, POINT_COUNT) != pointCount ||
    (lc(c2, BLOCK) == 1) != block ||
    lc(c1, RESTITUTION) > 0 ||
    lc(c2, RESTITUTION) > 0
  ) {
    return false;
  }
  const a1 = load<i32>(bodiesPtr + ((<usize>i1) << 3));
  const b1 = load<i32>(bodiesPtr + ((<usize>i1) << 3), 4);
  const a2 = load<i32>(bodiesPtr + ((<usize>i2) << 3));
  const b2 = load<i32>(bodiesPtr + ((<usize>i2) << 3), 4);
  const sa1 = sPtr + ((<usize>a1) << 3);
  const sb1 = sPtr + ((<usize>b1) << 3);
  const sa2 = sPtr + ((<usize>a2) << 3);
  const sb2 = sPtr + ((<usize>b2) << 3);
  const zero = f64x2.splat(0);
  const one = f64x2.splat(1);
  const rate = f64x2.splat(inverseH);
  const floor = f64x2.splat(-maxPushSpeed);
  const mA = lanesOf(c1, INV_MASS_A);
  const iA = lanesOf(c1, INV_I_A);
  const mB = lanesOf(c1, INV_MASS_B);
  const iB = lanesOf(c1, INV_I_B);
  const nx = lanesOf(c1, NORMAL_X);
  const ny = lanesOf(c1, NORMAL_Y);
  const biasRate = lanesOf(c1, BIAS_RATE);
  let vAx = lanes(sa1, sa2, V_X);
  let vAy = lanes(sa1, sa2, V_Y);
  let wA = lanes(sa1, sa2, W);
  let vBx = lanes(sb1, sb2, V_X);
  let vBy = lanes(sb1, sb2, V_Y);
  let wB = lanes(sb1, sb2, W);
  const dpAx = lanes(sa1, sa2, DP_X);
  const dpAy = lanes(sa1, sa2, DP_Y);
  const dpBx = lanes(sb1, sb2, DP_X);
  const dpBy = lanes(sb1, sb2, DP_Y);
  const shiftA = lanesOf(c1, SHIFT_WEIGHT_A);
  const shiftB = lanesOf(c1, SHIFT_WEIGHT_B);
  const eAx = f64x2.sub(dpAx, lanesOf(c1, REF_DP_AX));
  const eAy = f64x2.sub(dpAy, lanesOf(c1, REF_DP_AY));
  const eBx = f64x2.sub(dpBx, lanesOf(c1, REF_DP_BX));
  const eBy = f64x2.sub(dpBy, lanesOf(c1, REF_DP_BY));
  const shiftX = f64x2.add(f64x2.mul(shiftA, eAx), f64x2.mul(shiftB, eBx));
  const shiftY = f64x2.add(f64x2.mul(shiftA, eAy), f64x2.mul(shiftB, eBy));
  const sAx = f64x2.sub(shiftX, eAx);
  const sAy = f64x2.sub(shiftY, eAy);
  const sBx = f64x2.sub(shiftX, eBx);
  const sBy = f64x2.sub(shiftY, eBy);
  const dnA = f64x2.sub(f64x2.mul(sAx, ny), f64x2.mul(sAy, nx));
  const dnB = f64x2.sub(f64x2.mul(sBx, ny), f64x2.mul(sBy, nx));
  const qAc = lanes(sa1, sa2, Q_C);
  const qAs = lanes(sa1, sa2, Q_S);
  const qBc = lanes(sb1, sb2, Q_C);
  const qBs = lanes(sb1, sb2, Q_S);
  const nAx = f64x2.add(f64x2.mul(qAc, nx), f64x2.mul(qAs, ny));
  const nAy = f64x2.sub(f64x2.mul(qAc, ny), f64x2.mul(qAs, nx));
  const nBx = f64x2.add(f64x2.mul(qBc, nx), f64x2.mul(qBs, ny));
  const nBy = f64x2.sub(f64x2.mul(qBc, ny), f64x2.mul(qBs, nx));
  const dpn = f64x2.add(f64x2.mul(f64x2.sub(dpBx, dpAx), nx), f64x2.mul(f64x2.sub(dpBy, dpAy), ny));
  // The soft step's numbers of a touching point (the scalar pass's `else if (useBias)`).
  const massScaleSoft = useBias ? lanesOf(c1, MASS_SCALE) : one;
  const impulseScaleSoft = useBias ? lanesOf(c1, IMPULSE_SCALE) : zero;

  let firstSequential = 0;
  if (block) {
    const p1 = pointAt(c1, 0);
    const p2 = p1 + ((<usize>POINT_STRIDE) << 4);
    // Lanes: (constraint 1, constraint 2); p1 their first points, p2 their second.
    const separation1 = separationLanes(p1, dpn, nAx, nAy, nBx, nBy);
    const separation2 = separationLanes(p2, dpn, nAx, nAy, nBx, nBy);
    const n1A = f64x2.add(lanesOf(p1, RN_A), dnA);
    const n1B = f64x2.add(lanesOf(p1, RN_B), dnB);
    const n2A = f64x2.add(lanesOf(p2, RN_A), dnA);
    const n2B = f64x2.add(lanesOf(p2, RN_B), dnB);
    const k11 = lanesOf(c1, BLOCK_K11);
    const k12 = lanesOf(c1, BLOCK_K12);
    const k22 = lanesOf(c1, BLOCK_K22);
    const speculative1 = f64x2.gt(separation1, zero);
    const speculative2 = f64x2.gt(separation2, zero);
    let bias1 = f64x2.mul(separation1, rate);
    let bias2 = f64x2.mul(separation2, rate);
    let gamma1 = zero;
    let gamma2 = zero;
    if (useBias) {
      const scale = lanesOf(c1, IMPULSE_SCALE);
      bias1 = v128.bitselect(
        bias1,
        f64x2.max(f64x2.mul(biasRate, separation1), floor),
        speculative1,
      );
      bias2 = v128.bitselect(
        bias2,
        f64x2.max(f64x2.mul(biasRate, separation2), floor),
        speculative2,
      );
      gamma1 = v128.bitselect(zero, f64x2.div(f64x2.mul(k11, scale), massScaleSoft), speculative1);
      gamma2 = v128.bitselect(zero, f64x2.div(f64x2.mul(k22, scale), massScaleSoft), speculative2);
    } else {
      bias1 = v128.bitselect(bias1, zero, speculative1);
      bias2 = v128.bitselect(bias2, zero, speculative2);
    }
    const dvn = f64x2.add(f64x2.mul(f64x2.sub(vBx, vAx), nx), f64x2.mul(f64x2.sub(vBy, vAy), ny));
    const vn1 = f64x2.sub(f64x2.add(dvn, f64x2.mul(wB, n1B)), f64x2.mul(wA, n1A));
    const vn2 = f64x2.sub(f64x2.add(dvn, f64x2.mul(wB, n2B)), f64x2.mul(wA, n2A));
    const accumulated1 = lanesOf(p1, NORMAL_IMPULSE);
    const accumulated2 = lanesOf(p2, NORMAL_IMPULSE);
    const a11 = f64x2.add(k11, gamma1);
    const a22 = f64x2.add(k22, gamma2);
    const r1 = f64x2.sub(
      f64x2.add(vn1, bias1),
      f64x2.add(f64x2.mul(k11, accumulated1), f64x2.mul(k12, accumulated2)),
    );
    const r2 = f64x2.sub(
      f64x2.add(vn2, bias2),
      f64x2.add(f64x2.mul(k12, accumulated1), f64x2.mul(k22, accumulated2)),
    );
    // The scalar pass's four cases, each lane taking the first that holds.
    const det = f64x2.sub(f64x2.mul(a11, a22), f64x2.mul(k12, k12));
    const y1 = f64x2.div(f64x2.sub(f64x2.mul(k12, r2), f64x2.mul(a22, r1)), det);
    const y2 = f64x2.div(f64x2.sub(f64x2.mul(k12, r1), f64x2.mul(a11, r2)), det);
    const z1 = f64x2.div(f64x2.neg(r1), a11);
    const z2 = f64x2.div(f64x2.neg(r2), a22);
    const case1 = v128.and(f64x2.ge(y1, zero), f64x2.ge(y2, zero));
    const case2 = v128.and(f64x2.ge(z1, zero), f64x2.ge(f64x2.add(f64x2.mul(k12, z1), r2), zero));
    const case3 = v128.and(f64x2.ge(z2, zero), f64x2.ge(f64x2.add(f64x2.mul(k12, z2), r1), zero));
    const case4 = v128.and(f64x2.ge(r1, zero), f64x2.ge(r2, zero));
    const none = f64x2.splat(-1);
    let x1 = v128.bitselect(zero, none, case4);
    let x2 = x1;
    x1 = v128.bitselect(zero, x1, case3);
    x2 = v128.bitselect(z2, x2, case3);
    x1 = v128.bitselect(z1, x1, case2);
    x2 = v128.bitselect(zero, x2, case2);
    x1 = v128.bitselect(y1, x1, case1);
    x2 = v128.bitselect(y2, x2, case1);
    if (!i64x2.all_true(v128.and(f64x2.ge(x1, zero), f64x2.ge(x2, zero)))) return false;
    firstSequential = 2;
    const dx1 = f64x2.sub(x1, accumulated1);
    const dx2 = f64x2.sub(x2, accumulated2);
    stLanesOf(p1, NORMAL_IMPULSE, x1);
    stLanesOf(p2, NORMAL_IMPULSE, x2);
    if (!useBias) {
      stLanesOf(p1, TOTAL_NORMAL_IMPULSE, f64x2.add(lanesOf(p1, TOTAL_NORMAL_IMPULSE), x1));
      stLanesOf(p2, TOTAL_NORMAL_IMPULSE, f64x2.add(lanesOf(p2, TOTAL_NORMAL_IMPULSE), x2));
    }
    stMaxLanes(p1, MAX_NORMAL_IMPULSE, dx1);
    stMaxLanes(p2, MAX_NORMAL_IMPULSE, dx2);
    const sum = f64x2.add(dx1, dx2);
    vAx = f64x2.sub(vAx, f64x2.mul(f64x2.mul(mA, sum), nx));
    vAy = f64x2.sub(vAy, f64x2.mul(f64x2.mul(mA, sum), ny));
    wA = f64x2.sub(wA, f64x2.mul(iA, f64x2.add(f64x2.mul(n1A, dx1), f64x2.mul(n2A, dx2))));
    vBx = f64x2.add(vBx, f64x2.mul(f64x2.mul(mB, sum), nx));
    vBy = f64x2.add(vBy, f64x2.mul(f64x2.mul(mB, sum), ny));
    wB = f64x2.add(wB, f64x2.mul(iB, f64x2.add(f64x2.mul(n1B, dx1), f64x2.mul(n2B, dx2))));
  }

  for (let j = firstSequential; j < pointCount; j++) {
    const p1 = pointAt(c1, j);
    const separation = separationLanes(p1, dpn, nAx, nAy, nBx, nBy);
    const leverA = f64x2.add(lanesOf(p1, RN_A), dnA);
    const leverB = f64x2.add(lanesOf(p1, RN_B), dnB);
    const speculative = f64x2.gt(separation, zero);
    const bias = v128.bitselect(
      f64x2.mul(separation, rate),
      useBias ? f64x2.max(f64x2.mul(biasRate, separation), floor) : zero,
      speculative,
    );
    const massScale = v128.bitselect(one, massScaleSoft, speculative);
    const impulseScale = v128.bitselect(zero, impulseScaleSoft, speculative);
    const vn = f64x2.sub(
      f64x2.add(
        f64x2.add(f64x2.mul(f64x2.sub(vBx, vAx), nx), f64x2.mul(f64x2.sub(vBy, vAy), ny)),
        f64x2.mul(wB, leverB),
      ),
      f64x2.mul(wA, leverA),
    );
    const accumulated = lanesOf(p1, NORMAL_IMPULSE);
    const newImpulse = f64x2.max(
      f64x2.sub(
        f64x2.sub(
          accumulated,
          f64x2.mul(f64x2.mul(lanesOf(p1, NORMAL_MASS), massScale), f64x2.add(vn, bias)),
        ),
        f64x2.mul(impulseScale, accumulated),
      ),
      zero,
    );
    const impulse = f64x2.sub(newImpulse, accumulated);
    stLanesOf(p1, NORMAL_IMPULSE, newImpulse);
    if (!useBias) {
      stLanesOf(p1, TOTAL_NORMAL_IMPULSE, f64x2.add(lanesOf(p1, TOTAL_NORMAL_IMPULSE), newImpulse));
    }
    stMaxLanes(p1, MAX_NORMAL_IMPULSE, impulse);
    vAx = f64x2.sub(vAx, f64x2.mul(f64x2.mul(mA, impulse), nx));
    vAy = f64x2.sub(vAy, f64x2.mul(f64x2.mul(mA, impulse), ny));
    wA = f64x2.sub(wA, f64x2.mul(f64x2.mul(iA, leverA), impulse));
    vBx = f64x2.add(vBx, f64x2.mul(f64x2.mul(mB, impulse), nx));
    vBy = f64x2.add(vBy, f64x2.mul(f64x2.mul(mB, impulse), ny));
    wB = f64x2.add(wB, f64x2.mul(f64x2.mul(iB, leverB), impulse));
  }

  const dtA = f64x2.neg(f64x2.add(f64x2.mul(sAx, nx), f64x2.mul(sAy, ny)));
  const dtB = f64x2.neg(f64x2.add(f64x2.mul(sBx, nx), f64x2.mul(sBy, ny)));
  const friction = lanesOf(c1, FRICTION);
  for (let j = 0; j < pointCount; j++) {
    const p1 = pointAt(c1, j);
    const leverA = f64x2.sub(
      dtA,
      f64x2.add(f64x2.mul(lanesOf(p1, R_AX), nx), f64x2.mul(lanesOf(p1, R_AY), ny)),
    );
    const leverB = f64x2.sub(
      dtB,
      f64x2.add(f64x2.mul(lanesOf(p1, R_BX), nx), f64x2.mul(lanesOf(p1, R_BY), ny)),
    );
    const vt = f64x2.sub(
      f64x2.add(
        f64x2.sub(f64x2.mul(f64x2.sub(vBx, vAx), ny), f64x2.mul(f64x2.sub(vBy, vAy), nx)),
        f64x2.mul(wB, leverB),
      ),
      f64x2.mul(wA, leverA),
    );
    const accumulated = lanesOf(p1, TANGENT_IMPULSE);
    const maxFriction = f64x2.mul(friction, lanesOf(p1, NORMAL_IMPULSE));
    const minFriction = f64x2.neg(maxFriction);
    const free = f64x2.sub(accumulated, f64x2.mul(lanesOf(p1, TANGENT_MASS), vt));
    const above = f64x2.gt(free, maxFriction);
    const below = v128.andnot(f64x2.lt(free, minFriction), above);
    const newImpulse = v128.bitselect(minFriction, v128.bitselect(maxFriction, free, above), below);
    const impulse = f64x2.sub(newImpulse, accumulated);
    stLanesOf(p1, TANGENT_IMPULSE, newImpulse);
    if (!useBias) {
      stLanesOf(
        p1,
        TOTAL_TANGENT_IMPULSE,
        f64x2.add(lanesOf(p1, TOTAL_TANGENT_IMPULSE), newImpulse),
      );
    }
    vAx = f64x2.sub(vAx, f64x2.mul(f64x2.mul(mA, impulse), ny));
    vAy = f64x2.add(vAy, f64x2.mul(f64x2.mul(mA, impulse), nx));
    wA = f64x2.sub(wA, f64x2.mul(f64x2.mul(iA, leverA), impulse));
    vBx = f64x2.add(vBx, f64x2.mul(f64x2.mul(mB, impulse), ny));
    vBy = f64x2.sub(vBy, f64x2.mul(f64x2.mul(mB, impulse), nx));
    wB = f64x2.add(wB, f64x2.mul(f64x2.mul(iB, leverB), impulse));
  }

  if (a1 != 0) stVelocity(sa1, 0, vAx, vAy, wA);
  if (b1 != 0) stVelocity(sb1, 0, vBx, vBy, wB);
  if (a2 != 0) stVelocity(sa2, 1, vAx, vAy, wA);
  if (b2 != 0) stVelocity(sb2, 1, vBx, vBy, wB);
  return true;
}

/**
 * Applies last step's accumulated impulses, so resting contacts start where they left off; to the
 * `count` constraints listed from `orderPtr`.
 */
export function warmStart(
  cPtr: usize,
  bodiesPtr: usize,
  orderPtr: usize,
  sPtr: usize,
  count: i32,
): void {
  for (let n = 0; n < count; n++) {
    const i = load<i32>(orderPtr + ((<usize>n) << 2));
    if (LANES && (i & 1) == 0 && n + 1 < count) {
      const i2 = load<i32>(orderPtr + ((<usize>(n + 1)) << 2));
      if (i2 == i + 1 && independent(bodiesPtr, i, i2) && warmStartPair(cPtr, bodiesPtr, sPtr, i)) {
        n++;
        continue;
      }
    }
    const cb = constraintAt(cPtr, i);
    const a = load<i32>(bodiesPtr + ((<usize>i) << 3));
    const b = load<i32>(bodiesPtr + ((<usize>i) << 3), 4);
    const sa = sPtr + ((<usize>a) << 3);
    const sb = sPtr + ((<usize>b) << 3);
    const mA = lc(cb, INV_MASS_A);
    const iA = lc(cb, INV_I_A);
    const mB = lc(cb, INV_MASS_B);
    const iB = lc(cb, INV_I_B);
    const nx = lc(cb, NORMAL_X);
    const ny = lc(cb, NORMAL_Y);
    const tx = ny;
    const ty = -nx;
    let vAx = ld(sa, V_X);
    let vAy = ld(sa, V_Y);
    let wA = ld(sa, W);
    let vBx = ld(sb, V_X);
    let vBy = ld(sb, V_Y);
    let wB = ld(sb, W);
    const pointCount = <i32>lc(cb, POINT_COUNT);
    // Lever arms to the common point of application (see Preparation.fill).
    const shiftA = lc(cb, SHIFT_WEIGHT_A);
    const shiftB = lc(cb, SHIFT_WEIGHT_B);
    const dpAx = ld(sa, DP_X);
    const dpAy = ld(sa, DP_Y);
    const dpBx = ld(sb, DP_X);
    const dpBy = ld(sb, DP_Y);
    // Motion since the lever arms were set: the step's start, or a circle pair's refresh.
    const eAx = dpAx - lc(cb, REF_DP_AX);
    const eAy = dpAy - lc(cb, REF_DP_AY);
    const eBx = dpBx - lc(cb, REF_DP_BX);
    const eBy = dpBy - lc(cb, REF_DP_BY);
    const shiftX = shiftA * eAx + shiftB * eBx;
    const shiftY = shiftA * eAy + shiftB * eBy;
    // The shift as cross products with n and t (see RN_A).
    const sAx = shiftX - eAx;
    const sAy = shiftY - eAy;
    const sBx = shiftX - eBx;
    const sBy = shiftY - eBy;
    const dnA = sAx * ny - sAy * nx;
    const dnB = sBx * ny - sBy * nx;
    const dtA = -(sAx * nx + sAy * ny);
    const dtB = -(sBx * nx + sBy * ny);
    for (let j = 0; j < pointCount; j++) {
      const p = pointAt(cb, j);
      dropOneOffImpulse(p);
      const pn = lc(p, NORMAL_IMPULSE);
      const pt = lc(p, TANGENT_IMPULSE);
      const px = pn * nx + pt * tx;
      const py = pn * ny + pt * ty;
      const rtA = dtA - (lc(p, R_AX) * nx + lc(p, R_AY) * ny);
      const rtB = dtB - (lc(p, R_BX) * nx + lc(p, R_BY) * ny);
      wA -= iA * (pn * (lc(p, RN_A) + dnA) + pt * rtA);
      vAx -= mA * px;
      vAy -= mA * py;
      wB += iB * (pn * (lc(p, RN_B) + dnB) + pt * rtB);
      vBx += mB * px;
      vBy += mB * py;
    }
    if (a != 0) {
      st(sa, V_X, vAx);
      st(sa, V_Y, vAy);
      st(sa, W, wA);
    }
    if (b != 0) {
      st(sb, V_X, vBx);
      st(sb, V_Y, vBy);
      st(sb, W, wB);
    }
  }
}

/**
 * One pass over the `count` constraints listed from `orderPtr`. With `useBias` the soft position
 * correction pushes overlapping shapes apart (at most `maxPushSpeed`); without it ("relax") the
 * pass removes the velocity that push added, so resting bodies do not gain energy from correction.
 * Returns the number of bounces in the pass (the impact rounds run when there are any, see
 * impacts). A bounce marks its bodies (`marksPtr`, see body-state.ts); a bouncy resting point on
 * a marked body that approaches faster than `impactSpeed` is left for the impact rounds, not
 * stopped here as a resting contact would be (that would absorb the impact); a loaded one only
 * when faster than `loadSpeed` (see solver.ts, MIN_LOADED_IMPACT_SPEED). The inverse sub-step, the
 * push-out limit, the threshold and the two speeds are the arguments at `args`
 * (kernel-arguments.ts).
 */
export function solve(
  cPtr: usize,
  bodiesPtr: usize,
  orderPtr: usize,
  sPtr: usize,
  count: i32,
  args: usize,
  marksPtr: usize,
  useBias: bool,
): i32 {
  const inverseH = ld(args, A_INVERSE_H);
  const maxPushSpeed = ld(args, A_MAX_PUSH_SPEED);
  const restitutionThreshold = ld(args, A_RESTITUTION_THRESHOLD);
  const impactSpeed = ld(args, A_IMPACT_SPEED);
  const loadSpeed = ld(args, A_LOAD_SPEED);
  let bounces: i32 = 0;
  for (let n = 0; n < count; n++) {
    const i = load<i32>(orderPtr + ((<usize>n) << 2));
    if (LANES && (i & 1) == 0 && n + 1 < count) {
      const i2 = load<i32>(orderPtr + ((<usize>(n + 1)) << 2));
      if (
        i2 == i + 1 &&
        independent(bodiesPtr, i, i2) &&
        solvePair(cPtr, bodiesPtr, sPtr, i, inverseH, maxPushSpeed, useBias)
      ) {
        n++;
        continue;
      }
    }
    const cb = constraintAt(cPtr, i);
    const a = load<i32>(bodiesPtr + ((<usize>i) << 3));
    const b = load<i32>(bodiesPtr + ((<usize>i) << 3), 4);
    const sa = sPtr + ((<usize>a) << 3);
    const sb = sPtr + ((<usize>b) << 3);
    const mA = lc(cb, INV_MASS_A);
    const iA = lc(cb, INV_I_A);
    const mB = lc(cb, INV_MASS_B);
    const iB = lc(cb, INV_I_B);
    const nx = lc(cb, NORMAL_X);
    const ny = lc(cb, NORMAL_Y);
    const restitution = lc(cb, RESTITUTION);
    const biasRate = lc(cb, BIAS_RATE);
    // Received: an impact of this sub-step may push this bouncy contact (see above).
    const receives =
      !useBias &&
      restitution > 0 &&
      ld(markOf(marksPtr, a), MARK) + ld(markOf(marksPtr, b), MARK) > 0;
    let vAx = ld(sa, V_X);
    let vAy = ld(sa, V_Y);
    let wA = ld(sa, W);
    let vBx = ld(sb, V_X);
    let vBy = ld(sb, V_Y);
    let wB = ld(sb, W);
    const dpAx = ld(sa, DP_X);
    const dpAy = ld(sa, DP_Y);
    const dpBx = ld(sb, DP_X);
    const dpBy = ld(sb, DP_Y);
    // Lever arms to the common point of application (see Preparation.fill), as cross products
    // with n and t (see RN_A): the prepared ones plus the shift of the common point since the
    // arms were set (the step's start, or a circle pair's refresh).
    const shiftA = lc(cb, SHIFT_WEIGHT_A);
    const shiftB = lc(cb, SHIFT_WEIGHT_B);
    const eAx = dpAx - lc(cb, REF_DP_AX);
    const eAy = dpAy - lc(cb, REF_DP_AY);
    const eBx = dpBx - lc(cb, REF_DP_BX);
    const eBy = dpBy - lc(cb, REF_DP_BY);
    const shiftX = shiftA * eAx + shiftB * eBx;
    const shiftY = shiftA * eAy + shiftB * eBy;
    let sAx = shiftX - eAx;
    let sAy = shiftY - eAy;
    let sBx = shiftX - eBx;
    let sBy = shiftY - eBy;
    const dnA = sAx * ny - sAy * nx;
    const dnB = sBx * ny - sBy * nx;
    let bounced = false;
    // The normal in each body's rotated frame, so that each point's separation costs two dot
    // products: (q r) . n = r . (q^T n).
    const qAc = ld(sa, Q_C);
    const qAs = ld(sa, Q_S);
    const qBc = ld(sb, Q_C);
    const qBs = ld(sb, Q_S);
    const nAx = qAc * nx + qAs * ny;
    const nAy = qAc * ny - qAs * nx;
    const nBx = qBc * nx + qBs * ny;
    const nBy = qBc * ny - qBs * nx;
    const dpn = (dpBx - dpAx) * nx + (dpBy - dpAy) * ny;
    const pointCount = <i32>lc(cb, POINT_COUNT);

    // Two-point manifolds are solved as one block when both points are plain contacts, or both
    // bounce now; otherwise (one point waits for its impact, or K is ill-conditioned, see
    // Preparation.fill) the points go one after the other below.
    let firstSequential = 0;
    if (lc(cb, BLOCK) == 1) {
      const p1 = pointAt(cb, 0);
      const p2 = p1 + ((<usize>POINT_STRIDE) << 4);
      const separation1 =
        dpn +
        (lc(p1, R_BX) * nBx + lc(p1, R_BY) * nBy) -
        (lc(p1, R_AX) * nAx + lc(p1, R_AY) * nAy) +
        lc(p1, BASE_SEPARATION);
      const separation2 =
        dpn +
        (lc(p2, R_BX) * nBx + lc(p2, R_BY) * nBy) -
        (lc(p2, R_AX) * nAx + lc(p2, R_AY) * nAy) +
        lc(p2, BASE_SEPARATION);
      const n1A = lc(p1, RN_A) + dnA;
      const n1B = lc(p1, RN_B) + dnB;
      const n2A = lc(p2, RN_A) + dnA;
      const n2B = lc(p2, RN_B) + dnB;
      const k11 = lc(cb, BLOCK_K11);
      const k12 = lc(cb, BLOCK_K12);
      const k22 = lc(cb, BLOCK_K22);
      // Each point's target as in the sequential pass below: bias, and the softness gamma.
      let bias1: f64 = 0;
      let gamma1: f64 = 0;
      if (separation1 > 0) bias1 = separation1 * inverseH;
      else if (useBias) {
        bias1 = max<f64>(biasRate * separation1, -maxPushSpeed);
        gamma1 = (k11 * lc(cb, IMPULSE_SCALE)) / lc(cb, MASS_SCALE);
      }
      let bias2: f64 = 0;
      let gamma2: f64 = 0;
      if (separation2 > 0) bias2 = separation2 * inverseH;
      else if (useBias) {
        bias2 = max<f64>(biasRate * separation2, -maxPushSpeed);
        gamma2 = (k22 * lc(cb, IMPULSE_SCALE)) / lc(cb, MASS_SCALE);
      }
      const dvn = (vBx - vAx) * nx + (vBy - vAy) * ny;
      const vn1 = dvn + wB * n1B - wA * n1A;
      const vn2 = dvn + wB * n2B - wA * n2A;
      const accumulated1 = lc(p1, NORMAL_IMPULSE);
      const accumulated2 = lc(p2, NORMAL_IMPULSE);
      // The impact test of the sequential pass (see there), on the velocities before the pass.
      let isImpact1 = false;
      let isImpact2 = false;
      if (restitution > 0) {
        const impact1 = lc(p1, IMPACT);
        const impact2 = lc(p2, IMPACT);
        isImpact1 =
          accumulated1 == 0 &&
          (impact1 < 2 || impact1 == 3 || (impact1 == 4 && vn1 < -maxPushSpeed)) &&
          vn1 < -restitutionThreshold &&
          (impact1 == 1 || vn1 + bias1 < 0);
        isImpact2 =
          accumulated2 == 0 &&
          (impact2 < 2 || impact2 == 3 || (impact2 == 4 && vn2 < -maxPushSpeed)) &&
          vn2 < -restitutionThreshold &&
          (impact2 == 1 || vn2 + bias2 < 0);
      }
      if (
        receives &&
        !isImpact1 &&
        !isImpact2 &&
        (vn1 < -loadSpeed || vn2 < -loadSpeed) &&
        (lc(p1, IMPACT) != 4 || vn1 < -maxPushSpeed) &&
        (lc(p2, IMPACT) != 4 || vn2 < -maxPushSpeed)
      ) {
        firstSequential = 2;
      } else if (!isImpact1 && !isImpact2) {
        // Both points push: the mixed LCP  w = A x + q >= 0, x >= 0, x . w = 0  for the new
        // accumulated impulses x (Box2D v2's block solver, Catto's b2ContactSolver, enumerates
        // its four cases the same way). With the soft step, the sequential update of one point
        //   dx = -massScale (vn + bias) / K - impulseScale x_old
        // is, writing massScale = a2 / (1 + a2) and impulseScale = 1 / (1 + a2) (softness.ts),
        //   vn + K dx + bias + gamma x_new = 0  with  gamma = K / a2 = K impulseScale / massScale:
        // a rigid constraint plus a compliance gamma on the total impulse. Both points together:
        //   w = vn + K (x - x_old) + bias + Gamma x,  so  A = K + Gamma,  q = vn + bias - K x_old,
        // with Gamma = diag(gamma1, gamma2). With one point this is exactly the sequential update;
        // A is better conditioned than K, so the check on K in Preparation.fill covers it.
        const a11 = k11 + gamma1;
        const a22 = k22 + gamma2;
        const q1 = vn1 + bias1 - (k11 * accumulated1 + k12 * accumulated2);
        const q2 = vn2 + bias2 - (k12 * accumulated1 + k22 * accumulated2);
        // Case 4: both separate.
        let x1: f64 = -1;
        let x2: f64 = -1;
        // Case 1: both push, w = 0.
        const det = a11 * a22 - k12 * k12;
        const y1 = (k12 * q2 - a22 * q1) / det;
        const y2 = (k12 * q1 - a11 * q2) / det;
        if (y1 >= 0 && y2 >= 0) {
          x1 = y1;
          x2 = y2;
        } else {
          // Case 2: only point 1 pushes; point 2 must not approach.
          const z1 = -q1 / a11;
          if (z1 >= 0 && k12 * z1 + q2 >= 0) {
            x1 = z1;
            x2 = 0;
          } else {
            // Case 3: only point 2 pushes.
            const z2 = -q2 / a22;
            if (z2 >= 0 && k12 * z2 + q1 >= 0) {
              x1 = 0;
              x2 = z2;
            } else if (q1 >= 0 && q2 >= 0) {
              x1 = 0;
              x2 = 0;
            }
          }
        }
        // Rounding can leave no case satisfied (a nearly degenerate K): then sequential below.
        if (x1 >= 0 && x2 >= 0) {
          firstSequential = 2;
          if (restitution > 0) {
            if (lc(p1, IMPACT) == 1) sc(p1, IMPACT, 0);
            if (lc(p2, IMPACT) == 1) sc(p2, IMPACT, 0);
          }
          const dx1 = x1 - accumulated1;
          const dx2 = x2 - accumulated2;
          sc(p1, NORMAL_IMPULSE, x1);
          sc(p2, NORMAL_IMPULSE, x2);
          if (!useBias) {
            sc(p1, TOTAL_NORMAL_IMPULSE, lc(p1, TOTAL_NORMAL_IMPULSE) + x1);
            sc(p2, TOTAL_NORMAL_IMPULSE, lc(p2, TOTAL_NORMAL_IMPULSE) + x2);
          }
          if (dx1 > lc(p1, MAX_NORMAL_IMPULSE)) sc(p1, MAX_NORMAL_IMPULSE, dx1);
          if (dx2 > lc(p2, MAX_NORMAL_IMPULSE)) sc(p2, MAX_NORMAL_IMPULSE, dx2);
          const sum = dx1 + dx2;
          vAx -= mA * sum * nx;
          vAy -= mA * sum * ny;
          wA -= iA * (n1A * dx1 + n2A * dx2);
          vBx += mB * sum * nx;
          vBy += mB * sum * ny;
          wB += iB * (n1B * dx1 + n2B * dx2);
        }
      } else if (isImpact1 && isImpact2 && !useBias && separation1 <= 0 && separation2 <= 0) {
        // Both points hit in this sub-step: one collision, resolved at once at the moment of
        // contact (see the single-point case below), so neither point takes the other's share.
        // Back to the moment of contact: the mean of the two points' times, symmetric in them.
        const back = min<f64>(0.5 * (separation1 / vn1 + separation2 / vn2), 1 / inverseH);
        const tAx = dpAx - vAx * back;
        const tAy = dpAy - vAy * back;
        const tBx = dpBx - vBx * back;
        const tBy = dpBy - vBy * back;
        // The common point of application, where it was at that moment.
        const eAx = tAx - lc(cb, REF_DP_AX);
        const eAy = tAy - lc(cb, REF_DP_AY);
        const eBx = tBx - lc(cb, REF_DP_BX);
        const eBy = tBy - lc(cb, REF_DP_BY);
        const sx = shiftA * eAx + shiftB * eBx;
        const sy = shiftA * eAy + shiftB * eBy;
        const b1Ax = lc(p1, R_AX) + sx - eAx;
        const b1Ay = lc(p1, R_AY) + sy - eAy;
        const b1Bx = lc(p1, R_BX) + sx - eBx;
        const b1By = lc(p1, R_BY) + sy - eBy;
        const b2Ax = lc(p2, R_AX) + sx - eAx;
        const b2Ay = lc(p2, R_AY) + sy - eAy;
        const b2Bx = lc(p2, R_BX) + sx - eBx;
        const b2By = lc(p2, R_BY) + sy - eBy;
        // The approaches at that moment (see the single-point case below).
        const kA = markOf(marksPtr, a);
        const kB = markOf(marksPtr, b);
        const since = 0.5 - back * inverseH;
        const approach1 =
          (vBx - wB * b1By - (vAx - wA * b1Ay)) * nx +
          (vBy + wB * b1Bx - (vAy + wA * b1Ax)) * ny +
          kickApproach(kA, kB, b1Ax, b1Ay, b1Bx, b1By, nx, ny) * since;
        const approach2 =
          (vBx - wB * b2By - (vAx - wA * b2Ay)) * nx +
          (vBy + wB * b2Bx - (vAy + wA * b2Ax)) * ny +
          kickApproach(kA, kB, b2Ax, b2Ay, b2Bx, b2By, nx, ny) * since;
        const rn1A = b1Ax * ny - b1Ay * nx;
        const rn1B = b1Bx * ny - b1By * nx;
        const rn2A = b2Ax * ny - b2Ay * nx;
        const rn2B = b2Bx * ny - b2By * nx;
        const mAB = mA + mB;
        const b11 = mAB + iA * rn1A * rn1A + iB * rn1B * rn1B;
        const b22 = mAB + iA * rn2A * rn2A + iB * rn2B * rn2B;
        const b12 = mAB + iA * rn1A * rn2A + iB * rn1B * rn2B;
        // Newton's law per point as an LCP: w = B x + (1 + e) approach >= 0, x >= 0, x . w = 0:
        // each point leaves at e times its approach, or faster with no impulse of its own.
        const q1 = (1 + restitution) * approach1;
        const q2 = (1 + restitution) * approach2;
        let x1: f64 = -1;
        let x2: f64 = -1;
        const det = b11 * b22 - b12 * b12;
        const y1 = (b12 * q2 - b22 * q1) / det;
        const y2 = (b12 * q1 - b11 * q2) / det;
        if (y1 >= 0 && y2 >= 0) {
          x1 = y1;
          x2 = y2;
        } else if (-q1 / b11 >= 0 && (-b12 * q1) / b11 + q2 >= 0) {
          x1 = -q1 / b11;
          x2 = 0;
        } else if (-q2 / b22 >= 0 && (-b12 * q2) / b22 + q1 >= 0) {
          x1 = 0;
          x2 = -q2 / b22;
        } else if (q1 >= 0 && q2 >= 0) {
          x1 = 0;
          x2 = 0;
        }
        if (x1 >= 0 && x2 >= 0) {
          firstSequential = 2;
          sc(p1, NORMAL_IMPULSE, x1);
          sc(p2, NORMAL_IMPULSE, x2);
          sc(p1, TOTAL_NORMAL_IMPULSE, lc(p1, TOTAL_NORMAL_IMPULSE) + x1);
          sc(p2, TOTAL_NORMAL_IMPULSE, lc(p2, TOTAL_NORMAL_IMPULSE) + x2);
          sc(p1, RELATIVE_VELOCITY, approach1);
          sc(p2, RELATIVE_VELOCITY, approach2);
          sc(p1, IMPACT, 2);
          sc(p2, IMPACT, 2);
          if (x1 > lc(p1, MAX_NORMAL_IMPULSE)) sc(p1, MAX_NORMAL_IMPULSE, x1);
          if (x2 > lc(p2, MAX_NORMAL_IMPULSE)) sc(p2, MAX_NORMAL_IMPULSE, x2);
          const px = (x1 + x2) * nx;
          const py = (x1 + x2) * ny;
          const dvAx = -mA * px;
          const dvAy = -mA * py;
          const dwA = -iA * (rn1A * x1 + rn2A * x2);
          const dvBx = mB * px;
          const dvBy = mB * py;
          const dwB = iB * (rn1B * x1 + rn2B * x2);
          vAx += dvAx;
          vAy += dvAy;
          wA += dwA;
          vBx += dvBx;
          vBy += dvBy;
          wB += dwB;
          // And forward again with the new velocities: the exact path of the collision.
          if (a != 0) advancePose(sa, dvAx * back, dvAy * back, dwA * back);
          if (b != 0) advancePose(sb, dvBx * back, dvBy * back, dwB * back);
          bounced = true;
        }
      }
    }

    for (let j = firstSequential; j < pointCount; j++) {
      const p = pointAt(cb, j);
      // Current separation: the anchors moved with their bodies since the step began.
      const separation =
        dpn +
        (lc(p, R_BX) * nBx + lc(p, R_BY) * nBy) -
        (lc(p, R_AX) * nAx + lc(p, R_AY) * nAy) +
        lc(p, BASE_SEPARATION);
      const leverA = lc(p, RN_A) + dnA;
      const leverB = lc(p, RN_B) + dnB;
      let bias: f64 = 0;
      let massScale: f64 = 1;
      let impulseScale: f64 = 0;
      if (separation > 0) {
        // Speculative: allow closing exactly the gap within this sub-step, no more.
        bias = separation * inverseH;
      } else if (useBias) {
        bias = max<f64>(biasRate * separation, -maxPushSpeed);
        massScale = lc(cb, MASS_SCALE);
        impulseScale = lc(cb, IMPULSE_SCALE);
      }
      const vn = (vBx - vAx) * nx + (vBy - vAy) * ny + wB * leverB - wA * leverA;
      const accumulated = lc(p, NORMAL_IMPULSE);
      // Restitution (Newton's law) at the moment of impact. An impact is an approach faster than
      // the threshold on a point not already pushing, and not pressed unless it approaches faster
      // than a load presses (an impact that travelled to it, see impacts) (a resting contact is
      // always warm-started, so it never counts, and never jitters). The solve pass lets it go; the
      // relax pass, once the shapes touch, applies the whole collision impulse -(1 + e) m vn along
      // the normal of that instant, and moves both bodies on by their velocity change for the part
      // of the sub-step left after the moment of contact: the exact trajectory of two colliding
      // bodies, so momentum, angular momentum and (for e = 1) energy are kept. A bounce after all
      // the sub-steps (Box2D v3) comes after the normal of sliding particles has turned and after
      // gravity has changed the approach, and cannot bounce a particle twice in one step.
      if (restitution > 0) {
        const impactState = lc(p, IMPACT);
        if (
          accumulated == 0 &&
          (impactState < 2 || impactState == 3 || (impactState == 4 && vn < -maxPushSpeed)) &&
          vn < -restitutionThreshold &&
          (impactState == 1 || vn + bias < 0)
        ) {
          if (useBias || separation > 0) {
            // Not touching yet: the impact happens when the positions get there.
            sc(p, IMPACT, useBias ? 1 : 0);
            continue;
          }
          // Back to the moment of contact: the overlap divided by the approach speed ago.
          const back = min<f64>(separation / vn, 1 / inverseH);
          const tAx = dpAx - vAx * back;
          const tAy = dpAy - vAy * back;
          const tBx = dpBx - vBx * back;
          const tBy = dpBy - vBy * back;
          let bnx = nx;
          let bny = ny;
          let bAx: f64;
          let bAy: f64;
          let bBx: f64;
          let bBy: f64;
          const radiusA = lc(cb, RADIUS_A);
          const radiusB = lc(cb, RADIUS_B);
          if (radiusA > 0 && radiusB > 0) {
            // Two particles meet along the line through their centres at that moment.
            const cx = lc(cb, CENTER_DX) + tBx - tAx;
            const cy = lc(cb, CENTER_DY) + tBy - tAy;
            const length = Math.sqrt(cx * cx + cy * cy);
            if (length > 1e-12) {
              bnx = cx / length;
              bny = cy / length;
            }
            bAx = bnx * radiusA;
            bAy = bny * radiusA;
            bBx = -bnx * radiusB;
            bBy = -bny * radiusB;
          } else {
            const eAx = tAx - lc(cb, REF_DP_AX);
            const eAy = tAy - lc(cb, REF_DP_AY);
            const eBx = tBx - lc(cb, REF_DP_BX);
            const eBy = tBy - lc(cb, REF_DP_BY);
            const sx = shiftA * eAx + shiftB * eBx;
            const sy = shiftA * eAy + shiftB * eBy;
            bAx = lc(p, R_AX) + sx - eAx;
            bAy = lc(p, R_AY) + sy - eAy;
            bBx = lc(p, R_BX) + sx - eBx;
            bBy = lc(p, R_BY) + sy - eBy;
          }
          // The approach at that moment. The sub-step's velocity is its average (semi-implicit
          // Euler: positions move by h v); gravity and forces changed it by the integration's
          // kick k over the sub-step, so at the moment of contact, `back` before its end, the
          // approach was v + k (1/2 - back / h). Reversing that one (and moving on by the change
          // for `back`) is the exact bounce of the discrete parabola: a ball bouncing on the
          // ground keeps the integrator's energy (1/2 m (v + k/2)^2 - m g y at the sub-step's
          // end) at every bounce, where reversing the average gained or lost up to 2 g h / v of
          // it, depending on when in the sub-step the ball touched.
          const approach =
            (vBx - wB * bBy - (vAx - wA * bAy)) * bnx +
            (vBy + wB * bBx - (vAy + wA * bAx)) * bny +
            kickApproach(markOf(marksPtr, a), markOf(marksPtr, b), bAx, bAy, bBx, bBy, bnx, bny) *
              (0.5 - back * inverseH);
          const rnA = bAx * bny - bAy * bnx;
          const rnB = bBx * bny - bBy * bnx;
          const k = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
          const bounce: f64 = approach < 0 && k > 0 ? (-(1 + restitution) * approach) / k : 0;
          sc(p, NORMAL_IMPULSE, bounce);
          sc(p, TOTAL_NORMAL_IMPULSE, lc(p, TOTAL_NORMAL_IMPULSE) + bounce);
          sc(p, RELATIVE_VELOCITY, approach);
          sc(p, IMPACT, 2);
          if (bounce > lc(p, MAX_NORMAL_IMPULSE)) sc(p, MAX_NORMAL_IMPULSE, bounce);
          const px = bounce * bnx;
          const py = bounce * bny;
          const dvAx = -mA * px;
          const dvAy = -mA * py;
          const dwA = -iA * (bAx * py - bAy * px);
          const dvBx = mB * px;
          const dvBy = mB * py;
          const dwB = iB * (bBx * py - bBy * px);
          vAx += dvAx;
          vAy += dvAy;
          wA += dwA;
          vBx += dvBx;
          vBy += dvBy;
          wB += dwB;
          if (a != 0) advancePose(sa, dvAx * back, dvAy * back, dwA * back);
          if (b != 0) advancePose(sb, dvBx * back, dvBy * back, dwB * back);
          bounced = true;
          continue;
        }
        if (impactState == 1) sc(p, IMPACT, 0);
        // A pressed point that overlaps (impact state 4) is pushed out, not bounced, unless it
        // approaches faster than any push-out moves it: then an impact reached it.
        if (
          receives &&
          (impactState != 4 || vn < -maxPushSpeed) &&
          vn < -(accumulated > 0 ? loadSpeed : impactSpeed)
        ) {
          continue;
        }
      }
      const newImpulse = max<f64>(
        accumulated - lc(p, NORMAL_MASS) * massScale * (vn + bias) - impulseScale * accumulated,
        0,
      );
      const impulse = newImpulse - accumulated;
      sc(p, NORMAL_IMPULSE, newImpulse);
      // The relax pass ends the sub-step: the accumulated impulse is what acted in it.
      if (!useBias) sc(p, TOTAL_NORMAL_IMPULSE, lc(p, TOTAL_NORMAL_IMPULSE) + newImpulse);
      if (impulse > lc(p, MAX_NORMAL_IMPULSE)) sc(p, MAX_NORMAL_IMPULSE, impulse);
      vAx -= mA * impulse * nx;
      vAy -= mA * impulse * ny;
      wA -= iA * leverA * impulse;
      vBx += mB * impulse * nx;
      vBy += mB * impulse * ny;
      wB += iB * leverB * impulse;
    }

    if (bounced) {
      bounces++;
      if (a != 0) st(markOf(marksPtr, a), MARK, 1);
      if (b != 0) st(markOf(marksPtr, b), MARK, 1);
      // The bounce moved the bodies on: friction acts at the common point where it is now.
      const eAx = ld(sa, DP_X) - lc(cb, REF_DP_AX);
      const eAy = ld(sa, DP_Y) - lc(cb, REF_DP_AY);
      const eBx = ld(sb, DP_X) - lc(cb, REF_DP_BX);
      const eBy = ld(sb, DP_Y) - lc(cb, REF_DP_BY);
      const sx = shiftA * eAx + shiftB * eBx;
      const sy = shiftA * eAy + shiftB * eBy;
      sAx = sx - eAx;
      sAy = sy - eAy;
      sBx = sx - eBx;
      sBy = sy - eBy;
    }
    const dtA = -(sAx * nx + sAy * ny);
    const dtB = -(sBx * nx + sBy * ny);
    const friction = lc(cb, FRICTION);
    for (let j = 0; j < pointCount; j++) {
      const p = pointAt(cb, j);
      const leverA = dtA - (lc(p, R_AX) * nx + lc(p, R_AY) * ny);
      const leverB = dtB - (lc(p, R_BX) * nx + lc(p, R_BY) * ny);
      // Slip along t = (ny, -nx).
      const vt = (vBx - vAx) * ny - (vBy - vAy) * nx + wB * leverB - wA * leverA;
      const accumulated = lc(p, TANGENT_IMPULSE);
      const maxFriction = friction * lc(p, NORMAL_IMPULSE);
      let newImpulse = accumulated - lc(p, TANGENT_MASS) * vt;
      if (newImpulse > maxFriction) newImpulse = maxFriction;
      else if (newImpulse < -maxFriction) newImpulse = -maxFriction;
      const impulse = newImpulse - accumulated;
      sc(p, TANGENT_IMPULSE, newImpulse);
      if (!useBias) sc(p, TOTAL_TANGENT_IMPULSE, lc(p, TOTAL_TANGENT_IMPULSE) + newImpulse);
      vAx -= mA * impulse * ny;
      vAy += mA * impulse * nx;
      wA -= iA * leverA * impulse;
      vBx += mB * impulse * ny;
      vBy -= mB * impulse * nx;
      wB += iB * leverB * impulse;
    }

    if (a != 0) {
      st(sa, V_X, vAx);
      st(sa, V_Y, vAy);
      st(sa, W, wA);
    }
    if (b != 0) {
      st(sb, V_X, vBx);
      st(sb, V_Y, vBy);
      st(sb, W, wB);
    }
  }
  return bounces;
}

// Impact rounds: restitution over the whole impact, not contact by contact.
//
// An impact that meets a body already pressed (a ball resting on the floor, a light body under a
// heavy one) or held (a pinned rod) has to travel: the resting contact it presses through must
// bounce too, and a joint must take part in the impulse. The model is sequential impacts through
// the impact graph, as in Newton's cradle (Smith, Kaufman, Vouga, Tamstorf and Grinspun,
// "Reflections on Simultaneous Impact", SIGGRAPH 2012, name this family and the properties it
// keeps): after the relax pass of a sub-step in which something bounced, round after round, every
// touching contact that approaches faster than the impact speed is an impact of its own and leaves
// at e times the approach it received, with the masses of its two bodies (a two-point manifold as
// one block). Each such impact keeps momentum and angular momentum, keeps the energy at e = 1, and
// at e = 0 stops the approach as an inelastic collision does; a chain of them is the
// sequential-impact solution (a ball dropped on an equal ball resting on the floor rebounds to its
// drop height, the bottom one stays). Kept of the paper's properties: momentum, energy (e = 1:
// never gained; e < 1: lost), and breaking of contact along the chain; given up: symmetry of truly
// simultaneous impacts (the round visits contacts in the solver's order). Joints: a lone bounce of
// the relax pass and the joints are solved together, a few Gauss-Seidel iterations, the impact
// towards its target (-e times its approach), so that a disc hitting a pinned rod sees the rod's
// pinned effective mass. Not the rounds' impacts, nor several bounces at once: impacts of one chain
// solved together towards fixed targets make energy. Resting contacts that no impact reaches are
// never visited by an impact (they approach slower than the impact speed), so stacks stay at rest
// and sleep; steps without a bounce run no round at all.

/**
 * One pass of the impact rounds over the constraints at positions `from` to `to` of the visiting
 * order (see the note above); returns the number of impacts it started. `IMPACT_ROUND` closes the
 * last round's impacts and starts a new one: each touching point of a body an impact reached
 * (`marks`) approaching faster than `impactSpeed` (a loaded point: `loadSpeed`; a pressed,
 * overlapping point: `pushSpeed`, the most a push-out moves it) gets -(1 + e)
 * times its approach, with its bodies' masses. `IMPACT_CONTINUE`
 * moves the open impacts on towards their targets (between joint passes); `IMPACT_OPEN` opens the
 * bounces of the relax pass for that; `IMPACT_CLOSE` closes all; `IMPACT_COUNT` returns the
 * relax pass's bounces and changes nothing. The three speeds are the arguments at `args`
 * (A_IMPACT_SPEED, A_LOAD_SPEED, A_MAX_PUSH_SPEED: kernel-arguments.ts).
 */
export function impacts(
  cPtr: usize,
  bodiesPtr: usize,
  orderPtr: usize,
  sPtr: usize,
  count: i32,
  args: usize,
  marksPtr: usize,
  mode: i32,
): i32 {
  const impactSpeed = ld(args, A_IMPACT_SPEED);
  const loadSpeed = ld(args, A_LOAD_SPEED);
  const pushSpeed = ld(args, A_MAX_PUSH_SPEED);
  let started: i32 = 0;
  for (let n = 0; n < count; n++) {
    const i = load<i32>(orderPtr + ((<usize>n) << 2));
    const cb = constraintAt(cPtr, i);
    const pointCount = <i32>lc(cb, POINT_COUNT);
    if (mode == IMPACT_COUNT) {
      for (let j = 0; j < pointCount; j++) {
        if (lc(pointAt(cb, j), IMPACT) == 2) started++;
      }
      continue;
    }
    if (mode == IMPACT_OPEN || mode == IMPACT_CLOSE || mode == IMPACT_ROUND) {
      const from2: f64 = mode == IMPACT_OPEN ? 2 : 5;
      const to2: f64 = mode == IMPACT_OPEN ? 5 : 6;
      for (let j = 0; j < pointCount; j++) {
        const p = pointAt(cb, j);
        if (lc(p, IMPACT) == from2) {
          sc(p, IMPACT, to2);
          if (mode == IMPACT_OPEN) started++;
        }
      }
      if (mode == IMPACT_OPEN) continue;
    }
    const a = load<i32>(bodiesPtr + ((<usize>i) << 3));
    const b = load<i32>(bodiesPtr + ((<usize>i) << 3), 4);
    const markA = markOf(marksPtr, a);
    const markB = markOf(marksPtr, b);
    if (mode == IMPACT_CLOSE) {
      store<f64>(markA, 0);
      store<f64>(markB, 0);
      continue;
    }
    if (mode == IMPACT_ROUND && load<f64>(markA) + load<f64>(markB) == 0) continue;
    const sa = sPtr + ((<usize>a) << 3);
    const sb = sPtr + ((<usize>b) << 3);
    const mA = lc(cb, INV_MASS_A);
    const iA = lc(cb, INV_I_A);
    const mB = lc(cb, INV_MASS_B);
    const iB = lc(cb, INV_I_B);
    const restitution = lc(cb, RESTITUTION);
    let vAx = ld(sa, V_X);
    let vAy = ld(sa, V_Y);
    let wA = ld(sa, W);
    let vBx = ld(sb, V_X);
    let vBy = ld(sb, V_Y);
    let wB = ld(sb, W);
    const dpAx = ld(sa, DP_X);
    const dpAy = ld(sa, DP_Y);
    const dpBx = ld(sb, DP_X);
    const dpBy = ld(sb, DP_Y);
    // Two particles meet along the line through their centres where they are now (a bounce of
    // this sub-step moved them on since the normal was set), with no lever: the impulses act on
    // one line (momentum and angular momentum kept) through both centres (no spin), as the
    // relax pass's bounce does at the moment of contact (see solve).
    const radiusA = lc(cb, RADIUS_A);
    const radiusB = lc(cb, RADIUS_B);
    let nx = lc(cb, NORMAL_X);
    let ny = lc(cb, NORMAL_Y);
    let gap: f64 = 0;
    const particles = radiusA > 0 && radiusB > 0;
    if (particles) {
      const cx = lc(cb, CENTER_DX) + dpBx - dpAx;
      const cy = lc(cb, CENTER_DY) + dpBy - dpAy;
      const length = Math.sqrt(cx * cx + cy * cy);
      if (length > 1e-12) {
        nx = cx / length;
        ny = cy / length;
      }
      gap = length - radiusA - radiusB;
    }
    const shiftA = lc(cb, SHIFT_WEIGHT_A);
    const shiftB = lc(cb, SHIFT_WEIGHT_B);
    const eAx = dpAx - lc(cb, REF_DP_AX);
    const eAy = dpAy - lc(cb, REF_DP_AY);
    const eBx = dpBx - lc(cb, REF_DP_BX);
    const eBy = dpBy - lc(cb, REF_DP_BY);
    const shiftX = shiftA * eAx + shiftB * eBx;
    const shiftY = shiftA * eAy + shiftB * eBy;
    const dnA: f64 = particles ? 0 : (shiftX - eAx) * ny - (shiftY - eAy) * nx;
    const dnB: f64 = particles ? 0 : (shiftX - eBx) * ny - (shiftY - eBy) * nx;
    const qAc = ld(sa, Q_C);
    const qAs = ld(sa, Q_S);
    const qBc = ld(sb, Q_C);
    const qBs = ld(sb, Q_S);
    const nAx = qAc * nx + qAs * ny;
    const nAy = qAc * ny - qAs * nx;
    const nBx = qBc * nx + qBs * ny;
    const nBy = qBc * ny - qBs * nx;
    const dpn = (dpBx - dpAx) * nx + (dpBy - dpAy) * ny;
    let firstSequential = 0;
    if (mode == IMPACT_ROUND && lc(cb, BLOCK) == 1) {
      const p1 = pointAt(cb, 0);
      const p2 = p1 + ((<usize>POINT_STRIDE) << 4);
      const separation1 =
        dpn +
        (lc(p1, R_BX) * nBx + lc(p1, R_BY) * nBy) -
        (lc(p1, R_AX) * nAx + lc(p1, R_AY) * nAy) +
        lc(p1, BASE_SEPARATION);
      const separation2 =
        dpn +
        (lc(p2, R_BX) * nBx + lc(p2, R_BY) * nBy) -
        (lc(p2, R_AX) * nAx + lc(p2, R_AY) * nAy) +
        lc(p2, BASE_SEPARATION);
      const n1A = lc(p1, RN_A) + dnA;
      const n1B = lc(p1, RN_B) + dnB;
      const n2A = lc(p2, RN_A) + dnA;
      const n2B = lc(p2, RN_B) + dnB;
      const dvn = (vBx - vAx) * nx + (vBy - vAy) * ny;
      const vn1 = dvn + wB * n1B - wA * n1A;
      const vn2 = dvn + wB * n2B - wA * n2A;
      const speed1: f64 =
        lc(p1, NORMAL_IMPULSE) > 0 && lc(p1, IMPACT) != 2 ? loadSpeed : impactSpeed;
      const speed2: f64 =
        lc(p2, NORMAL_IMPULSE) > 0 && lc(p2, IMPACT) != 2 ? loadSpeed : impactSpeed;
      if (
        separation1 < LINEAR_SLOP &&
        separation2 < LINEAR_SLOP &&
        vn1 < -speed1 &&
        vn2 < -speed2 &&
        (lc(p1, IMPACT) != 4 || vn1 < -pushSpeed) &&
        (lc(p2, IMPACT) != 4 || vn2 < -pushSpeed)
      ) {
        const mAB = mA + mB;
        const k11 = mAB + iA * n1A * n1A + iB * n1B * n1B;
        const k12 = mAB + iA * n1A * n2A + iB * n1B * n2B;
        const k22 = mAB + iA * n2A * n2A + iB * n2B * n2B;
        // The approaches at the sub-step's end, where the round's impacts happen: the sub-step's
        // average plus half its kick (see the relax pass's bounce in solve).
        const u1 = vn1 + 0.5 * kickNormal(markA, markB, nx, ny, n1A, n1B);
        const u2 = vn2 + 0.5 * kickNormal(markA, markB, nx, ny, n2A, n2B);
        const q1 = (1 + restitution) * u1;
        const q2 = (1 + restitution) * u2;
        let x1: f64 = -1;
        let x2: f64 = -1;
        const det = k11 * k22 - k12 * k12;
        const y1 = (k12 * q2 - k22 * q1) / det;
        const y2 = (k12 * q1 - k11 * q2) / det;
        if (y1 >= 0 && y2 >= 0) {
          x1 = y1;
          x2 = y2;
        } else if (-q1 / k11 >= 0 && (-k12 * q1) / k11 + q2 >= 0) {
          x1 = -q1 / k11;
          x2 = 0;
        } else if (-q2 / k22 >= 0 && (-k12 * q2) / k22 + q1 >= 0) {
          x1 = 0;
          x2 = -q2 / k22;
        }
        if (x1 >= 0 && x2 >= 0) {
          firstSequential = 2;
          started++;
          sc(p1, NORMAL_IMPULSE, lc(p1, NORMAL_IMPULSE) + x1);
          sc(p2, NORMAL_IMPULSE, lc(p2, NORMAL_IMPULSE) + x2);
          sc(p1, TOTAL_NORMAL_IMPULSE, lc(p1, TOTAL_NORMAL_IMPULSE) + x1);
          sc(p2, TOTAL_NORMAL_IMPULSE, lc(p2, TOTAL_NORMAL_IMPULSE) + x2);
          if (x1 > lc(p1, MAX_NORMAL_IMPULSE)) sc(p1, MAX_NORMAL_IMPULSE, x1);
          if (x2 > lc(p2, MAX_NORMAL_IMPULSE)) sc(p2, MAX_NORMAL_IMPULSE, x2);
          sc(p1, RELATIVE_VELOCITY, u1);
          sc(p2, RELATIVE_VELOCITY, u2);
          sc(p1, IMPACT, 5);
          sc(p2, IMPACT, 5);
          const sum = x1 + x2;
          vAx -= mA * sum * nx;
          vAy -= mA * sum * ny;
          wA -= iA * (n1A * x1 + n2A * x2);
          vBx += mB * sum * nx;
          vBy += mB * sum * ny;
          wB += iB * (n1B * x1 + n2B * x2);
        }
      }
    }
    let changed = firstSequential == 2;
    for (let j = firstSequential; j < pointCount; j++) {
      const p = pointAt(cb, j);
      const impact = lc(p, IMPACT);
      if (mode == IMPACT_CONTINUE ? impact != 5 : impact == 5) continue;
      const leverA = lc(p, RN_A) + dnA;
      const leverB = lc(p, RN_B) + dnB;
      const vn = (vBx - vAx) * nx + (vBy - vAy) * ny + wB * leverB - wA * leverA;
      // A pressed, overlapping point (4) only when faster than a push-out (see solve).
      if (mode != IMPACT_CONTINUE && impact == 4 && vn >= -pushSpeed) continue;
      // The approach at the sub-step's end (see above).
      const u = vn + 0.5 * kickNormal(markA, markB, nx, ny, leverA, leverB);
      const accumulated = lc(p, NORMAL_IMPULSE);
      const k = mA + mB + iA * leverA * leverA + iB * leverB * leverB;
      if (!(k > 0)) continue;
      let impulse: f64;
      if (mode == IMPACT_CONTINUE) {
        const target = -restitution * lc(p, RELATIVE_VELOCITY);
        impulse = max<f64>((target - u) / k, -accumulated);
      } else {
        if (vn >= -(accumulated > 0 && impact != 2 ? loadSpeed : impactSpeed)) continue;
        const separation = particles
          ? gap
          : dpn +
            (lc(p, R_BX) * nBx + lc(p, R_BY) * nBy) -
            (lc(p, R_AX) * nAx + lc(p, R_AY) * nAy) +
            lc(p, BASE_SEPARATION);
        if (separation >= LINEAR_SLOP) continue;
        impulse = (-(1 + restitution) * u) / k;
        started++;
        sc(p, RELATIVE_VELOCITY, u);
        sc(p, IMPACT, 5);
        if (impulse > lc(p, MAX_NORMAL_IMPULSE)) sc(p, MAX_NORMAL_IMPULSE, impulse);
      }
      sc(p, NORMAL_IMPULSE, accumulated + impulse);
      sc(p, TOTAL_NORMAL_IMPULSE, lc(p, TOTAL_NORMAL_IMPULSE) + impulse);
      vAx -= mA * impulse * nx;
      vAy -= mA * impulse * ny;
      wA -= iA * leverA * impulse;
      vBx += mB * impulse * nx;
      vBy += mB * impulse * ny;
      wB += iB * leverB * impulse;
      changed = true;
    }
    if (!changed) continue;
    if (a != 0) {
      st(sa, V_X, vAx);
      st(sa, V_Y, vAy);
      st(sa, W, wA);
      store<f64>(markA, 1);
    }
    if (b != 0) {
      st(sb, V_X, vBx);
      st(sb, V_Y, vBy);
      st(sb, W, wB);
      store<f64>(markB, 1);
    }
  }
  return started;
}

/** Counts of the last prepare: circle pairs listed, heavy-on-light constraints. */
export let circlePairCount: i32 = 0;
export let heavyOnLightCount: i32 = 0;

// The per-contact bodies of the preparation, as static members so that AssemblyScript's `@inline`
// decorates a member, where TypeScript's grammar (and so Prettier) allows a decorator.
// eslint-disable-next-line @typescript-eslint/no-extraneous-class
class Preparation {
  /**
   * Whether contact `slot` becomes constraint `i` (it has points and a moving body); if so,
   * records the constraint's slot and state offsets and counts it as a circle pair (listing it)
   * or a heavy-on-light pair.
   */
  @inline
  static classify(
    slot: i32,
    i: i32,
    dataPtr: usize,
    contactBodiesPtr: usize,
    tablePtr: usize,
    bodiesPtr: usize,
    slotsPtr: usize,
    circlePairsPtr: usize,
  ): bool {
    const m = dataPtr + ((<usize>(slot * CONTACT_STRIDE)) << 3);
    if (ld(m, C_POINT_COUNT) == 0) return false;
    const tA =
      tablePtr +
      ((<usize>(load<i32>(contactBodiesPtr + ((<usize>slot) << 3)) * TABLE_STRIDE)) << 3);
    const tB =
      tablePtr +
      ((<usize>(load<i32>(contactBodiesPtr + ((<usize>slot) << 3), 4) * TABLE_STRIDE)) << 3);
    const mA = ld(tA, TABLE_INV_MASS);
    const mB = ld(tB, TABLE_INV_MASS);
    if (mA == 0 && mB == 0) return false;
    store<i32>(slotsPtr + ((<usize>i) << 2), slot);
    // Sleeping or static bodies are solved as immovable (slot 0, no inverse mass); awake
    // kinematic ones too.
    store<i32>(bodiesPtr + ((<usize>i) << 3), <i32>ld(tA, TABLE_SLOT) * STATE_STRIDE);
    store<i32>(bodiesPtr + ((<usize>i) << 3), <i32>ld(tB, TABLE_SLOT) * STATE_STRIDE, 4);
    if (mA != 0 && mB != 0 && (mA > mB ? mA / mB : mB / mA) > 2) heavyOnLightCount++;
    if (ld(m, C_RADIUS_A) > 0 && ld(m, C_RADIUS_B) > 0) {
      store<i32>(circlePairsPtr + ((<usize>circlePairCount) << 2), i);
      circlePairCount++;
    }
    return true;
  }

  /** Fills constraint `i` from contact `slot` (classified before); a call, not inlined, to keep the module small. */
  static fill(
    slot: i32,
    i: i32,
    dataPtr: usize,
    contactBodiesPtr: usize,
    tablePtr: usize,
    sPtr: usize,
    cPtr: usize,
    bodiesPtr: usize,
    contactBiasRate: f64,
    contactMassScale: f64,
    contactImpulseScale: f64,
    staticBiasRate: f64,
    staticMassScale: f64,
    staticImpulseScale: f64,
    contactHertz: f64,
    zeta: f64,
    h: f64,
    dt: f64,
  ): void {
    const m = dataPtr + ((<usize>(slot * CONTACT_STRIDE)) << 3);
    // Touching: the manifold has a point (Contact.touching).
    const pointCount = ld(m, C_POINT_COUNT);
    const tA =
      tablePtr +
      ((<usize>(load<i32>(contactBodiesPtr + ((<usize>slot) << 3)) * TABLE_STRIDE)) << 3);
    const tB =
      tablePtr +
      ((<usize>(load<i32>(contactBodiesPtr + ((<usize>slot) << 3), 4) * TABLE_STRIDE)) << 3);
    const mA = ld(tA, TABLE_INV_MASS);
    const mB = ld(tB, TABLE_INV_MASS);
    const iA = ld(tA, TABLE_INV_I);
    const iB = ld(tB, TABLE_INV_I);
    const cb = constraintAt(cPtr, i);
    const a = load<i32>(bodiesPtr + ((<usize>i) << 3));
    const b = load<i32>(bodiesPtr + ((<usize>i) << 3), 4);
    // Stiffer against immovable bodies: nothing on the other side gives way.
    const immovable = mA == 0 || mB == 0;
    const nx = ld(m, C_NORMAL_X);
    const ny = ld(m, C_NORMAL_Y);
    sc(cb, NORMAL_X, nx);
    sc(cb, NORMAL_Y, ny);
    sc(cb, FRICTION, ld(m, C_FRICTION));
    sc(cb, RESTITUTION, ld(m, C_RESTITUTION));
    sc(cb, INV_MASS_A, mA);
    sc(cb, INV_I_A, iA);
    sc(cb, INV_MASS_B, mB);
    sc(cb, INV_I_B, iB);
    sc(cb, BIAS_RATE, immovable ? staticBiasRate : contactBiasRate);
    sc(cb, MASS_SCALE, immovable ? staticMassScale : contactMassScale);
    sc(cb, IMPULSE_SCALE, immovable ? staticImpulseScale : contactImpulseScale);
    // Heavy on light: the soft contact's stiffness follows the heavier body's mass (softness.ts).
    if (!immovable) {
      const ratio = mA > mB ? mA / mB : mB / mA;
      if (ratio > 2) {
        // Softness.setForMassRatio, then Softness.set (softness.ts).
        const hertz = Math.min(contactHertz * Math.sqrt(ratio), 0.25 / h);
        const omega = 2 * Math.PI * hertz;
        const a1 = 2 * zeta + h * omega;
        if (hertz == 0 || a1 == 0) {
          sc(cb, BIAS_RATE, 0);
          sc(cb, MASS_SCALE, 1);
          sc(cb, IMPULSE_SCALE, 0);
        } else {
          const a2 = h * omega * a1;
          const a3 = 1 / (1 + a2);
          sc(cb, BIAS_RATE, omega / a1);
          sc(cb, MASS_SCALE, a2 * a3);
          sc(cb, IMPULSE_SCALE, a3);
        }
      }
    }
    sc(cb, POINT_COUNT, pointCount);
    const pressed = ld(m, C_BOUNCING_STEPS) >= PRESSED_AFTER_BOUNCING_STEPS;
    const radiusA = ld(m, C_RADIUS_A);
    const radiusB = ld(m, C_RADIUS_B);
    const centerAX = ld(tA, TABLE_CENTER_X);
    const centerAY = ld(tA, TABLE_CENTER_Y);
    const centerBX = ld(tB, TABLE_CENTER_X);
    const centerBY = ld(tB, TABLE_CENTER_Y);
    sc(cb, RADIUS_A, radiusA);
    sc(cb, RADIUS_B, radiusB);
    sc(cb, CENTER_DX, centerBX - centerAX);
    sc(cb, CENTER_DY, centerBY - centerAY);
    sc(cb, REF_DP_AX, 0);
    sc(cb, REF_DP_AY, 0);
    sc(cb, REF_DP_BX, 0);
    sc(cb, REF_DP_BY, 0);
    if (radiusB > 0 && radiusA == 0) {
      // On the circle's line of centres, so the circle gets no torque from a normal impulse.
      sc(cb, SHIFT_WEIGHT_A, 0);
      sc(cb, SHIFT_WEIGHT_B, 1);
    } else {
      const total = mA + mB;
      sc(cb, SHIFT_WEIGHT_A, mA / total);
      sc(cb, SHIFT_WEIGHT_B, mB / total);
    }
    const tx = ny;
    const ty = -nx;
    const sa = sPtr + ((<usize>a) << 3);
    const sb = sPtr + ((<usize>b) << 3);
    const vAx = ld(sa, V_X);
    const vAy = ld(sa, V_Y);
    const wA = ld(sa, W);
    const vBx = ld(sb, V_X);
    const vBy = ld(sb, V_Y);
    const wB = ld(sb, W);
    const count = <i32>pointCount;
    for (let j: i32 = 0; j < count; j++) {
      const mp = m + ((<usize>(C_POINTS + j * C_POINT_STRIDE)) << 3);
      const p = pointAt(cb, j);
      const x = ld(mp, C_X);
      const y = ld(mp, C_Y);
      const rAx = x - centerAX;
      const rAy = y - centerAY;
      const rBx = x - centerBX;
      const rBy = y - centerBY;
      sc(p, R_AX, rAx);
      sc(p, R_AY, rAy);
      sc(p, R_BX, rBx);
      // Separation later = baseline + (change of the anchors' world positions) . n.
      sc(p, R_BY, rBy);
      sc(p, BASE_SEPARATION, ld(mp, C_SEPARATION) - ((rBx - rAx) * nx + (rBy - rAy) * ny));
      sc(p, NORMAL_IMPULSE, ld(mp, C_NORMAL_IMPULSE));
      sc(p, TANGENT_IMPULSE, ld(mp, C_TANGENT_IMPULSE));
      sc(p, MAX_NORMAL_IMPULSE, 0);
      sc(p, TOTAL_NORMAL_IMPULSE, 0);
      sc(p, TOTAL_TANGENT_IMPULSE, 0);
      sc(p, IMPACT, 0);
      const rnA = rAx * ny - rAy * nx;
      const rnB = rBx * ny - rBy * nx;
      sc(p, RN_A, rnA);
      sc(p, RN_B, rnB);
      const kNormal = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
      sc(p, NORMAL_MASS, kNormal > 0 ? 1 / kNormal : 0);
      const rtA = rAx * ty - rAy * tx;
      const rtB = rBx * ty - rBy * tx;
      const kTangent = mA + mB + iA * rtA * rtA + iB * rtB * rtB;
      sc(p, TANGENT_MASS, kTangent > 0 ? 1 / kTangent : 0);
      // Normal approach velocity before the step, for restitution; replaced by the velocity at the
      // first push of the step (see solve).
      const dvx = vBx - wB * rBy - (vAx - wA * rAy);
      const dvy = vBy + wB * rBx - (vAy + wA * rAx);
      const approach = dvx * nx + dvy * ny;
      sc(p, RELATIVE_VELOCITY, approach);
      // A pressed point (see PRESSED_AFTER_BOUNCING_STEPS) overlapping deeper than this step's
      // approach explains is a contact for this step, not an impact.
      const separation = ld(mp, C_SEPARATION);
      if (pressed && separation < Math.min(approach * dt, 0) - LINEAR_SLOP) sc(p, IMPACT, 4);
    }
    sc(cb, BLOCK, 0);
    if (count == 2) {
      // The normal block K (the inverse mass seen by the two points together): K_jj = 1 / normal
      // mass, K_12 couples them through the bodies' rotation.
      const p1 = pointAt(cb, 0);
      const p2 = p1 + ((<usize>POINT_STRIDE) << 4);
      const rn1A = lc(p1, R_AX) * ny - lc(p1, R_AY) * nx;
      const rn1B = lc(p1, R_BX) * ny - lc(p1, R_BY) * nx;
      const rn2A = lc(p2, R_AX) * ny - lc(p2, R_AY) * nx;
      const rn2B = lc(p2, R_BX) * ny - lc(p2, R_BY) * nx;
      const k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
      const k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
      const k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;
      sc(cb, BLOCK_K11, k11);
      sc(cb, BLOCK_K12, k12);
      sc(cb, BLOCK_K22, k22);
      // Condition number check (Box2D v2's b2ContactSolver, k_maxConditionNumber): two points
      // almost on top of each other make K nearly singular, and its inverse would trade huge
      // opposite impulses; those manifolds stay sequential, which is well-defined for any K.
      const kMax = Math.max(k11, k22);
      if (kMax > 0 && kMax * kMax < MAX_CONDITION_NUMBER * (k11 * k22 - k12 * k12)) {
        sc(cb, BLOCK, 1);
      }
    }
  }
}

/**
 * Makes a constraint of every touching contact (slots 0..`contactCount` - 1 of the contact data)
 * with something that can move, computing effective masses, the anchors relative to each centre
 * of mass and the separation baseline from the contact's slot. Reads the bodies from the body
 * table (body-state.ts) through the slot's world indices, and velocities from the states (already
 * loaded with the bodies' velocities of this step's start) for restitution. Visits the contacts in
 * slot order, so the contact data streams through memory; the sub-step passes use the order.
 * Returns the number of constraints.
 */
export function prepare(
  dataPtr: usize,
  contactBodiesPtr: usize,
  tablePtr: usize,
  sPtr: usize,
  cPtr: usize,
  bodiesPtr: usize,
  slotsPtr: usize,
  circlePairsPtr: usize,
  contactCount: i32,
  contactBiasRate: f64,
  contactMassScale: f64,
  contactImpulseScale: f64,
  staticBiasRate: f64,
  staticMassScale: f64,
  staticImpulseScale: f64,
  contactHertz: f64,
  zeta: f64,
  h: f64,
  dt: f64,
): i32 {
  circlePairCount = 0;
  heavyOnLightCount = 0;
  let i: i32 = 0;
  for (let slot: i32 = 0; slot < contactCount; slot++) {
    if (
      !Preparation.classify(
        slot,
        i,
        dataPtr,
        contactBodiesPtr,
        tablePtr,
        bodiesPtr,
        slotsPtr,
        circlePairsPtr,
      )
    ) {
      continue;
    }
    Preparation.fill(
      slot,
      i,
      dataPtr,
      contactBodiesPtr,
      tablePtr,
      sPtr,
      cPtr,
      bodiesPtr,
      contactBiasRate,
      contactMassScale,
      contactImpulseScale,
      staticBiasRate,
      staticMassScale,
      staticImpulseScale,
      contactHertz,
      zeta,
      h,
      dt,
    );
    i++;
  }
  return i;
}

/**
 * The first half of {@link prepare}: which contacts become constraints, their slots, state
 * offsets and counts, without filling them; {@link prepareListed} fills them later (a batch of
 * islands at a time, solver-batches.ts). Returns the number of constraints.
 */
export function classify(
  dataPtr: usize,
  contactBodiesPtr: usize,
  tablePtr: usize,
  bodiesPtr: usize,
  slotsPtr: usize,
  circlePairsPtr: usize,
  contactCount: i32,
): i32 {
  circlePairCount = 0;
  heavyOnLightCount = 0;
  let i: i32 = 0;
  for (let slot: i32 = 0; slot < contactCount; slot++) {
    if (
      Preparation.classify(
        slot,
        i,
        dataPtr,
        contactBodiesPtr,
        tablePtr,
        bodiesPtr,
        slotsPtr,
        circlePairsPtr,
      )
    ) {
      i++;
    }
  }
  return i;
}

/**
 * The second half of {@link prepare} for the `count` constraints listed from `orderPtr`; the
 * softness, h and dt are the arguments at `args` (kernel-arguments.ts).
 */
export function prepareListed(
  dataPtr: usize,
  contactBodiesPtr: usize,
  tablePtr: usize,
  sPtr: usize,
  cPtr: usize,
  bodiesPtr: usize,
  slotsPtr: usize,
  orderPtr: usize,
  count: i32,
  args: usize,
): void {
  const contactBiasRate = ld(args, A_CONTACT_BIAS_RATE);
  const contactMassScale = ld(args, A_CONTACT_MASS_SCALE);
  const contactImpulseScale = ld(args, A_CONTACT_IMPULSE_SCALE);
  const staticBiasRate = ld(args, A_STATIC_BIAS_RATE);
  const staticMassScale = ld(args, A_STATIC_MASS_SCALE);
  const staticImpulseScale = ld(args, A_STATIC_IMPULSE_SCALE);
  const contactHertz = ld(args, A_CONTACT_HERTZ);
  const zeta = ld(args, A_CONTACT_ZETA);
  const h = ld(args, A_H);
  const dt = ld(args, A_DT);
  for (let n: i32 = 0; n < count; n++) {
    const i = load<i32>(orderPtr + ((<usize>n) << 2));
    Preparation.fill(
      load<i32>(slotsPtr + ((<usize>i) << 2)),
      i,
      dataPtr,
      contactBodiesPtr,
      tablePtr,
      sPtr,
      cPtr,
      bodiesPtr,
      contactBiasRate,
      contactMassScale,
      contactImpulseScale,
      staticBiasRate,
      staticMassScale,
      staticImpulseScale,
      contactHertz,
      zeta,
      h,
      dt,
    );
  }
}

/**
 * Copies the accumulated impulses back to the contacts' slots for warm starting, and the impulses
 * the step delivered (sum over the sub-steps, plus restitution) for events.
 */
export function storeImpulses(
  cPtr: usize,
  slotsPtr: usize,
  dataPtr: usize,
  orderPtr: usize,
  count: i32,
): void {
  for (let n: i32 = 0; n < count; n++) {
    const i = load<i32>(orderPtr + ((<usize>n) << 2));
    const cb = constraintAt(cPtr, i);
    const m = dataPtr + ((<usize>(load<i32>(slotsPtr + ((<usize>i) << 2)) * CONTACT_STRIDE)) << 3);
    const pointCount = <i32>lc(cb, POINT_COUNT);
    let bounced = 0;
    for (let j: i32 = 0; j < pointCount; j++) {
      const p = pointAt(cb, j);
      const mp = m + ((<usize>(C_POINTS + j * C_POINT_STRIDE)) << 3);
      const impact = lc(p, IMPACT);
      if (impact == 2 || impact == 3) bounced = 1;
      st(mp, C_NORMAL_IMPULSE, impact == 2 || impact == 6 ? 0 : lc(p, NORMAL_IMPULSE));
      st(mp, C_TANGENT_IMPULSE, lc(p, TANGENT_IMPULSE));
      st(mp, C_MAX_NORMAL_IMPULSE, lc(p, MAX_NORMAL_IMPULSE));
      st(mp, C_RELATIVE_VELOCITY, lc(p, RELATIVE_VELOCITY));
      st(mp, C_STEP_NORMAL_IMPULSE, lc(p, TOTAL_NORMAL_IMPULSE));
      st(mp, C_STEP_TANGENT_IMPULSE, lc(p, TOTAL_TANGENT_IMPULSE));
    }
    st(m, C_BOUNCING_STEPS, bounced == 1 ? ld(m, C_BOUNCING_STEPS) + 1 : 0);
  }
}
