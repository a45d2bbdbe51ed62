// The heavy-on-light sweep: the choice of contacts once a step and the sweep of each sub-step
// (shock propagation: Guendelman, Bridson and Fedkiw,
// "Nonconvex rigid bodies with stacking", SIGGRAPH 2003, section 7; Erleben's thesis, 2004): the
// one source, built into the kernel with the contact passes (contact-kernel.ts). Why:
// src/dynamics/contact-solver.ts (ShockPropagation, which calls both).
import {
  A_GRAVITY_X,
  A_GRAVITY_Y,
  A_INVERSE_H,
  A_MAX_PUSH_SPEED,
  A_RESTITUTION_THRESHOLD,
  A_SHOCK_BIAS_RATE,
  A_SHOCK_MAX_APPROACH,
  A_SHOCK_REST_SPEED,
  BASE_SEPARATION,
  BIAS_RATE,
  IMPULSE_SCALE,
  MASS_SCALE,
  RESTITUTION,
  STATE_STRIDE,
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
import { hypot } from '../src/math/hypot';

/** True when the constraint at `c` was pushing at the end of last step (a resting contact). */
function resting(c: usize): bool {
  const pointCount = lc(c, POINT_COUNT);
  for (let j = 0; <f64>j < pointCount; j++) {
    if (lc(pointAt(c, j), NORMAL_IMPULSE) > 0) return true;
  }
  return false;
}

/** Int32 number k of the scratch at `p`. */
function li(p: usize, k: i32): i32 {
  return load<i32>(p + ((<usize>k) << 2));
}

function si(p: usize, k: i32, v: i32): void {
  store<i32>(p + ((<usize>k) << 2), v);
}

/**
 * Finds the contacts to sweep this step among the `count` constraints (their state offsets at
 * `bodies`, CONSTRAINT_BODIES), with the states at the step's start; `bodyCount` is the number
 * of awake bodies (solver slots 1..bodyCount; slot 0 is every immovable body). Lists them in
 * SHOCK_SWEEP (`sweep`) from the top down, makes them rigid, moves them to the end of the
 * visiting order (`order`, ground up) and returns their number. The swept contacts push out
 * overlap at `biasRate`, as contacts with the ground do. A light body moving along the contact's
 * normal at `restSpeed` or faster is not resting under the heavy one (see below). `scratch`:
 * 2 (bodyCount + 1) + 5 count int32 (SHOCK_SCRATCH). `biasRate`, gravity and `restSpeed` are the
 * arguments at `args` (A_SHOCK_BIAS_RATE, A_GRAVITY_X, A_GRAVITY_Y, A_SHOCK_REST_SPEED:
 * kernel-arguments.ts).
 *
 * Once a step the bodies are ordered by how many resting contacts separate them from the ground
 * (static, sleeping or kinematic bodies); a contact where a heavy body rests on one more than
 * twice lighter (already pushing last step, normal within 60 degrees of up) is swept, and so is
 * every resting contact under a body a swept contact stands on, down to the ground.
 */
export function prepareShockSweep(
  constraints: usize,
  bodies: usize,
  order: usize,
  count: i32,
  states: usize,
  sweep: usize,
  scratch: usize,
  bodyCount: i32,
  args: usize,
): i32 {
  const biasRate = ld(args, A_SHOCK_BIAS_RATE);
  const gravityX = ld(args, A_GRAVITY_X);
  const gravityY = ld(args, A_GRAVITY_Y);
  const restSpeed = ld(args, A_SHOCK_REST_SPEED);
  const gravity = hypot(gravityX, gravityY);
  if (gravity == 0) return 0;
  // Scratch: a level and a flag (supports a swept contact) per solver slot; per constraint a
  // flag (swept), its two solver slots, its rank; the resting constraints.
  const level = scratch;
  const supports = level + ((<usize>(bodyCount + 1)) << 2);
  const swept = supports + ((<usize>(bodyCount + 1)) << 2);
  const ends = swept + ((<usize>count) << 2);
  const rank = ends + ((<usize>(2 * count)) << 2);
  const edges = rank + ((<usize>count) << 2);

  // Each constraint's two solver slots (immovable bodies are slot 0), and the resting ones
  // (pushing since last step): only they hold a body up.
  let edgeCount = 0;
  for (let i = 0; i < count; i++) {
    const c = constraintAt(constraints, i);
    const a = load<i32>(bodies + ((<usize>i) << 3));
    const b = load<i32>(bodies + ((<usize>i) << 3), 4);
    si(ends, 2 * i, lc(c, INV_MASS_A) == 0 ? 0 : a / STATE_STRIDE);
    si(ends, 2 * i + 1, lc(c, INV_MASS_B) == 0 ? 0 : b / STATE_STRIDE);
    if (resting(c)) si(edges, edgeCount++, i);
  }
  // Levels: resting contacts from the ground (slot 0), relaxed until no level shrinks (a stack
  // of n bodies takes at most n sweeps of the resting contacts). A body that only bounces or
  // flies has none: nothing holds it up.
  const far = 1 << 30;
  for (let n = 0; n <= bodyCount; n++) si(level, n, far);
  si(level, 0, 0);
  for (let changed = true; changed;) {
    changed = false;
    for (let e = 0; e < edgeCount; e++) {
      const i = li(edges, e);
      const na = li(ends, 2 * i);
      const nb = li(ends, 2 * i + 1);
      const la = li(level, na);
      const lb = li(level, nb);
      if (la + 1 < lb) si(level, nb, la + 1);
      else if (lb + 1 < la) si(level, na, lb + 1);
      else continue;
      changed = true;
    }
  }
  // A contact's rank: its lower body's level + 1 (0 between equal or unheld bodies).
  let maxRank = 0;
  for (let i = 0; i < count; i++) {
    const la = li(level, li(ends, 2 * i));
    const lb = li(level, li(ends, 2 * i + 1));
    const low = min(la, lb);
    const r = la == lb || low == far ? 0 : low + 1;
    si(rank, i, r);
    if (r > maxRank) maxRank = r;
  }

  // From the top down: a heavy-on-light contact on a resting light body is swept, and so is
  // every resting contact under a body that a swept contact stands on (down to the ground), so
  // the sweep starts from solid ground.
  for (let n = 0; n <= bodyCount; n++) si(supports, n, 0);
  for (let i = 0; i < count; i++) si(swept, i, 0);
  let listed = 0;
  for (let k = maxRank; k >= 1; k--) {
    for (let i = 0; i < count; i++) {
      if (li(rank, i) != k) continue;
      const c = constraintAt(constraints, i);
      const aLower = li(level, li(ends, 2 * i)) < li(level, li(ends, 2 * i + 1));
      const lower = li(ends, 2 * i + (aLower ? 0 : 1));
      const upper = li(ends, 2 * i + (aLower ? 1 : 0));
      const mLower = lc(c, aLower ? INV_MASS_A : INV_MASS_B);
      const mUpper = lc(c, aLower ? INV_MASS_B : INV_MASS_A);
      const nx = lc(c, NORMAL_X);
      const ny = lc(c, NORMAL_Y);
      // Heavy on light: the lower body more than twice lighter, the normal within 60 degrees of
      // up (a body beside another is not resting on it).
      const up = (aLower ? -1.0 : 1.0) * (nx * gravityX + ny * gravityY);
      // And the light body resting there: not moving along the normal (as fast as a load
      // presses). The sweep's bounce treats it as held still by what is under it; a light ball
      // sliding fast along the floor into a heavy one is not held along a slanted normal, and
      // treating it so reflected the heavy ball off a surface moving at the light ball's speed
      // (a 16-ball gas gained 90 % of its energy in one step). Such a hit is an impact of two
      // bodies, passed on to the floor by the impact rounds (contact-kernel.ts).
      const vLower = mLower == 0 ? 0 : load<i32>(bodies + ((<usize>i) << 3) + (aLower ? 0 : 4));
      const v = states + ((<usize>vLower) << 3);
      const heavyOnLight =
        mLower > 2 * mUpper &&
        up >= 0.5 * gravity &&
        Math.abs(ld(v, V_X) * nx + ld(v, V_Y) * ny) < restSpeed;
      if (heavyOnLight || (li(supports, upper) == 1 && li(level, upper) == k && resting(c))) {
        si(swept, i, 1);
        si(supports, lower, 1);
        // Listed from the top down; the sweeps read the list backwards, ground up.
        const e = sweep + ((<usize>(listed++ * SWEEP_STRIDE)) << 3);
        st(e, SWEEP_CONSTRAINT, <f64>i);
        st(e, SWEEP_LOWER_IS_A, aLower ? 1 : 0);
        // A contact approaching at the step's start may bounce (restitution), once, at first
        // touch (a resting one does not approach: the last relax pass stopped it). A heavy body
        // bounces off the light one here, not in the contact solver: there, its bounce would
        // send the light body into the ground, again each sub-step.
        st(e, SWEEP_RESTITUTION, lc(c, RESTITUTION));
        if (heavyOnLight) sc(c, RESTITUTION, 0);
        // Rigid in the ordinary passes: a soft contact lets its impulse leak each pass, so the
        // weight above would not reach the ground.
        sc(c, BIAS_RATE, biasRate);
        sc(c, MASS_SCALE, 1);
        sc(c, IMPULSE_SCALE, 0);
      }
    }
  }
  // The ordinary passes visit the swept contacts last, ground up.
  let kept = 0;
  for (let n = 0; n < count; n++) {
    const i = li(order, n);
    if (li(swept, i) == 0) si(order, kept++, i);
  }
  for (let n = listed - 1; n >= 0; n--) {
    si(order, kept++, <i32>ld(sweep + ((<usize>(n * SWEEP_STRIDE)) << 3), SWEEP_CONSTRAINT));
  }
  return listed;
}

/**
 * Sweeps the `count` contacts listed at `sweep` (SHOCK_SWEEP, from the top down) once, ground up:
 * each upper body stops approaching the body below it, as if that body could not move. With
 * `useBias` 1, overlap is pushed out at `biasRate` (at most `maxPushSpeed`), as against the
 * ground; with 0, only the approach is removed (relax pass). A new contact faster than
 * `restitutionThreshold` bounces at its first touch, reversing its approach at that moment (with
 * the sub-step velocity changes at `marks`), an approach bounded by `maxApproach` (two bodies at
 * the world's maxLinearSpeed). `bodies`: the constraints' state offsets (CONSTRAINT_BODIES).
 * The inverse sub-step and the numbers named here are the arguments at `args` (A_INVERSE_H,
 * A_SHOCK_BIAS_RATE, A_MAX_PUSH_SPEED, A_RESTITUTION_THRESHOLD, A_SHOCK_MAX_APPROACH).
 */
export function shockSweep(
  constraints: usize,
  bodies: usize,
  sweep: usize,
  count: i32,
  states: usize,
  marks: usize,
  args: usize,
  useBias: i32,
): void {
  const inverseH = ld(args, A_INVERSE_H);
  const biasRate = ld(args, A_SHOCK_BIAS_RATE);
  const maxPushSpeed = ld(args, A_MAX_PUSH_SPEED);
  const restitutionThreshold = ld(args, A_RESTITUTION_THRESHOLD);
  const maxApproach = ld(args, A_SHOCK_MAX_APPROACH);
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
