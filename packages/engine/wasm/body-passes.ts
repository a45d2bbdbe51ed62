// The body passes of a step: integrate velocities, integrate positions, hold velocities to the
// limits, and finalize (velocities, centre of mass, angle and sleep clock written back to the body
// memory). Like the contact passes (contact-kernel.ts, which exports these too), this is their one
// source, built to WebAssembly and by wasm2js to JavaScript (scripts/contact-kernel-build.ts), in
// AssemblyScript's portable subset: f64 and i32 arithmetic over the solver memory at the byte
// offsets the solver passes in (src/dynamics/solver-memory.ts), no allocation.
//
// They read each body's own numbers in place (the BODIES region, body-memory.ts: inverse masses,
// gravity scale, drag, damping, this step's force and torque, flags) through the step's awake list
// (AWAKE_BODIES: the world index of awake body i, whose state is slot i + 1) instead of a per-step
// copy of those numbers, and write the states (STATES, body-state.ts).
import {
  A_DT,
  A_GRAVITY_X,
  A_GRAVITY_Y,
  A_H,
  A_MAX_ANGULAR_SPEED,
  A_MAX_SPEED,
  BODY_STRIDE,
  B_ANGLE,
  B_ANGLE0,
  B_ANGULAR_DAMPING,
  B_C,
  B_CENTER0_X,
  B_CENTER0_Y,
  B_CENTER_X,
  B_CENTER_Y,
  B_DRAG,
  B_FLAGS,
  B_FORCES_LEFT,
  B_FORCE_X,
  B_FORCE_Y,
  B_GRAVITY_SCALE,
  B_INV_INERTIA,
  B_INV_MASS,
  B_LINEAR_DAMPING,
  B_LOCAL_CENTER_X,
  B_LOCAL_CENTER_Y,
  B_MAX_EXTENT,
  B_MIN_EXTENT,
  B_S,
  B_SLEEP_TIME,
  B_TORQUE,
  B_VX,
  B_VY,
  B_W,
  B_X,
  B_Y,
  DELTA_ANGLE,
  DP_X,
  DP_Y,
  FLAG_ALLOW_SLEEP,
  KICK_VX,
  KICK_VY,
  KICK_W,
  MARK_STRIDE,
  Q_C,
  Q_S,
  SLEEP_SPEED,
  STATE_STRIDE,
  V_X,
  V_Y,
  W,
} from './contact-layout';
import { ld, st } from './load-store';
// AssemblyScript has no `import type`, and DoublesAt is only a type here (pointers cast to it).
// eslint-disable-next-line @typescript-eslint/consistent-type-imports
import { DoublesAt } from './doubles-at';
// The engine's own deterministic cosine and sine, this very file compiled in (one source for
// TypeScript and the kernel).
import { cosSin } from '../src/math/trigonometry';

/**
 * The awake index visited n-th: list[n] of the int32 list at `list` when `useList` is 1 (a batch
 * of islands, src/dynamics/solver-batches.ts), else n itself.
 */
function awakeAt(list: usize, useList: i32, n: i32): i32 {
  return useList != 0 ? load<i32>(list + ((<usize>n) << 2)) : n;
}

/** Where the numbers of awake body i start in the body memory (`awake`: the world indices). */
function bodyOf(bodies: usize, awake: usize, i: i32): usize {
  return bodies + ((<usize>(load<i32>(awake + ((<usize>i) << 2)) * BODY_STRIDE)) << 3);
}

/** Where awake body i's state starts (slot i + 1; slot 0 is the immovable bodies' identity). */
function stateOf(states: usize, i: i32): usize {
  return states + ((<usize>((i + 1) * STATE_STRIDE)) << 3);
}

/**
 * Semi-implicit Euler, velocity half: v += h (F / m + g), with damping and the thesis's drag
 * applied implicitly (v / (1 + h c)) so that no damping value can reverse a velocity; for the
 * awake bodies visited from `from` to `to` (see awakeAt). Each body's velocity change goes after
 * its impact mark (`marks`, body-state.ts), for a bounce later in the sub-step. Gravity, the
 * sub-step h and the speed limits are the arguments at `args` (kernel-arguments.ts).
 */
