// The heavy-on-light sweep of each sub-step (shock propagation: Guendelman, Bridson and Fedkiw,
// "Nonconvex rigid bodies with stacking", SIGGRAPH 2003, section 7; Erleben's thesis, 2004): the
// one source, built into the kernel with the contact passes (contact-kernel.ts). Why and which
// contacts: src/dynamics/contact-solver.ts (ShockPropagation, which lists them once a step in the
// SHOCK_SWEEP region, shock-sweep-layout.ts).
import {
  BASE_SEPARATION,
  DP_X,
  DP_Y,
  FRICTION,
  INV_I_A,
  INV_I_B,
  INV_MASS_A,
  INV_MASS_B,
  KICK_VX,
  KICK_VY,
  KICK_W,
  NORMAL_IMPULSE,
  NORMAL_X,
  NORMAL_Y,
  POINT_COUNT,
  Q_C,
  Q_S,
  RELATIVE_VELOCITY,
  R_AX,
  R_AY,
  R_BX,
  R_BY,
  SWEEP_CONSTRAINT,
  SWEEP_LOWER_IS_A,
  SWEEP_RESTITUTION,
  SWEEP_SLIP,
  SWEEP_STRIDE,
  TANGENT_IMPULSE,
  V_X,
  V_Y,
  W,
} from './contact-layout';
import { constraintAt, lc, markOf, pointAt, sc } from './constraint-access';
import { ld, st } from './load-store';

/**
 * Sweeps the `count` contacts listed at `sweep` (SHOCK_SWEEP, from the top down) once, ground up:
 * each upper body stops approaching the body below it, as if that body could not move. With
 * `useBias` 1, overlap is pushed out at `biasRate` (at most `maxPushSpeed`), as against the
 * ground; with 0, only the approach is removed (relax pass). A new contact faster than
 * `restitutionThreshold` bounces at its first touch, reversing its approach at that moment (with
 * the sub-step velocity changes at `marks`), an approach bounded by `maxApproach` (two bodies at
 * the world's maxLinearSpeed). `bodies`: the constraints' state offsets (CONSTRAINT_BODIES).
 */
