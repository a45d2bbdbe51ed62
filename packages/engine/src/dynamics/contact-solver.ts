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
const POINT_STRIDE = 12;
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
      const rnA = rAx * ny - rAy * nx;
      const rnB = rBx * ny - rBy * nx;
      const kNormal = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
      c[p + NORMAL_MASS] = kNormal > 0 ? 1 / kNormal : 0;
      const rtA = rAx * ty - rAy * tx;
      const rtB = rBx * ty - rBy * tx;
      const kTangent = mA + mB + iA * rtA * rtA + iB * rtB * rtB;
      c[p + TANGENT_MASS] = kTangent > 0 ? 1 / kTangent : 0;
      // Normal approach velocity before the step, for restitution.
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
    for (let j = 0; j < pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      const rAx = c[p + R_AX]!;
      const rAy = c[p + R_AY]!;
      const rBx = c[p + R_BX]!;
      const rBy = c[p + R_BY]!;
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
    const dpx = s[b + DP_X]! - s[a + DP_X]!;
    const dpy = s[b + DP_Y]! - s[a + DP_Y]!;
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
      const dvx = vBx - wB * rBy - (vAx - wA * rAy);
      const dvy = vBy + wB * rBx - (vAy + wA * rAx);
      const vn = dvx * nx + dvy * ny;
      const accumulated = c[p + NORMAL_IMPULSE]!;
      let impulse = -c[p + NORMAL_MASS]! * massScale * (vn + bias) - impulseScale * accumulated;
      const newImpulse = Math.max(accumulated + impulse, 0);
      impulse = newImpulse - accumulated;
      c[p + NORMAL_IMPULSE] = newImpulse;
      if (impulse > c[p + MAX_NORMAL_IMPULSE]!) c[p + MAX_NORMAL_IMPULSE] = impulse;
      const px = impulse * nx;
      const py = impulse * ny;
      vAx -= mA * px;
      vAy -= mA * py;
      wA -= iA * (rAx * py - rAy * px);
      vBx += mB * px;
      vBy += mB * py;
      wB += iB * (rBx * py - rBy * px);
    }

    const tx = ny;
    const ty = -nx;
    for (let j = 0; j < pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      const rAx = c[p + R_AX]!;
      const rAy = c[p + R_AY]!;
      const rBx = c[p + R_BX]!;
      const rBy = c[p + R_BY]!;
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
 * and was actually pushed, set the normal velocity to -e times the approach velocity (Newton's
 * law of restitution). Done once per step on final velocities, so the soft contact's damping never
 * eats into the bounce.
 */
export function applyRestitution(
  constraints: ContactConstraints,
  s: Float64Array,
  threshold: number,
): void {
  const c = constraints.data;
  const indices = constraints.bodies;
  for (let i = 0; i < constraints.count; i++) {
    const base = i * STRIDE;
    const restitution = c[base + RESTITUTION]!;
    if (restitution === 0) continue;
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
    for (let j = 0; j < pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      const relativeVelocity = c[p + RELATIVE_VELOCITY]!;
      if (relativeVelocity > -threshold || c[p + MAX_NORMAL_IMPULSE]! === 0) continue;
      const rAx = c[p + R_AX]!;
      const rAy = c[p + R_AY]!;
      const rBx = c[p + R_BX]!;
      const rBy = c[p + R_BY]!;
      const dvx = vBx - wB * rBy - (vAx - wA * rAy);
      const dvy = vBy + wB * rBx - (vAy + wA * rAx);
      const vn = dvx * nx + dvy * ny;
      const accumulated = c[p + NORMAL_IMPULSE]!;
      let impulse = -c[p + NORMAL_MASS]! * (vn + restitution * relativeVelocity);
      const newImpulse = Math.max(accumulated + impulse, 0);
      impulse = newImpulse - accumulated;
      c[p + NORMAL_IMPULSE] = newImpulse;
      if (impulse > c[p + MAX_NORMAL_IMPULSE]!) c[p + MAX_NORMAL_IMPULSE] = impulse;
      const px = impulse * nx;
      const py = impulse * ny;
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

/** Copies the accumulated impulses back to the manifolds, for warm starting and events. */
export function storeImpulses(constraints: ContactConstraints): void {
  const c = constraints.data;
  for (let i = 0; i < constraints.count; i++) {
    const base = i * STRIDE;
    const m = constraints.contacts[i]!.manifold;
    for (let j = 0; j < m.pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      const mp = m.points[j]!;
      mp.normalImpulse = c[p + NORMAL_IMPULSE]!;
      mp.tangentImpulse = c[p + TANGENT_IMPULSE]!;
      mp.maxNormalImpulse = c[p + MAX_NORMAL_IMPULSE]!;
      mp.relativeVelocity = c[p + RELATIVE_VELOCITY]!;
    }
  }
}
