import type { Contact } from './contact.ts';
import { DP_X, DP_Y, Q_C, Q_S, STATE_STRIDE, V_X, V_Y, W } from './body-state.ts';
import type { Softness } from './softness.ts';

// Contact constraints of one step, prepared once into flat arrays so the sub-step loops touch only
// numbers (Box2D v3 prepares contact constraints the same way, "b2PrepareContactsTask").
//
// Sequential impulses (Catto, GDC 2006 "Fast and simple physics using sequential impulses") with
// accumulated, clamped impulses; soft contacts and sub-stepping (Catto, Box2D v3 "soft step") for
// position error: no separate position pass, anchors fixed for the step, the separation updated
// from the bodies' pose change. Normal first, then friction limited by the new normal impulse.

// Per-constraint layout (doubles).
const NORMAL_X = 0;
const NORMAL_Y = 1;
const FRICTION = 2;
const RESTITUTION = 3;
const INV_MASS_A = 4;
const INV_I_A = 5;
const INV_MASS_B = 6;
const INV_I_B = 7;
const BIAS_RATE = 8;
const MASS_SCALE = 9;
const IMPULSE_SCALE = 10;
const POINT_COUNT = 11;
const POINTS = 12;
// Per-point layout, relative to POINTS + j * POINT_STRIDE.
const R_AX = 0;
const R_AY = 1;
const R_BX = 2;
const R_BY = 3;
const BASE_SEPARATION = 4;
const NORMAL_IMPULSE = 5;
const TANGENT_IMPULSE = 6;
const MAX_NORMAL_IMPULSE = 7;
const NORMAL_MASS = 8;
const TANGENT_MASS = 9;
const RELATIVE_VELOCITY = 10;
const TOTAL_NORMAL_IMPULSE = 11;
const TOTAL_TANGENT_IMPULSE = 12;
const BASELINE_VELOCITY = 13;
const RESTITUTION_IMPULSE = 14;
const POINT_STRIDE = 16;
const STRIDE = POINTS + 2 * POINT_STRIDE;

/** Solver-side copies of the touching contacts of one step. */
export class ContactConstraints {
  count = 0;
  data: Float64Array = new Float64Array(STRIDE * 256);
  /** State offsets (index * STATE_STRIDE) of body A and B per constraint. */
  bodies: Int32Array = new Int32Array(2 * 256);
  /** The contact each constraint came from, to store impulses back. */
  readonly contacts: Contact[] = [];

  reserve(count: number): void {
    if (this.bodies.length < 2 * count) {
      let size = this.bodies.length / 2;
      while (size < count) size *= 2;
      this.data = new Float64Array(size * STRIDE);
      this.bodies = new Int32Array(size * 2);
    }
  }
}

/**
 * Copies the manifolds of `contacts` into constraints, computing effective masses, the anchors
 * relative to each centre of mass and the separation baseline. Reads velocities from `states`
 * (already loaded with the bodies' velocities of this step's start) for restitution.
 */