export function shockSweep(
  constraints: usize,
  bodies: usize,
  sweep: usize,
  count: i32,
  states: usize,
  marks: usize,
  inverseH: f64,
  biasRate: f64,
  maxPushSpeed: f64,
  restitutionThreshold: f64,
  maxApproach: f64,
  useBias: i32,
): void {
  for (let n = count - 1; n >= 0; n--) {
    const e = sweep + ((<usize>(n * SWEEP_STRIDE)) << 3);
    const restitution = ld(e, SWEEP_RESTITUTION);
    const bounce = restitution > 0;
    let wait = false;
    const i = <i32>ld(e, SWEEP_CONSTRAINT);
    const c = constraintAt(constraints, i);
    const aOffset = load<i32>(bodies + ((<usize>i) << 3));
    const bOffset = load<i32>(bodies + ((<usize>i) << 3), 4);
    const a = states + ((<usize>aOffset) << 3);
    const b = states + ((<usize>bOffset) << 3);
    const aLower = ld(e, SWEEP_LOWER_IS_A) == 1;
    // The upper body takes the whole impulse, along +n if it is B and -n if it is A.
    const u = aLower ? b : a;
    const sign: f64 = aLower ? 1 : -1;
    const mU = lc(c, aLower ? INV_MASS_B : INV_MASS_A);
    const iU = lc(c, aLower ? INV_I_B : INV_I_A);
    const nx = lc(c, NORMAL_X);
    const ny = lc(c, NORMAL_Y);
    const vAx = ld(a, V_X);
    const vAy = ld(a, V_Y);
    const wA = ld(a, W);
    const vBx = ld(b, V_X);
    const vBy = ld(b, V_Y);
    const wB = ld(b, W);
    const dpx = ld(b, DP_X) - ld(a, DP_X);
    const dpy = ld(b, DP_Y) - ld(a, DP_Y);
    const qAc = ld(a, Q_C);
    const qAs = ld(a, Q_S);
    const qBc = ld(b, Q_C);
    const qBs = ld(b, Q_S);
    const pointCount = lc(c, POINT_COUNT);
    // The upper body's velocity change by this sub-step's integration (gravity, forces): the
    // lower body is held, so only the upper one's adds to the approach.
    const kick = markOf(marks, aLower ? bOffset : aOffset);
    const kickN = sign * (ld(kick, KICK_VX) * nx + ld(kick, KICK_VY) * ny);
    const kickW = sign * ld(kick, KICK_W);
    // Per point: the target q = vn + bias (>= 0 wanted) and the upper body's lever rn = r x n.
    let q1: f64 = 0;
    let q2: f64 = 0;
    let rn1: f64 = 0;
    let rn2: f64 = 0;
    // For the friction below: the passes' normal impulses per point and friction impulse, and
    // the levers (A's and B's) to the manifold's middle.
    let n1: f64 = 0;
    let n2: f64 = 0;
    let applied: f64 = 0;
    let lAx: f64 = 0;
    let lAy: f64 = 0;
    let lBx: f64 = 0;
    let lBy: f64 = 0;
    for (let j = 0; <f64>j < pointCount; j++) {
      const p = pointAt(c, j);
      const rAx = lc(p, R_AX);
      const rAy = lc(p, R_AY);
      const rBx = lc(p, R_BX);
      const rBy = lc(p, R_BY);
      const dx = dpx + (qBc * rBx - qBs * rBy) - (qAc * rAx - qAs * rAy);
      const dy = dpy + (qBs * rBx + qBc * rBy) - (qAs * rAx + qAc * rAy);
      const separation = dx * nx + dy * ny + lc(p, BASE_SEPARATION);
      let bias: f64 = 0;
      const rn = aLower ? rBx * ny - rBy * nx : rAx * ny - rAy * nx;
      const approach = lc(p, RELATIVE_VELOCITY);
      const due = bounce && approach < -restitutionThreshold;
      if (separation > 0) {
        // A bounce is due when it touches: not slowed before, as the contact solver waits too.
        // Meanwhile the upper body falls on: its approach at the step's start plus each
        // sub-step's velocity change until it touches (the ordinary passes slow it so that it
        // touches without overlap; the bounce reverses the approach it had, not that).
        if (due) {
          wait = true;
          // Bounded: a large torque's kicks on a light lever would otherwise add up without
          // limit while it waits (a torqued hinge chain on the floor overflowed to NaN).
          if (useBias != 0) {
            sc(p, RELATIVE_VELOCITY, Math.max(approach + kickN + kickW * rn, -maxApproach));
          }
        }
        bias = separation * inverseH;
      } else {
        if (useBias != 0) bias = Math.max(biasRate * separation, -maxPushSpeed);
        // First touch of a new contact: leave at e times the approach, as off the ground
        // (a light body squeezed between a heavy one and the ground passes the bounce on),
        // the approach at the moment of touching: the end of the sub-step it touched in, half a
        // velocity change after its middle (see the bounce in contact-kernel.ts).
        if (due) {
          bias = restitution * Math.max(approach + 0.5 * (kickN + kickW * rn), -maxApproach);
          // A bounce is a one-off impulse, not a force to warm-start: the contact solver's share
          // of this impact is dropped, or undoing it next sub-step would throw the light body up.
          sc(p, NORMAL_IMPULSE, 0);
        }
        st(e, SWEEP_RESTITUTION, 0);
      }
      const vn =
        (vBx - wB * rBy - (vAx - wA * rAy)) * nx + (vBy + wB * rBx - (vAy + wA * rAx)) * ny;
      if (j == 0) {
        q1 = vn + bias;
        rn1 = rn;
        n1 = lc(p, NORMAL_IMPULSE);
      } else {
        q2 = vn + bias;
        rn2 = rn;
        n2 = lc(p, NORMAL_IMPULSE);
      }
      applied += lc(p, TANGENT_IMPULSE);
      lAx += rAx / pointCount;
      lAy += rAy / pointCount;
      lBx += rBx / pointCount;
      lBy += rBy / pointCount;
    }
    if (wait) continue;
    // The LCP  w = K x + q >= 0, x >= 0, x . w = 0  with K the upper body's inverse mass seen
    // by the points (one point: a scalar; two: the 2x2 block, cases as in contact-kernel.ts).
    const k11 = mU + iU * rn1 * rn1;
    let x1: f64 = 0;
    let x2: f64 = 0;
    if (pointCount == 1) {
      if (q1 < 0 && k11 > 0) x1 = -q1 / k11;
    } else {
      const k22 = mU + iU * rn2 * rn2;
      const k12 = mU + iU * rn1 * rn2;
      const det = k11 * k22 - k12 * k12;
      const kMax = Math.max(k11, k22);
      let solved = false;
      if (kMax > 0 && kMax * kMax < 1000 * det) {
        const y1 = (k12 * q2 - k22 * q1) / det;
        const y2 = (k12 * q1 - k11 * q2) / det;
        if (y1 >= 0 && y2 >= 0) {
          x1 = y1;
          x2 = y2;
          solved = true;
        }
      }
      if (!solved) {
        // One point at a time (also the block's one-point and no-push cases).
        if (q1 < 0 && k11 > 0) x1 = -q1 / k11;
        const w2 = q2 + k12 * x1;
        if (w2 < 0 && k22 > 0) x2 = -w2 / k22;
      }
    }
    if (x1 != 0 || x2 != 0) {
      const impulse = sign * (x1 + x2);
      st(u, V_X, ld(u, V_X) + mU * impulse * nx);
      st(u, V_Y, ld(u, V_Y) + mU * impulse * ny);
      st(u, W, ld(u, W) + sign * iU * (rn1 * x1 + rn2 * x2));
    }
    // Friction the same way: the upper body stops sliding on the lower one as if that could
    // not move, within the cone of the contact's whole normal impulse (the passes' and this
    // sweep's) less the friction the passes already applied. Sequential friction moves a heavy
    // body on a light one as little as the normal impulses do: a 100:1 stack slid 3 m down a
    // 10 degree slope with friction 0.6 (tan 10 degrees is 0.18).
    const limit = lc(c, FRICTION) * (x1 + x2 + n1 + n2);
    if (limit <= 0) continue;
    // The slip there (B relative to A along t = (ny, -nx), as the contact solver measures it)
    // and the upper body's lever across t.
    const rt = aLower ? -lBx * nx - lBy * ny : -lAx * nx - lAy * ny;
    const k = mU + iU * rt * rt;
    if (!(k > 0)) continue;
    // The lower body's turning is left out: a light body rocks under a heavy one, and the heavy
    // one following that rocking walks off (10:1 on a 20 degree slope slid 4 m with it).
    const turnA: f64 = aLower ? 0 : ld(a, W);
    const turnB: f64 = aLower ? ld(b, W) : 0;
    const slip =
      (ld(b, V_X) - turnB * lBy - (ld(a, V_X) - turnA * lAy)) * ny -
      (ld(b, V_Y) + turnB * lBx - (ld(a, V_Y) + turnA * lAx)) * nx;
    if (Math.abs(slip) < SWEEP_SLIP) continue;
    const friction = Math.max(-limit - applied, Math.min(limit - applied, -slip / k));
    st(u, V_X, ld(u, V_X) + sign * mU * friction * ny);
    st(u, V_Y, ld(u, V_Y) - sign * mU * friction * nx);
    st(u, W, ld(u, W) + sign * iU * rt * friction);
  }
}