export function integrateVelocities(
  bodies: usize,
  awake: usize,
  list: usize,
  useList: i32,
  from: i32,
  to: i32,
  states: usize,
  marks: usize,
  args: usize,
): void {
  const gx = ld(args, A_GRAVITY_X);
  const gy = ld(args, A_GRAVITY_Y);
  const h = ld(args, A_H);
  const maxSpeed = ld(args, A_MAX_SPEED);
  const maxAngularSpeed = ld(args, A_MAX_ANGULAR_SPEED);
  for (let n = from; n < to; n++) {
    const i = awakeAt(list, useList, n);
    const b = bodyOf(bodies, awake, i);
    const invMass = ld(b, B_INV_MASS);
    if (invMass == 0) continue; // kinematic: keeps the velocity it was given
    const k = stateOf(states, i);
    const scale = ld(b, B_GRAVITY_SCALE);
    let vx = ld(k, V_X);
    let vy = ld(k, V_Y);
    // The thesis's drag, F = -drag |v| v, with |v| taken at the start of the sub-step: then the
    // discrete motion has the exact terminal speed sqrt(m g / drag) and coasts exactly as
    // 1/v = 1/v0 + (drag/m) t.
    const drag = ld(b, B_DRAG);
    const dragFactor: f64 =
      drag > 0 ? 1 / (1 + h * invMass * drag * Math.sqrt(vx * vx + vy * vy)) : 1;
    vx = (vx + h * (invMass * ld(b, B_FORCE_X) + scale * gx)) * dragFactor;
    vy = (vy + h * (invMass * ld(b, B_FORCE_Y) + scale * gy)) * dragFactor;
    let w = ld(k, W) + h * ld(b, B_INV_INERTIA) * ld(b, B_TORQUE);
    const linearDamping = ld(b, B_LINEAR_DAMPING);
    if (linearDamping > 0) {
      const factor = 1 / (1 + h * linearDamping);
      vx *= factor;
      vy *= factor;
    }
    const angularDamping = ld(b, B_ANGULAR_DAMPING);
    if (angularDamping > 0) w /= 1 + h * angularDamping;
    const vx0 = ld(k, V_X);
    const vy0 = ld(k, V_Y);
    const w0 = ld(k, W);
    st(k, V_X, vx);
    st(k, V_Y, vy);
    st(k, W, w);
    limitSpeed(k, maxSpeed, maxAngularSpeed);
    // The velocity change of this integration, for a bounce later in the sub-step (body-state.ts).
    const m = marks + ((<usize>((i + 1) * MARK_STRIDE)) << 3);
    st(m, KICK_VX, ld(k, V_X) - vx0);
    st(m, KICK_VY, ld(k, V_Y) - vy0);
    st(m, KICK_W, ld(k, W) - w0);
  }
}

/**
 * Holds the velocity of the state at `k` to `maxSpeed` (the world's maxLinearSpeed) and
 * `maxAngularSpeed` (a quarter turn per sub-step, Box2D v3's B2_MAX_ROTATION: faster, the
 * first-order rotation of the contact and joint anchors is meaningless, and a joint pulling a tiny
 * body by a long lever could spin it up without bound). A velocity with a component that
 * overflowed to infinity or became NaN has no direction left to keep: it is dropped (set to
 * zero), so a solve that failed for one sub-step stops the body instead of making its pose NaN.
 */