export function prepareContacts(
  constraints: ContactConstraints,
  states: Float64Array,
  contactSoftness: Softness,
  staticSoftness: Softness,
): void {
  const count = constraints.contacts.length;
  constraints.count = count;
  constraints.reserve(count);
  const c = constraints.data;
  const indices = constraints.bodies;
  for (let i = 0; i < count; i++) {
    const contact = constraints.contacts[i]!;
    const bodyA = contact.bodyA;
    const bodyB = contact.bodyB;
    const m = contact.manifold;
    const base = i * STRIDE;
    const a = bodyA.solverIndex * STATE_STRIDE;
    const b = bodyB.solverIndex * STATE_STRIDE;
    indices[2 * i] = a;
    indices[2 * i + 1] = b;
    // Sleeping or static bodies are solved as immovable (slot 0); awake kinematic ones too.
    const mA = bodyA.solverIndex === 0 ? 0 : bodyA.invMass;
    const iA = bodyA.solverIndex === 0 ? 0 : bodyA.invInertia;
    const mB = bodyB.solverIndex === 0 ? 0 : bodyB.invMass;
    const iB = bodyB.solverIndex === 0 ? 0 : bodyB.invInertia;
    // Stiffer against immovable bodies: nothing on the other side gives way.
    const soft = mA === 0 || mB === 0 ? staticSoftness : contactSoftness;
    const nx = m.normalX;
    const ny = m.normalY;
    c[base + NORMAL_X] = nx;
    c[base + NORMAL_Y] = ny;
    c[base + FRICTION] = contact.friction;
    c[base + RESTITUTION] = contact.restitution;
    c[base + INV_MASS_A] = mA;
    c[base + INV_I_A] = iA;
    c[base + INV_MASS_B] = mB;
    c[base + INV_I_B] = iB;
    c[base + BIAS_RATE] = soft.biasRate;
    c[base + MASS_SCALE] = soft.massScale;
    c[base + IMPULSE_SCALE] = soft.impulseScale;
    c[base + POINT_COUNT] = m.pointCount;
    const tx = ny;
    const ty = -nx;
    const vAx = states[a + V_X]!;
    const vAy = states[a + V_Y]!;
    const wA = states[a + W]!;
    const vBx = states[b + V_X]!;
    const vBy = states[b + V_Y]!;
    const wB = states[b + W]!;
    for (let j = 0; j < m.pointCount; j++) {
      const mp = m.points[j]!;
      const p = base + POINTS + j * POINT_STRIDE;
      const rAx = mp.x - bodyA.centerX;
      const rAy = mp.y - bodyA.centerY;
      const rBx = mp.x - bodyB.centerX;
      const rBy = mp.y - bodyB.centerY;
      c[p + R_AX] = rAx;
      c[p + R_AY] = rAy;
      c[p + R_BX] = rBx;
      c[p + R_BY] = rBy;
      // Separation later = baseline + (change of the anchors' world positions) . n.
      c[p + BASE_SEPARATION] = mp.separation - ((rBx - rAx) * nx + (rBy - rAy) * ny);
      c[p + NORMAL_IMPULSE] = mp.normalImpulse;
      c[p + TANGENT_IMPULSE] = mp.tangentImpulse;
      c[p + MAX_NORMAL_IMPULSE] = 0;
      c[p + TOTAL_NORMAL_IMPULSE] = 0;
      c[p + TOTAL_TANGENT_IMPULSE] = 0;
      const rnA = rAx * ny - rAy * nx;
      const rnB = rBx * ny - rBy * nx;
      const kNormal = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
      c[p + NORMAL_MASS] = kNormal > 0 ? 1 / kNormal : 0;
      const rtA = rAx * ty - rAy * tx;
      const rtB = rBx * ty - rBy * tx;
      const kTangent = mA + mB + iA * rtA * rtA + iB * rtB * rtB;
      c[p + TANGENT_MASS] = kTangent > 0 ? 1 / kTangent : 0;
      // Normal approach velocity before the step, for restitution; replaced by the velocity at the
      // first push of the step (see solveContacts).
      const dvx = vBx - wB * rBy - (vAx - wA * rAy);
      const dvy = vBy + wB * rBx - (vAy + wA * rAx);
      c[p + RELATIVE_VELOCITY] = dvx * nx + dvy * ny;
    }
  }
}

/** Applies last step's accumulated impulses, so resting contacts start where they left off. */
export function warmStartContacts(constraints: ContactConstraints, s: Float64Array): void {
  const c = constraints.data;
  const indices = constraints.bodies;
  for (let i = 0; i < constraints.count; i++) {
    const base = i * STRIDE;
    const a = indices[2 * i]!;
    const b = indices[2 * i + 1]!;
    const mA = c[base + INV_MASS_A]!;
    const iA = c[base + INV_I_A]!;
    const mB = c[base + INV_MASS_B]!;
    const iB = c[base + INV_I_B]!;
    const nx = c[base + NORMAL_X]!;
    const ny = c[base + NORMAL_Y]!;
    const tx = ny;
    const ty = -nx;
    let vAx = s[a + V_X]!;
    let vAy = s[a + V_Y]!;
    let wA = s[a + W]!;
    let vBx = s[b + V_X]!;
    let vBy = s[b + V_Y]!;
    let wB = s[b + W]!;
    const pointCount = c[base + POINT_COUNT]!;
    // Lever arms reach the contact point where it is now: it moves with the bodies (weighted by
    // inverse mass, so it stays on a body pushed against a static one). Both bodies then get
    // the impulse at the same world point, and angular momentum is conserved exactly.
    const shiftTotal = mA + mB;
    const shiftA = shiftTotal > 0 ? mA / shiftTotal : 0;
    const shiftB = shiftTotal > 0 ? mB / shiftTotal : 0;
    const dpAx = s[a + DP_X]!;
    const dpAy = s[a + DP_Y]!;
    const dpBx = s[b + DP_X]!;
    const dpBy = s[b + DP_Y]!;
    const shiftX = shiftA * dpAx + shiftB * dpBx;
    const shiftY = shiftA * dpAy + shiftB * dpBy;
    const shiftAx = shiftX - dpAx;
    const shiftAy = shiftY - dpAy;
    const shiftBx = shiftX - dpBx;
    const shiftBy = shiftY - dpBy;
    for (let j = 0; j < pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      const rAx = c[p + R_AX]! + shiftAx;
      const rAy = c[p + R_AY]! + shiftAy;
      const rBx = c[p + R_BX]! + shiftBx;
      const rBy = c[p + R_BY]! + shiftBy;
      const pn = c[p + NORMAL_IMPULSE]!;
      const pt = c[p + TANGENT_IMPULSE]!;
      const px = pn * nx + pt * tx;
      const py = pn * ny + pt * ty;
      wA -= iA * (rAx * py - rAy * px);
      vAx -= mA * px;
      vAy -= mA * py;
      wB += iB * (rBx * py - rBy * px);
      vBx += mB * px;
      vBy += mB * py;
    }
    if (a !== 0) {
      s[a + V_X] = vAx;
      s[a + V_Y] = vAy;
      s[a + W] = wA;
    }
    if (b !== 0) {
      s[b + V_X] = vBx;
      s[b + V_Y] = vBy;
      s[b + W] = wB;
    }
  }
}

/**
 * One pass over every contact. With `useBias` the soft position correction pushes overlapping
 * shapes apart (at most `maxPushSpeed`); without it ("relax") the pass removes the velocity that
 * push added, so resting bodies do not gain energy from correction.
 */