function limitSpeed(k: usize, maxSpeed: f64, maxAngularSpeed: f64): void {
  const w = ld(k, W);
  if (w > maxAngularSpeed) st(k, W, maxAngularSpeed);
  else if (w < -maxAngularSpeed) st(k, W, -maxAngularSpeed);
  else if (w != w) st(k, W, 0);
  const vx = ld(k, V_X);
  const vy = ld(k, V_Y);
  const speedSquared = vx * vx + vy * vy;
  if (speedSquared <= maxSpeed * maxSpeed) return;
  if (speedSquared < Infinity) {
    const ratio = maxSpeed / Math.sqrt(speedSquared);
    st(k, V_X, vx * ratio);
    st(k, V_Y, vy * ratio);
    return;
  }
  // The square overflowed (or is NaN): scale by the larger component first.
  const big = Math.max(Math.abs(vx), Math.abs(vy));
  if (big < Infinity) {
    const ux = vx / big;
    const uy = vy / big;
    const ratio = maxSpeed / Math.sqrt(ux * ux + uy * uy);
    st(k, V_X, ux * ratio);
    st(k, V_Y, uy * ratio);
  } else {
    st(k, V_X, 0);
    st(k, V_Y, 0);
  }
}

/**
 * Holds every awake dynamic body's velocity to the limits (see limitSpeed): after the relax pass,
 * which can ask more of a light body than the limits allow. The limits are the arguments at `args`.
 */
export function limitSpeeds(
  bodies: usize,
  awake: usize,
  list: usize,
  useList: i32,
  from: i32,
  to: i32,
  states: usize,
  args: usize,
): void {
  const maxSpeed = ld(args, A_MAX_SPEED);
  const maxAngularSpeed = ld(args, A_MAX_ANGULAR_SPEED);
  for (let n = from; n < to; n++) {
    const i = awakeAt(list, useList, n);
    if (ld(bodyOf(bodies, awake, i), B_INV_MASS) != 0) {
      limitSpeed(stateOf(states, i), maxSpeed, maxAngularSpeed);
    }
  }
}

/**
 * Semi-implicit Euler, position half: x += h v with the velocity just solved, for the awake
 * bodies visited from `from` to `to`.
 *
 * A dynamic body's solved velocity is held to the same limits as in integrateVelocities. The
 * solve can exceed them: a joint that cannot hold a tiny body against a large torque (a constant
 * 2 N m on a 0.01 kg box on a prismatic joint) let each sub-step's impulses grow the last's, until
 * the velocities overflowed and the whole world went NaN. Bounded, every pose moves at most
 * maxLinearSpeed h and a quarter turn per sub-step, so no error a constraint sees can grow without
 * bound. The sub-step h and the limits are the arguments at `args`.
 */
export function integratePositions(
  bodies: usize,
  awake: usize,
  list: usize,
  useList: i32,
  from: i32,
  to: i32,
  states: usize,
  args: usize,
): void {
  const h = ld(args, A_H);
  const maxSpeed = ld(args, A_MAX_SPEED);
  const maxAngularSpeed = ld(args, A_MAX_ANGULAR_SPEED);
  for (let n = from; n < to; n++) {
    const i = awakeAt(list, useList, n);
    const k = stateOf(states, i);
    // Kinematic bodies keep the velocity they were given.
    if (ld(bodyOf(bodies, awake, i), B_INV_MASS) != 0) limitSpeed(k, maxSpeed, maxAngularSpeed);
    const w = ld(k, W);
    const vx = ld(k, V_X);
    const vy = ld(k, V_Y);
    st(k, DP_X, ld(k, DP_X) + h * vx);
    st(k, DP_Y, ld(k, DP_Y) + h * vy);
    if (w != 0) {
      st(k, DELTA_ANGLE, ld(k, DELTA_ANGLE) + h * w);
      // First-order rotation update, renormalised: enough for the contact anchors within a step.
      const qc = ld(k, Q_C);
      const qs = ld(k, Q_S);
      const c = qc - h * w * qs;
      const sn = qs + h * w * qc;
      const inverseLength = 1 / Math.sqrt(c * c + sn * sn);
      st(k, Q_C, c * inverseLength);
      st(k, Q_S, sn * inverseLength);
    }
  }
}