export function solveContacts(
  constraints: ContactConstraints,
  s: Float64Array,
  inverseH: number,
  maxPushSpeed: number,
  useBias: boolean,
): void {
  const c = constraints.data;
  const indices = constraints.bodies;
  for (let i = 0; i < constraints.count; i++) {
    const base = i * STRIDE;
    const a = indices[2 * i]!;
    const b = indices[2 * i + 1]!;
    const mA = c[base + INV_MASS_A]!;
    const iA = c[base + INV_I_A]!;
    const mB = c[base + INV_MASS_B]!;
    const iB = c[base + INV_I_B]!;
    const nx = c[base + NORMAL_X]!;
    const ny = c[base + NORMAL_Y]!;
    const friction = c[base + FRICTION]!;
    const biasRate = c[base + BIAS_RATE]!;
    const softMassScale = c[base + MASS_SCALE]!;
    const softImpulseScale = c[base + IMPULSE_SCALE]!;
    let vAx = s[a + V_X]!;
    let vAy = s[a + V_Y]!;
    let wA = s[a + W]!;
    let vBx = s[b + V_X]!;
    let vBy = s[b + V_Y]!;
    let wB = s[b + W]!;
    const dpAx = s[a + DP_X]!;
    const dpAy = s[a + DP_Y]!;
    const dpBx = s[b + DP_X]!;
    const dpBy = s[b + DP_Y]!;
    const dpx = dpBx - dpAx;
    const dpy = dpBy - dpAy;
    // Lever arms reach the contact point where it is now: it moves with the bodies (weighted by
    // inverse mass, so it stays on a body pushed against a static one). Both bodies then get each
    // impulse at the same world point, and angular momentum is conserved exactly. (Arms fixed at
    // the step's start, as in Box2D v3, drift 1e-3 of the angular momentum of 100 colliding
    // bodies in 10 s.)
    const shiftTotal = mA + mB;
    const shiftA = shiftTotal > 0 ? mA / shiftTotal : 0;
    const shiftB = shiftTotal > 0 ? mB / shiftTotal : 0;
    const shiftX = shiftA * dpAx + shiftB * dpBx;
    const shiftY = shiftA * dpAy + shiftB * dpBy;
    const shiftAx = shiftX - dpAx;
    const shiftAy = shiftY - dpAy;
    const shiftBx = shiftX - dpBx;
    const shiftBy = shiftY - dpBy;
    const qAc = s[a + Q_C]!;
    const qAs = s[a + Q_S]!;
    const qBc = s[b + Q_C]!;
    const qBs = s[b + Q_S]!;
    const pointCount = c[base + POINT_COUNT]!;

    for (let j = 0; j < pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      const rAx = c[p + R_AX]!;
      const rAy = c[p + R_AY]!;
      const rBx = c[p + R_BX]!;
      const rBy = c[p + R_BY]!;
      // Current separation: the anchors moved with their bodies since the step began.
      const dx = dpx + (qBc * rBx - qBs * rBy) - (qAc * rAx - qAs * rAy);
      const dy = dpy + (qBs * rBx + qBc * rBy) - (qAs * rAx + qAc * rAy);
      const separation = dx * nx + dy * ny + c[p + BASE_SEPARATION]!;
      const lAx = rAx + shiftAx;
      const lAy = rAy + shiftAy;
      const lBx = rBx + shiftBx;
      const lBy = rBy + shiftBy;
      let bias = 0;
      let massScale = 1;
      let impulseScale = 0;
      if (separation > 0) {
        // Speculative: allow closing exactly the gap within this sub-step, no more.
        bias = separation * inverseH;
      } else if (useBias) {
        bias = Math.max(biasRate * separation, -maxPushSpeed);
        massScale = softMassScale;
        impulseScale = softImpulseScale;
      }
      const dvx = vBx - wB * lBy - (vAx - wA * lAy);
      const dvy = vBy + wB * lBx - (vAy + wA * lAx);
      const vn = dvx * nx + dvy * ny;
      const accumulated = c[p + NORMAL_IMPULSE]!;
      let impulse = -c[p + NORMAL_MASS]! * massScale * (vn + bias) - impulseScale * accumulated;
      const newImpulse = Math.max(accumulated + impulse, 0);
      impulse = newImpulse - accumulated;
      c[p + NORMAL_IMPULSE] = newImpulse;
      // The relax pass ends the sub-step: the accumulated impulse is what acted in it.
      if (!useBias) c[p + TOTAL_NORMAL_IMPULSE] += newImpulse;
      // Restitution must reverse the approach speed at the moment of impact, not at the start of
      // the step: a speculative contact is often first pushed in a later sub-step, after gravity
      // (or another contact) has changed the velocity. Record the normal velocity just before the
      // first push of the step. (With the step-start value a ball dropped 1 m onto the floor lost
      // the gravity of the bounce step: 8 % of the rebound height at e = 1.)
      if (impulse > 0 && c[p + MAX_NORMAL_IMPULSE]! === 0) c[p + RELATIVE_VELOCITY] = vn;
      if (impulse > c[p + MAX_NORMAL_IMPULSE]!) c[p + MAX_NORMAL_IMPULSE] = impulse;
      const px = impulse * nx;
      const py = impulse * ny;
      vAx -= mA * px;
      vAy -= mA * py;
      wA -= iA * (lAx * py - lAy * px);
      vBx += mB * px;
      vBy += mB * py;
      wB += iB * (lBx * py - lBy * px);
    }

    const tx = ny;
    const ty = -nx;
    for (let j = 0; j < pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      const rAx = c[p + R_AX]! + shiftAx;
      const rAy = c[p + R_AY]! + shiftAy;
      const rBx = c[p + R_BX]! + shiftBx;
      const rBy = c[p + R_BY]! + shiftBy;
      const dvx = vBx - wB * rBy - (vAx - wA * rAy);
      const dvy = vBy + wB * rBx - (vAy + wA * rAx);
      const vt = dvx * tx + dvy * ty;
      const accumulated = c[p + TANGENT_IMPULSE]!;
      const maxFriction = friction * c[p + NORMAL_IMPULSE]!;
      let newImpulse = accumulated - c[p + TANGENT_MASS]! * vt;
      if (newImpulse > maxFriction) newImpulse = maxFriction;
      else if (newImpulse < -maxFriction) newImpulse = -maxFriction;
      const impulse = newImpulse - accumulated;
      c[p + TANGENT_IMPULSE] = newImpulse;
      if (!useBias) c[p + TOTAL_TANGENT_IMPULSE] += newImpulse;
      const px = impulse * tx;
      const py = impulse * ty;
      vAx -= mA * px;
      vAy -= mA * py;
      wA -= iA * (rAx * py - rAy * px);
      vBx += mB * px;
      vBy += mB * py;
      wB += iB * (rBx * py - rBy * px);
    }

    if (a !== 0) {
      s[a + V_X] = vAx;
      s[a + V_Y] = vAy;
      s[a + W] = wA;
    }
    if (b !== 0) {
      s[b + V_X] = vBx;
      s[b + V_Y] = vBy;
      s[b + W] = wB;
    }
  }
}

/**
 * Restitution, after the sub-steps: for each point that was approaching faster than `threshold`
 * when it was first pushed, set the normal velocity to -e times that approach velocity (Newton's
 * law of restitution). Done once per step on final velocities, so the soft contact's damping never
 * eats into the bounce.
 *
 * Fixes over Box2D v3's single pass, which lost about half the kinetic energy of 20 elastic balls
 * in a box in a minute:
 * - The bounce impulse is a one-off: it counts in the step's total but is not added to the
 *   accumulated impulse used for warm starting. (Box2D adds it, so the next step re-applies the
 *   bounce at every sub-step until the solver takes it back, and neighbouring contacts respond to
 *   that phantom velocity in the meantime.)
 * - Bounces propagate. A single pass cannot handle a ball bounced into another body that rests
 *   against it (or against a wall): that contact just stops it and the energy is gone. After the
 *   bounces, further passes find contacts that the bounces made approach, and bounce them too
 *   with their own restitution (or stop them, below the threshold), at the velocity they approach
 *   with now: a sequence of two-body collisions, each of which keeps the energy when e = 1. (Solving
 *   all the bounce targets at once instead, as Box2D v2 does, creates energy when a ball is
 *   squeezed between another and a wall.)
 */
export function applyRestitution(
  constraints: ContactConstraints,
  s: Float64Array,
  threshold: number,
): void {
  const c = constraints.data;
  const indices = constraints.bodies;
  const count = constraints.count;
  let bounces = false;
  for (let i = 0; i < count; i++) {
    const base = i * STRIDE;
    const restitution = c[base + RESTITUTION]!;
    const pointCount = c[base + POINT_COUNT]!;
    for (let j = 0; j < pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      c[p + RESTITUTION_IMPULSE] = 0;
      if (
        restitution > 0 &&
        c[p + RELATIVE_VELOCITY]! < -threshold &&
        c[p + MAX_NORMAL_IMPULSE]! > 0
      ) {
        bounces = true;
      }
    }
  }
  if (!bounces) return;

  // Baselines: a point pushed this step may not approach faster than it does now (or than 0).
  for (let i = 0; i < count; i++) {
    const base = i * STRIDE;
    const a = indices[2 * i]!;
    const b = indices[2 * i + 1]!;
    const nx = c[base + NORMAL_X]!;
    const ny = c[base + NORMAL_Y]!;
    const mA = c[base + INV_MASS_A]!;
    const mB = c[base + INV_MASS_B]!;
    const pointCount = c[base + POINT_COUNT]!;
    const shiftTotal = mA + mB;
    const shiftA = shiftTotal > 0 ? mA / shiftTotal : 0;
    const shiftB = shiftTotal > 0 ? mB / shiftTotal : 0;
    const dpAx = s[a + DP_X]!;
    const dpAy = s[a + DP_Y]!;
    const dpBx = s[b + DP_X]!;
    const dpBy = s[b + DP_Y]!;
    const shiftX = shiftA * dpAx + shiftB * dpBx;
    const shiftY = shiftA * dpAy + shiftB * dpBy;
    const shiftAx = shiftX - dpAx;
    const shiftAy = shiftY - dpAy;
    const shiftBx = shiftX - dpBx;
    const shiftBy = shiftY - dpBy;
    for (let j = 0; j < pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      if (c[p + MAX_NORMAL_IMPULSE]! === 0) {
        c[p + BASELINE_VELOCITY] = -Infinity; // not pushed this step: not in contact
        continue;
      }
      const rAx = c[p + R_AX]! + shiftAx;
      const rAy = c[p + R_AY]! + shiftAy;
      const rBx = c[p + R_BX]! + shiftBx;
      const rBy = c[p + R_BY]! + shiftBy;
      const dvx = s[b + V_X]! - s[b + W]! * rBy - (s[a + V_X]! - s[a + W]! * rAy);
      const dvy = s[b + V_Y]! + s[b + W]! * rBx - (s[a + V_Y]! + s[a + W]! * rAx);
      c[p + BASELINE_VELOCITY] = Math.min(dvx * nx + dvy * ny, 0);
    }
  }

  // The bounces of this step's impacts.
  restitutionPass(constraints, s, threshold, true);
  // Their consequences, until nothing approaches (or the pass budget is spent: what is left is
  // the next step's contact to solve).
  for (let pass = 0; pass < PROPAGATION_PASSES; pass++) {
    if (!restitutionPass(constraints, s, threshold, false)) break;
  }

  for (let i = 0; i < count; i++) {
    const base = i * STRIDE;
    const pointCount = c[base + POINT_COUNT]!;
    for (let j = 0; j < pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      c[p + TOTAL_NORMAL_IMPULSE] += c[p + RESTITUTION_IMPULSE]!;
    }
  }
}