/**
 * The step's end for the `count` awake bodies: velocities, centre of mass and angle written back
 * to the body memory, the transform from the new angle, and the sleep clock advanced or reset.
 * Returns how many awake bodies need a sweep test (continuous collision, when `continuous` is 1),
 * their awake indices listed in order in the int32 list at `fast` (FAST_BODIES).
 *
 * The angle is the exact sum of h w, and the transform follows it (the engine's cosSin, the same
 * bits as TypeScript's: src/math/trigonometry.ts is compiled in), so rotation never drifts from
 * the integrated angle; the origin is placed so that the body-local centre of mass lands on the
 * centre (as math/transform.ts's setFromCenter, operation for operation).
 *
 * Fast: a dynamic body that moved more than half its smallest extent (the centre's travel plus
 * the largest extent turned through the step's rotation), so it might have passed through a thin
 * shape; the world sweeps it (src/dynamics/continuous.ts).
 *
 * Sleep: the body must be slow, and not being moved by position correction either (Box2D v3's
 * rule, with its 0.5 weight on correction). A body with a force still to act (B_FORCES_LEFT, a
 * 'constant' or timed force) must not sleep: a small force on a heavy body is slow at first, and
 * sleeping would zero its velocity and stop it. The step dt is A_DT of the arguments at `args`.
 */
export function finalizeBodies(
  bodies: usize,
  awake: usize,
  count: i32,
  states: usize,
  args: usize,
  fast: usize,
  continuous: i32,
): i32 {
  const dt = ld(args, A_DT);
  let fastCount = 0;
  for (let i = 0; i < count; i++) {
    const b = bodyOf(bodies, awake, i);
    const k = stateOf(states, i);
    const vx = ld(k, V_X);
    const vy = ld(k, V_Y);
    const w = ld(k, W);
    const dpx = ld(k, DP_X);
    const dpy = ld(k, DP_Y);
    st(b, B_VX, vx);
    st(b, B_VY, vy);
    st(b, B_W, w);
    const centerX = ld(b, B_CENTER_X) + dpx;
    const centerY = ld(b, B_CENTER_Y) + dpy;
    const angle = ld(b, B_ANGLE) + ld(k, DELTA_ANGLE);
    st(b, B_CENTER_X, centerX);
    st(b, B_CENTER_Y, centerY);
    st(b, B_ANGLE, angle);
    // c and s straight into the body's numbers (B_S follows B_C, body-memory.ts).
    cosSin<DoublesAt>(angle, changetype<DoublesAt>(b + ((<usize>B_C) << 3)));
    const c = ld(b, B_C);
    const s = ld(b, B_S);
    const localX = ld(b, B_LOCAL_CENTER_X);
    const localY = ld(b, B_LOCAL_CENTER_Y);
    st(b, B_X, centerX - (c * localX - s * localY));
    st(b, B_Y, centerY - (s * localX + c * localY));
    // Awake and not kinematic (inverse mass 0) is dynamic.
    if (continuous != 0 && ld(b, B_INV_MASS) != 0) {
      const mx = centerX - ld(b, B_CENTER0_X);
      const my = centerY - ld(b, B_CENTER0_Y);
      const motion =
        Math.sqrt(mx * mx + my * my) + Math.abs(angle - ld(b, B_ANGLE0)) * ld(b, B_MAX_EXTENT);
      if (motion > 0.5 * ld(b, B_MIN_EXTENT)) {
        store<i32>(fast + ((<usize>fastCount) << 2), i);
        fastCount++;
      }
    }
    if (((<i32>ld(b, B_FLAGS)) & FLAG_ALLOW_SLEEP) == 0 || ld(b, B_FORCES_LEFT) != 0) {
      st(b, B_SLEEP_TIME, 0);
      continue;
    }
    const extent = ld(b, B_MAX_EXTENT);
    const speed = Math.sqrt(vx * vx + vy * vy) + extent * Math.abs(w);
    const moved = Math.sqrt(dpx * dpx + dpy * dpy) + extent * Math.abs(ld(k, DELTA_ANGLE));
    const sleepSpeed = Math.max(speed, (0.5 * moved) / dt);
    if (sleepSpeed > SLEEP_SPEED) st(b, B_SLEEP_TIME, 0);
    else st(b, B_SLEEP_TIME, ld(b, B_SLEEP_TIME) + dt);
  }
  return fastCount;
}