/** Most propagation passes per step (a chain of n touching bodies needs about n). */
const PROPAGATION_PASSES = 32;
/** Approach speed (m/s) below which a propagated contact is left alone. */
const PROPAGATION_TOLERANCE = 1e-9;

/**
 * One pass over the contacts. The first pass (`impacts`) bounces each point at -e times its
 * recorded impact velocity; it may also take back the last sub-step's push. Later passes bounce
 * (or stop) the points that approach faster than their baseline. Returns whether any impulse was
 * applied.
 */
function restitutionPass(
  constraints: ContactConstraints,
  s: Float64Array,
  threshold: number,
  impacts: boolean,
): boolean {
  const c = constraints.data;
  const indices = constraints.bodies;
  let applied = false;
  for (let i = 0; i < constraints.count; i++) {
    const base = i * STRIDE;
    const restitution = c[base + RESTITUTION]!;
    if (impacts && restitution === 0) continue;
    const a = indices[2 * i]!;
    const b = indices[2 * i + 1]!;
    const mA = c[base + INV_MASS_A]!;
    const iA = c[base + INV_I_A]!;
    const mB = c[base + INV_MASS_B]!;
    const iB = c[base + INV_I_B]!;
    const nx = c[base + NORMAL_X]!;
    const ny = c[base + NORMAL_Y]!;
    let vAx = s[a + V_X]!;
    let vAy = s[a + V_Y]!;
    let wA = s[a + W]!;
    let vBx = s[b + V_X]!;
    let vBy = s[b + V_Y]!;
    let wB = s[b + W]!;
    const pointCount = c[base + POINT_COUNT]!;
    // Lever arms reach the contact point where it is now: it moves with the bodies (weighted by
    // inverse mass, so it stays on a body pushed against a static one). Both bodies then get
    // the impulse at the same world point, and angular momentum is conserved exactly.
    const shiftTotal = mA + mB;
    const shiftA = shiftTotal > 0 ? mA / shiftTotal : 0;
    const shiftB = shiftTotal > 0 ? mB / shiftTotal : 0;
    const dpAx = s[a + DP_X]!;
    const dpAy = s[a + DP_Y]!;
    const dpBx = s[b + DP_X]!;
    const dpBy = s[b + DP_Y]!;
    const shiftX = shiftA * dpAx + shiftB * dpBx;
    const shiftY = shiftA * dpAy + shiftB * dpBy;
    const shiftAx = shiftX - dpAx;
    const shiftAy = shiftY - dpAy;
    const shiftBx = shiftX - dpBx;
    const shiftBy = shiftY - dpBy;
    let changed = false;
    for (let j = 0; j < pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      const baseline = c[p + BASELINE_VELOCITY]!;
      if (baseline === -Infinity) continue;
      const relativeVelocity = c[p + RELATIVE_VELOCITY]!;
      if (impacts && relativeVelocity >= -threshold) continue;
      const rAx = c[p + R_AX]! + shiftAx;
      const rAy = c[p + R_AY]! + shiftAy;
      const rBx = c[p + R_BX]! + shiftBx;
      const rBy = c[p + R_BY]! + shiftBy;
      const dvx = vBx - wB * rBy - (vAx - wA * rAy);
      const dvy = vBy + wB * rBx - (vAy + wA * rAx);
      const vn = dvx * nx + dvy * ny;
      // Effective mass at the current lever arms, so that a bounce sets vn exactly.
      const rnA = rAx * ny - rAy * nx;
      const rnB = rBx * ny - rBy * nx;
      const k = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
      const normalMass = k > 0 ? 1 / k : 0;
      let impulse: number;
      if (impacts) {
        // The solver stopped the approach; give back e times it. A bounce may also take back the
        // last sub-step's push, as long as the step's push stays >= 0.
        impulse = Math.max(
          -normalMass * (vn + restitution * relativeVelocity),
          -c[p + NORMAL_IMPULSE]!,
        );
        // It is now a separating contact: any later approach counts from 0.
        c[p + BASELINE_VELOCITY] = 0;
      } else {
        const approach = baseline - vn;
        if (!(approach > PROPAGATION_TOLERANCE)) continue;
        const e = approach > threshold ? restitution : 0;
        impulse = normalMass * (1 + e) * approach;
      }
      if (impulse === 0) continue;
      c[p + RESTITUTION_IMPULSE] += impulse;
      changed = true;
      const px = impulse * nx;
      const py = impulse * ny;
      vAx -= mA * px;
      vAy -= mA * py;
      wA -= iA * (rAx * py - rAy * px);
      vBx += mB * px;
      vBy += mB * py;
      wB += iB * (rBx * py - rBy * px);
    }
    if (!changed) continue;
    applied = true;
    if (a !== 0) {
      s[a + V_X] = vAx;
      s[a + V_Y] = vAy;
      s[a + W] = wA;
    }
    if (b !== 0) {
      s[b + V_X] = vBx;
      s[b + V_Y] = vBy;
      s[b + W] = wB;
    }
  }
  return applied;
}

/**
 * Copies the accumulated impulses back to the manifolds for warm starting, and the impulses the
 * step delivered (sum over the sub-steps, plus restitution) to the contacts for events.
 */
export function storeImpulses(constraints: ContactConstraints): void {
  const c = constraints.data;
  for (let i = 0; i < constraints.count; i++) {
    const base = i * STRIDE;
    const contact = constraints.contacts[i]!;
    const m = contact.manifold;
    for (let j = 0; j < m.pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      const mp = m.points[j]!;
      mp.normalImpulse = c[p + NORMAL_IMPULSE]!;
      mp.tangentImpulse = c[p + TANGENT_IMPULSE]!;
      mp.maxNormalImpulse = c[p + MAX_NORMAL_IMPULSE]!;
      mp.relativeVelocity = c[p + RELATIVE_VELOCITY]!;
      contact.stepNormalImpulse[j] = c[p + TOTAL_NORMAL_IMPULSE]!;
      contact.stepTangentImpulse[j] = c[p + TOTAL_TANGENT_IMPULSE]!;
    }
  }
}
