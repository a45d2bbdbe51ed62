import {
  BOUNCING_STEPS as C_BOUNCING_STEPS,
  CONTACT_STRIDE,
  FRICTION as C_FRICTION,
  NORMAL_X as C_NORMAL_X,
  NORMAL_Y as C_NORMAL_Y,
  POINT_COUNT as C_POINT_COUNT,
  POINT_STRIDE as C_POINT_STRIDE,
  POINTS as C_POINTS,
  P_MAX_NORMAL_IMPULSE as C_MAX_NORMAL_IMPULSE,
  P_NORMAL_IMPULSE as C_NORMAL_IMPULSE,
  P_RELATIVE_VELOCITY as C_RELATIVE_VELOCITY,
  P_SEPARATION as C_SEPARATION,
  P_STEP_NORMAL_IMPULSE as C_STEP_NORMAL_IMPULSE,
  P_STEP_TANGENT_IMPULSE as C_STEP_TANGENT_IMPULSE,
  P_TANGENT_IMPULSE as C_TANGENT_IMPULSE,
  P_X as C_X,
  P_Y as C_Y,
  RADIUS_A as C_RADIUS_A,
  RADIUS_B as C_RADIUS_B,
  RESTITUTION as C_RESTITUTION,
} from './contact-data.ts';
import {
  DELTA_ANGLE,
  DP_X,
  DP_Y,
  Q_C,
  Q_S,
  STATE_STRIDE,
  TABLE_CENTER_X,
  TABLE_CENTER_Y,
  TABLE_INV_I,
  TABLE_INV_MASS,
  TABLE_SLOT,
  TABLE_STRIDE,
  V_X,
  V_Y,
  W,
} from './body-state.ts';
import type { SolverMemory } from './solver-memory.ts';
import { LINEAR_SLOP } from '../core/constants.ts';
import { Softness } from './softness.ts';

// Scratch for a heavy/light pair's softness (prepare), so the hot path allocates nothing.
const pairSoftness = new Softness();

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
// Where the common point of application lives (see prepareContacts), and the motion since the
// lever arms were set.
const SHIFT_WEIGHT_A = 12;
const SHIFT_WEIGHT_B = 13;
const REF_DP_AX = 14;
const REF_DP_AY = 15;
const REF_DP_BX = 16;
const REF_DP_BY = 17;
// Circle pairs: radii and the centre difference cB - cA at the step's start.
const RADIUS_A = 18;
const RADIUS_B = 19;
const CENTER_DX = 20;
const CENTER_DY = 21;
// Two-point manifolds: the normal block K (see solveContacts), and 1 when it is well-conditioned
// enough to be solved as a block.
const BLOCK_K11 = 22;
const BLOCK_K12 = 23;
const BLOCK_K22 = 24;
const BLOCK = 25;
const POINTS = 26;
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
// Impact state of a point: 0 none; 1 an impact found in this sub-step's solve pass, to bounce in
// its relax pass; 2 bounced in this sub-step (the bounce is not warm-started); 3 bounced in an
// earlier sub-step of this step; 4 no bounce in this step (pressed, see prepareContacts); 5 an
// impact of the impact round under way, 6 an impact of an earlier round of this sub-step (see
// solveImpacts: not warm-started either, and not a bounce that makes a contact pressed).
// A point may bounce in states 0, 1 and 3.
const IMPACT = 15;
// The lever arms' cross products with the normal when they were set (rA x n, rB x n): a pass
// adds only the common point's shift to them. Those with the tangent t = (ny, -nx) are computed
// where they are needed, r x t = -(r . n): two more stored numbers per point made the stride
// longer, and a 58,000-contact pile slower (its constraints outgrow the cache).
const RN_A = 13;
const RN_B = 14;
const POINT_STRIDE = 16;
const STRIDE = POINTS + 2 * POINT_STRIDE;
// A contact that bounced in each of its last three steps and still overlaps is pressed together
// by a load (a pile on a bouncy particle), not colliding. Bouncing it again would skip its push-out
// each sub-step (an impact is not pushed out, see solveContacts), so its overlap would grow and the
// load would pass through it: a particle under 12 rows of a pile went through the floor. Such a
// point is a contact for one step; from then on it is warm-started and never counts as an impact.
// Not after one or two steps: in an elastic gas a light particle squeezed between a heavy one and
// a wall bounces in consecutive steps while overlapping, and holding it loses energy (4 % in
// test/fidelity/heavy-on-light.test.ts's gas).
const PRESSED_AFTER_BOUNCING_STEPS = 3;
/** Largest condition number (max K_jj^2 / det K) of a two-point block solved as a block. */
const MAX_CONDITION_NUMBER = 1000;

/** Doubles per constraint, for the solver's memory (solver-memory.ts). */
export const CONSTRAINT_STRIDE: number = STRIDE;

/**
 * Solver-side copies of the touching contacts of one step. The numbers, body offsets and visiting
 * order live in the solver's memory (solver-memory.ts), where the WebAssembly kernel reads them
 * too; each getter returns a view that a later reserve replaces.
 */
export class ContactConstraints {
  count = 0;
  circlePairCount = 0;
  /** Constraints of this step between two moving bodies whose masses differ more than twofold. */
  heavyOnLightCount = 0;

  constructor(readonly memory: SolverMemory) {}

  /** STRIDE numbers per constraint. */
  get data(): Float64Array {
    return this.memory.constraintData;
  }
  /** State offsets (index * STATE_STRIDE) of body A and B per constraint. */
  get bodies(): Int32Array {
    return this.memory.constraintBodies;
  }
  /** The order the sub-step passes visit the constraints in (see Solver.scrambleOrder). */
  get order(): Int32Array {
    return this.memory.constraintOrder;
  }
  /** The contact data slot each constraint came from, to store impulses back. */
  get slots(): Int32Array {
    return this.memory.constraintSlots;
  }
  /** Constraints between two circles centred on their bodies: their normal follows the centres. */
  get circlePairs(): Int32Array {
    return this.memory.circlePairs;
  }

  /** Makes room for `count` constraints. */
  reserve(count: number): void {
    this.memory.reserveConstraints(count);
  }
}

/**
 * Makes a constraint of every touching contact (slots 0..`contactCount` - 1 of `contactData`) with
 * something that can move, computing effective masses, the anchors relative to each centre of
 * mass and the separation baseline from the contact's slot. Reads the bodies from `table` (see
 * body-state.ts) through the slot's world indices, and velocities from `states` (already loaded
 * with the bodies' velocities of this step's start) for restitution. Visits the contacts in slot
 * order, so the contact data streams through memory; the sub-step passes use `order`.
 */
export function prepareContacts(
  constraints: ContactConstraints,
  contactCount: number,
  contactData: Float64Array,
  contactBodies: Int32Array,
  table: Float64Array,
  states: Float64Array,
  contactSoftness: Softness,
  staticSoftness: Softness,
  dt: number,
): void {
  // Each contact is a constraint at most once: reserve for all of them.
  constraints.reserve(contactCount);
  constraints.circlePairCount = 0;
  constraints.heavyOnLightCount = 0;
  const c = constraints.data;
  const indices = constraints.bodies;
  const slots = constraints.slots;
  const circlePairs = constraints.circlePairs;
  const contactBiasRate = contactSoftness.biasRate;
  const contactMassScale = contactSoftness.massScale;
  const contactImpulseScale = contactSoftness.impulseScale;
  const staticBiasRate = staticSoftness.biasRate;
  const staticMassScale = staticSoftness.massScale;
  const staticImpulseScale = staticSoftness.impulseScale;
  let i = 0;
  for (let slot = 0; slot < contactCount; slot++) {
    const m = slot * CONTACT_STRIDE;
    // Touching: the manifold has a point (Contact.touching).
    const pointCount = contactData[m + C_POINT_COUNT]!;
    if (pointCount === 0) continue;
    const tA = contactBodies[2 * slot]! * TABLE_STRIDE;
    const tB = contactBodies[2 * slot + 1]! * TABLE_STRIDE;
    // Sleeping or static bodies are solved as immovable (slot 0, no inverse mass); awake
    // kinematic ones too.
    const indexA = table[tA + TABLE_SLOT]!;
    const indexB = table[tB + TABLE_SLOT]!;
    const mA = table[tA + TABLE_INV_MASS]!;
    const mB = table[tB + TABLE_INV_MASS]!;
    if (mA === 0 && mB === 0) continue;
    const iA = table[tA + TABLE_INV_I]!;
    const iB = table[tB + TABLE_INV_I]!;
    slots[i] = slot;
    const base = i * STRIDE;
    const a = indexA * STATE_STRIDE;
    const b = indexB * STATE_STRIDE;
    indices[2 * i] = a;
    indices[2 * i + 1] = b;
    // Stiffer against immovable bodies: nothing on the other side gives way.
    const immovable = mA === 0 || mB === 0;
    const nx = contactData[m + C_NORMAL_X]!;
    const ny = contactData[m + C_NORMAL_Y]!;
    c[base + NORMAL_X] = nx;
    c[base + NORMAL_Y] = ny;
    c[base + FRICTION] = contactData[m + C_FRICTION]!;
    c[base + RESTITUTION] = contactData[m + C_RESTITUTION]!;
    c[base + INV_MASS_A] = mA;
    c[base + INV_I_A] = iA;
    c[base + INV_MASS_B] = mB;
    c[base + INV_I_B] = iB;
    c[base + BIAS_RATE] = immovable ? staticBiasRate : contactBiasRate;
    c[base + MASS_SCALE] = immovable ? staticMassScale : contactMassScale;
    c[base + IMPULSE_SCALE] = immovable ? staticImpulseScale : contactImpulseScale;
    // Heavy on light: the soft contact's stiffness follows the heavier body's mass (softness.ts).
    if (!immovable) {
      const ratio = mA > mB ? mA / mB : mB / mA;
      if (ratio > 2) {
        constraints.heavyOnLightCount++;
        pairSoftness.setForMassRatio(contactSoftness, ratio);
        c[base + BIAS_RATE] = pairSoftness.biasRate;
        c[base + MASS_SCALE] = pairSoftness.massScale;
        c[base + IMPULSE_SCALE] = pairSoftness.impulseScale;
      }
    }
    c[base + POINT_COUNT] = pointCount;
    const pressed = contactData[m + C_BOUNCING_STEPS]! >= PRESSED_AFTER_BOUNCING_STEPS;
    const radiusA = contactData[m + C_RADIUS_A]!;
    const radiusB = contactData[m + C_RADIUS_B]!;
    const centerAX = table[tA + TABLE_CENTER_X]!;
    const centerAY = table[tA + TABLE_CENTER_Y]!;
    const centerBX = table[tB + TABLE_CENTER_X]!;
    const centerBY = table[tB + TABLE_CENTER_Y]!;
    c[base + RADIUS_A] = radiusA;
    c[base + RADIUS_B] = radiusB;
    c[base + CENTER_DX] = centerBX - centerAX;
    c[base + CENTER_DY] = centerBY - centerAY;
    c[base + REF_DP_AX] = 0;
    c[base + REF_DP_AY] = 0;
    c[base + REF_DP_BX] = 0;
    c[base + REF_DP_BY] = 0;
    if (radiusB > 0 && radiusA === 0) {
      // On the circle's line of centres, so the circle gets no torque from a normal impulse.
      c[base + SHIFT_WEIGHT_A] = 0;
      c[base + SHIFT_WEIGHT_B] = 1;
    } else {
      const total = mA + mB;
      c[base + SHIFT_WEIGHT_A] = mA / total;
      c[base + SHIFT_WEIGHT_B] = mB / total;
    }
    if (radiusA > 0 && radiusB > 0) circlePairs[constraints.circlePairCount++] = i;
    const tx = ny;
    const ty = -nx;
    const vAx = states[a + V_X]!;
    const vAy = states[a + V_Y]!;
    const wA = states[a + W]!;
    const vBx = states[b + V_X]!;
    const vBy = states[b + V_Y]!;
    const wB = states[b + W]!;
    for (let j = 0; j < pointCount; j++) {
      const mp = m + C_POINTS + j * C_POINT_STRIDE;
      const p = base + POINTS + j * POINT_STRIDE;
      const x = contactData[mp + C_X]!;
      const y = contactData[mp + C_Y]!;
      const rAx = x - centerAX;
      const rAy = y - centerAY;
      const rBx = x - centerBX;
      const rBy = y - centerBY;
      c[p + R_AX] = rAx;
      c[p + R_AY] = rAy;
      c[p + R_BX] = rBx;
      c[p + R_BY] = rBy;
      // Separation later = baseline + (change of the anchors' world positions) . n.
      c[p + BASE_SEPARATION] =
        contactData[mp + C_SEPARATION]! - ((rBx - rAx) * nx + (rBy - rAy) * ny);
      c[p + NORMAL_IMPULSE] = contactData[mp + C_NORMAL_IMPULSE]!;
      c[p + TANGENT_IMPULSE] = contactData[mp + C_TANGENT_IMPULSE]!;
      c[p + MAX_NORMAL_IMPULSE] = 0;
      c[p + TOTAL_NORMAL_IMPULSE] = 0;
      c[p + TOTAL_TANGENT_IMPULSE] = 0;
      c[p + IMPACT] = 0;
      const rnA = rAx * ny - rAy * nx;
      const rnB = rBx * ny - rBy * nx;
      c[p + RN_A] = rnA;
      c[p + RN_B] = rnB;
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
      const approach = dvx * nx + dvy * ny;
      c[p + RELATIVE_VELOCITY] = approach;
      // A pressed point (see PRESSED_AFTER_BOUNCING_STEPS) overlapping deeper than this step's
      // approach explains is a contact for this step, not an impact.
      const separation = contactData[mp + C_SEPARATION]!;
      if (pressed && separation < Math.min(approach * dt, 0) - LINEAR_SLOP) c[p + IMPACT] = 4;
    }
    c[base + BLOCK] = 0;
    if (pointCount === 2) {
      // The normal block K (the inverse mass seen by the two points together): K_jj = 1 / normal
      // mass, K_12 couples them through the bodies' rotation.
      const p1 = base + POINTS;
      const p2 = p1 + POINT_STRIDE;
      const rn1A = c[p1 + R_AX]! * ny - c[p1 + R_AY]! * nx;
      const rn1B = c[p1 + R_BX]! * ny - c[p1 + R_BY]! * nx;
      const rn2A = c[p2 + R_AX]! * ny - c[p2 + R_AY]! * nx;
      const rn2B = c[p2 + R_BX]! * ny - c[p2 + R_BY]! * nx;
      const k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
      const k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
      const k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;
      c[base + BLOCK_K11] = k11;
      c[base + BLOCK_K12] = k12;
      c[base + BLOCK_K22] = k22;
      // Condition number check (Box2D v2's b2ContactSolver, k_maxConditionNumber): two points
      // almost on top of each other make K nearly singular, and its inverse would trade huge
      // opposite impulses; those manifolds stay sequential, which is well-defined for any K.
      const kMax = Math.max(k11, k22);
      if (kMax > 0 && kMax * kMax < MAX_CONDITION_NUMBER * (k11 * k22 - k12 * k12)) {
        c[base + BLOCK] = 1;
      }
    }
    i++;
  }
  constraints.count = i;
}

/** Moves a body's pose in this step by a translation and a rotation (a bounce's catch-up). */
function advancePose(s: Float64Array, k: number, dx: number, dy: number, angle: number): void {
  s[k + DP_X] += dx;
  s[k + DP_Y] += dy;
  if (angle !== 0) {
    s[k + DELTA_ANGLE] += angle;
    const qc = s[k + Q_C]!;
    const qs = s[k + Q_S]!;
    const c = qc - angle * qs;
    const sn = qs + angle * qc;
    const inverseLength = 1 / Math.sqrt(c * c + sn * sn);
    s[k + Q_C] = c * inverseLength;
    s[k + Q_S] = sn * inverseLength;
  }
}

/**
 * Points the normal of every circle pair along the line through the two centres as they are now,
 * with lever arms along it and the separation measured exactly (|cB - cA| - rA - rB). Called at
 * each sub-step and before the relax and restitution passes: two particles then push each other
 * only through their centres, so frictionless particles never spin and the impulse's line of
 * action is the same for both (angular momentum is kept).
 */
export function refreshCirclePairs(constraints: ContactConstraints, s: Float64Array): void {
  const c = constraints.data;
  const indices = constraints.bodies;
  const list = constraints.circlePairs;
  for (let k = 0; k < constraints.circlePairCount; k++) {
    const i = list[k]!;
    const base = i * STRIDE;
    const a = indices[2 * i]!;
    const b = indices[2 * i + 1]!;
    const dpAx = s[a + DP_X]!;
    const dpAy = s[a + DP_Y]!;
    const dpBx = s[b + DP_X]!;
    const dpBy = s[b + DP_Y]!;
    const dx = c[base + CENTER_DX]! + dpBx - dpAx;
    const dy = c[base + CENTER_DY]! + dpBy - dpAy;
    const length = Math.sqrt(dx * dx + dy * dy);
    if (!(length > 1e-12)) continue; // coincident centres: keep the last normal
    const nx = dx / length;
    const ny = dy / length;
    const radiusA = c[base + RADIUS_A]!;
    const radiusB = c[base + RADIUS_B]!;
    // Both arms end at the same point, midway across the gap (or overlap), so that a friction
    // impulse too acts on one line for both particles.
    const halfGap = 0.5 * (length - radiusA - radiusB);
    const armA = radiusA + halfGap;
    const armB = radiusB + halfGap;
    const rAx = nx * armA;
    const rAy = ny * armA;
    const rBx = -nx * armB;
    const rBy = -ny * armB;
    c[base + NORMAL_X] = nx;
    c[base + NORMAL_Y] = ny;
    c[base + REF_DP_AX] = dpAx;
    c[base + REF_DP_AY] = dpAy;
    c[base + REF_DP_BX] = dpBx;
    c[base + REF_DP_BY] = dpBy;
    const p = base + POINTS;
    c[p + R_AX] = rAx;
    c[p + R_AY] = rAy;
    c[p + R_BX] = rBx;
    c[p + R_BY] = rBy;
    // Along the line of centres: no arm across n.
    c[p + RN_A] = 0;
    c[p + RN_B] = 0;
    // Baseline such that the solver's separation formula gives the exact gap now.
    const qAc = s[a + Q_C]!;
    const qAs = s[a + Q_S]!;
    const qBc = s[b + Q_C]!;
    const qBs = s[b + Q_S]!;
    const gx = dpBx - dpAx + (qBc * rBx - qBs * rBy) - (qAc * rAx - qAs * rAy);
    const gy = dpBy - dpAy + (qBs * rBx + qBc * rBy) - (qAs * rAx + qAc * rAy);
    c[p + BASE_SEPARATION] = length - radiusA - radiusB - (gx * nx + gy * ny);
    const mA = c[base + INV_MASS_A]!;
    const mB = c[base + INV_MASS_B]!;
    const kNormal = mA + mB;
    c[p + NORMAL_MASS] = kNormal > 0 ? 1 / kNormal : 0;
    const kTangent = kNormal + c[base + INV_I_A]! * armA * armA + c[base + INV_I_B]! * armB * armB;
    c[p + TANGENT_MASS] = kTangent > 0 ? 1 / kTangent : 0;
  }
}

/**
 * Applies last step's accumulated impulses, so resting contacts start where they left off; to
 * the constraints at positions `from` to `to` (exclusive) of the visiting order.
 */
export function warmStartContacts(
  constraints: ContactConstraints,
  s: Float64Array,
  from: number,
  to: number,
): void {
  const c = constraints.data;
  const indices = constraints.bodies;
  const order = constraints.order;
  for (let n = from; n < to; n++) {
    const i = order[n]!;
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
    // Lever arms to the common point of application (see prepareContacts).
    const shiftA = c[base + SHIFT_WEIGHT_A]!;
    const shiftB = c[base + SHIFT_WEIGHT_B]!;
    const dpAx = s[a + DP_X]!;
    const dpAy = s[a + DP_Y]!;
    const dpBx = s[b + DP_X]!;
    const dpBy = s[b + DP_Y]!;
    // Motion since the lever arms were set: the step's start, or a circle pair's refresh.
    const eAx = dpAx - c[base + REF_DP_AX]!;
    const eAy = dpAy - c[base + REF_DP_AY]!;
    const eBx = dpBx - c[base + REF_DP_BX]!;
    const eBy = dpBy - c[base + REF_DP_BY]!;
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
      const p = base + POINTS + j * POINT_STRIDE;
      // A bounce is a one-off impulse, not a contact force to carry into the next sub-step.
      const impact = c[p + IMPACT]!;
      if (impact === 2) {
        c[p + IMPACT] = 3;
        c[p + NORMAL_IMPULSE] = 0;
      } else if (impact === 6) {
        c[p + IMPACT] = 0;
        c[p + NORMAL_IMPULSE] = 0;
      }
      const pn = c[p + NORMAL_IMPULSE]!;
      const pt = c[p + TANGENT_IMPULSE]!;
      const px = pn * nx + pt * tx;
      const py = pn * ny + pt * ty;
      const rtA = dtA - (c[p + R_AX]! * nx + c[p + R_AY]! * ny);
      const rtB = dtB - (c[p + R_BX]! * nx + c[p + R_BY]! * ny);
      wA -= iA * (pn * (c[p + RN_A]! + dnA) + pt * rtA);
      vAx -= mA * px;
      vAy -= mA * py;
      wB += iB * (pn * (c[p + RN_B]! + dnB) + pt * rtB);
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
 * One pass over the constraints at positions `from` to `to` (exclusive) of the visiting order.
 * With `useBias` the soft position correction pushes overlapping shapes apart (at most
 * `maxPushSpeed`); without it ("relax") the pass removes the velocity that push added, so resting
 * bodies do not gain energy from correction.
 */
export function solveContacts(
  constraints: ContactConstraints,
  s: Float64Array,
  from: number,
  to: number,
  inverseH: number,
  maxPushSpeed: number,
  restitutionThreshold: number,
  impactSpeed: number,
  loadSpeed: number,
  marks: number,
  useBias: boolean,
): number {
  const c = constraints.data;
  const indices = constraints.bodies;
  const order = constraints.order;
  // Bounces in this pass (returned: the impact rounds run when there are any). A bounce marks its
  // bodies (`marks`, see body-state.ts); a bouncy resting point on a marked body that approaches
  // faster than `impactSpeed` is left for the impact rounds (see solveImpacts), not stopped here
  // as a resting contact would be (that would absorb the impact); a loaded one only when faster
  // than `loadSpeed` (see solver.ts, MIN_LOADED_IMPACT_SPEED).
  let bounces = 0;
  for (let n = from; n < to; n++) {
    const i = order[n]!;
    const base = i * STRIDE;
    const a = indices[2 * i]!;
    const b = indices[2 * i + 1]!;
    const mA = c[base + INV_MASS_A]!;
    const iA = c[base + INV_I_A]!;
    const mB = c[base + INV_MASS_B]!;
    const iB = c[base + INV_I_B]!;
    const nx = c[base + NORMAL_X]!;
    const ny = c[base + NORMAL_Y]!;
    const restitution = c[base + RESTITUTION]!;
    const biasRate = c[base + BIAS_RATE]!;
    // Received: an impact of this sub-step may push this bouncy contact (see above).
    const receives =
      !useBias &&
      restitution > 0 &&
      s[marks + a / STATE_STRIDE]! + s[marks + b / STATE_STRIDE]! > 0;
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
    // Lever arms to the common point of application (see prepareContacts), as cross products
    // with n and t (see RN_A): the prepared ones plus the shift of the common point since the
    // arms were set (the step's start, or a circle pair's refresh).
    const shiftA = c[base + SHIFT_WEIGHT_A]!;
    const shiftB = c[base + SHIFT_WEIGHT_B]!;
    const eAx = dpAx - c[base + REF_DP_AX]!;
    const eAy = dpAy - c[base + REF_DP_AY]!;
    const eBx = dpBx - c[base + REF_DP_BX]!;
    const eBy = dpBy - c[base + REF_DP_BY]!;
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
    const qAc = s[a + Q_C]!;
    const qAs = s[a + Q_S]!;
    const qBc = s[b + Q_C]!;
    const qBs = s[b + Q_S]!;
    const nAx = qAc * nx + qAs * ny;
    const nAy = qAc * ny - qAs * nx;
    const nBx = qBc * nx + qBs * ny;
    const nBy = qBc * ny - qBs * nx;
    const dpn = (dpBx - dpAx) * nx + (dpBy - dpAy) * ny;
    const pointCount = c[base + POINT_COUNT]!;

    // Two-point manifolds are solved as one block when both points are plain contacts, or both
    // bounce now; otherwise (one point waits for its impact, or K is ill-conditioned, see
    // prepareContacts) the points go one after the other below.
    let firstSequential = 0;
    if (c[base + BLOCK]! === 1) {
      const p1 = base + POINTS;
      const p2 = p1 + POINT_STRIDE;
      const separation1 =
        dpn +
        (c[p1 + R_BX]! * nBx + c[p1 + R_BY]! * nBy) -
        (c[p1 + R_AX]! * nAx + c[p1 + R_AY]! * nAy) +
        c[p1 + BASE_SEPARATION]!;
      const separation2 =
        dpn +
        (c[p2 + R_BX]! * nBx + c[p2 + R_BY]! * nBy) -
        (c[p2 + R_AX]! * nAx + c[p2 + R_AY]! * nAy) +
        c[p2 + BASE_SEPARATION]!;
      const n1A = c[p1 + RN_A]! + dnA;
      const n1B = c[p1 + RN_B]! + dnB;
      const n2A = c[p2 + RN_A]! + dnA;
      const n2B = c[p2 + RN_B]! + dnB;
      const k11 = c[base + BLOCK_K11]!;
      const k12 = c[base + BLOCK_K12]!;
      const k22 = c[base + BLOCK_K22]!;
      // Each point's target as in the sequential pass below: bias, and the softness gamma.
      let bias1 = 0;
      let gamma1 = 0;
      if (separation1 > 0) bias1 = separation1 * inverseH;
      else if (useBias) {
        bias1 = Math.max(biasRate * separation1, -maxPushSpeed);
        gamma1 = (k11 * c[base + IMPULSE_SCALE]!) / c[base + MASS_SCALE]!;
      }
      let bias2 = 0;
      let gamma2 = 0;
      if (separation2 > 0) bias2 = separation2 * inverseH;
      else if (useBias) {
        bias2 = Math.max(biasRate * separation2, -maxPushSpeed);
        gamma2 = (k22 * c[base + IMPULSE_SCALE]!) / c[base + MASS_SCALE]!;
      }
      const dvn = (vBx - vAx) * nx + (vBy - vAy) * ny;
      const vn1 = dvn + wB * n1B - wA * n1A;
      const vn2 = dvn + wB * n2B - wA * n2A;
      const accumulated1 = c[p1 + NORMAL_IMPULSE]!;
      const accumulated2 = c[p2 + NORMAL_IMPULSE]!;
      // The impact test of the sequential pass (see there), on the velocities before the pass.
      let isImpact1 = false;
      let isImpact2 = false;
      if (restitution > 0) {
        const impact1 = c[p1 + IMPACT]!;
        const impact2 = c[p2 + IMPACT]!;
        isImpact1 =
          accumulated1 === 0 &&
          (impact1 < 2 || impact1 === 3 || (impact1 === 4 && vn1 < -maxPushSpeed)) &&
          vn1 < -restitutionThreshold &&
          (impact1 === 1 || vn1 + bias1 < 0);
        isImpact2 =
          accumulated2 === 0 &&
          (impact2 < 2 || impact2 === 3 || (impact2 === 4 && vn2 < -maxPushSpeed)) &&
          vn2 < -restitutionThreshold &&
          (impact2 === 1 || vn2 + bias2 < 0);
      }
      if (
        receives &&
        !isImpact1 &&
        !isImpact2 &&
        (vn1 < -loadSpeed || vn2 < -loadSpeed) &&
        c[p1 + IMPACT]! !== 4 &&
        c[p2 + IMPACT]! !== 4
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
        // A is better conditioned than K, so the check on K in prepareContacts covers it.
        const a11 = k11 + gamma1;
        const a22 = k22 + gamma2;
        const q1 = vn1 + bias1 - (k11 * accumulated1 + k12 * accumulated2);
        const q2 = vn2 + bias2 - (k12 * accumulated1 + k22 * accumulated2);
        let x1 = -1;
        let x2 = -1;
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
              // Case 4: both separate.
              x1 = 0;
              x2 = 0;
            }
          }
        }
        // Rounding can leave no case satisfied (a nearly degenerate K): then sequential below.
        if (x1 >= 0 && x2 >= 0) {
          firstSequential = 2;
          if (restitution > 0) {
            if (c[p1 + IMPACT]! === 1) c[p1 + IMPACT] = 0;
            if (c[p2 + IMPACT]! === 1) c[p2 + IMPACT] = 0;
          }
          const dx1 = x1 - accumulated1;
          const dx2 = x2 - accumulated2;
          c[p1 + NORMAL_IMPULSE] = x1;
          c[p2 + NORMAL_IMPULSE] = x2;
          if (!useBias) {
            c[p1 + TOTAL_NORMAL_IMPULSE] += x1;
            c[p2 + TOTAL_NORMAL_IMPULSE] += x2;
          }
          if (dx1 > c[p1 + MAX_NORMAL_IMPULSE]!) c[p1 + MAX_NORMAL_IMPULSE] = dx1;
          if (dx2 > c[p2 + MAX_NORMAL_IMPULSE]!) c[p2 + MAX_NORMAL_IMPULSE] = dx2;
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
        const back = Math.min(0.5 * (separation1 / vn1 + separation2 / vn2), 1 / inverseH);
        const tAx = dpAx - vAx * back;
        const tAy = dpAy - vAy * back;
        const tBx = dpBx - vBx * back;
        const tBy = dpBy - vBy * back;
        const eAx = tAx - c[base + REF_DP_AX]!;
        const eAy = tAy - c[base + REF_DP_AY]!;
        const eBx = tBx - c[base + REF_DP_BX]!;
        const eBy = tBy - c[base + REF_DP_BY]!;
        const sx = shiftA * eAx + shiftB * eBx;
        const sy = shiftA * eAy + shiftB * eBy;
        const b1Ax = c[p1 + R_AX]! + sx - eAx;
        const b1Ay = c[p1 + R_AY]! + sy - eAy;
        const b1Bx = c[p1 + R_BX]! + sx - eBx;
        const b1By = c[p1 + R_BY]! + sy - eBy;
        const b2Ax = c[p2 + R_AX]! + sx - eAx;
        const b2Ay = c[p2 + R_AY]! + sy - eAy;
        const b2Bx = c[p2 + R_BX]! + sx - eBx;
        const b2By = c[p2 + R_BY]! + sy - eBy;
        const approach1 =
          (vBx - wB * b1By - (vAx - wA * b1Ay)) * nx + (vBy + wB * b1Bx - (vAy + wA * b1Ax)) * ny;
        const approach2 =
          (vBx - wB * b2By - (vAx - wA * b2Ay)) * nx + (vBy + wB * b2Bx - (vAy + wA * b2Ax)) * ny;
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
        let x1 = -1;
        let x2 = -1;
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
          c[p1 + NORMAL_IMPULSE] = x1;
          c[p2 + NORMAL_IMPULSE] = x2;
          c[p1 + TOTAL_NORMAL_IMPULSE] += x1;
          c[p2 + TOTAL_NORMAL_IMPULSE] += x2;
          c[p1 + RELATIVE_VELOCITY] = approach1;
          c[p2 + RELATIVE_VELOCITY] = approach2;
          c[p1 + IMPACT] = 2;
          c[p2 + IMPACT] = 2;
          if (x1 > c[p1 + MAX_NORMAL_IMPULSE]!) c[p1 + MAX_NORMAL_IMPULSE] = x1;
          if (x2 > c[p2 + MAX_NORMAL_IMPULSE]!) c[p2 + MAX_NORMAL_IMPULSE] = x2;
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
          if (a !== 0) advancePose(s, a, dvAx * back, dvAy * back, dwA * back);
          if (b !== 0) advancePose(s, b, dvBx * back, dvBy * back, dwB * back);
          bounced = true;
        }
      }
    }

    for (let j = firstSequential; j < pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      // Current separation: the anchors moved with their bodies since the step began.
      const separation =
        dpn +
        (c[p + R_BX]! * nBx + c[p + R_BY]! * nBy) -
        (c[p + R_AX]! * nAx + c[p + R_AY]! * nAy) +
        c[p + BASE_SEPARATION]!;
      const leverA = c[p + RN_A]! + dnA;
      const leverB = c[p + RN_B]! + dnB;
      let bias = 0;
      let massScale = 1;
      let impulseScale = 0;
      if (separation > 0) {
        // Speculative: allow closing exactly the gap within this sub-step, no more.
        bias = separation * inverseH;
      } else if (useBias) {
        bias = Math.max(biasRate * separation, -maxPushSpeed);
        massScale = c[base + MASS_SCALE]!;
        impulseScale = c[base + IMPULSE_SCALE]!;
      }
      const vn = (vBx - vAx) * nx + (vBy - vAy) * ny + wB * leverB - wA * leverA;
      const accumulated = c[p + NORMAL_IMPULSE]!;
      // Restitution (Newton's law) at the moment of impact. An impact is an approach faster than
      // the threshold on a point not already pushing, and not pressed (unless it approaches faster
      // than a load presses: an impact that travelled to it, see solveImpacts) (a resting contact is always warm-started,
      // so it never counts, and never jitters). The solve pass lets it go; the relax pass, once
      // the shapes touch, applies the whole collision impulse -(1 + e) m vn along the normal of
      // that instant, and moves both bodies on by their velocity change for the part of the
      // sub-step left after the moment of contact: the exact trajectory of two colliding
      // bodies, so momentum, angular momentum and (for e = 1) energy are kept. A bounce after all
      // the sub-steps (Box2D v3) comes after the normal of sliding particles has turned and after
      // gravity has changed the approach, and cannot bounce a particle twice in one step.
      if (restitution > 0) {
        const impactState = c[p + IMPACT]!;
        if (
          accumulated === 0 &&
          (impactState < 2 || impactState === 3 || (impactState === 4 && vn < -maxPushSpeed)) &&
          vn < -restitutionThreshold &&
          (impactState === 1 || vn + bias < 0)
        ) {
          if (useBias || separation > 0) {
            // Not touching yet: the impact happens when the positions get there.
            c[p + IMPACT] = useBias ? 1 : 0;
            continue;
          }
          // Back to the moment of contact: the overlap divided by the approach speed ago.
          const back = Math.min(separation / vn, 1 / inverseH);
          const tAx = dpAx - vAx * back;
          const tAy = dpAy - vAy * back;
          const tBx = dpBx - vBx * back;
          const tBy = dpBy - vBy * back;
          let bnx = nx;
          let bny = ny;
          let bAx: number;
          let bAy: number;
          let bBx: number;
          let bBy: number;
          const radiusA = c[base + RADIUS_A]!;
          const radiusB = c[base + RADIUS_B]!;
          if (radiusA > 0 && radiusB > 0) {
            // Two particles meet along the line through their centres at that moment.
            const cx = c[base + CENTER_DX]! + tBx - tAx;
            const cy = c[base + CENTER_DY]! + tBy - tAy;
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
            // The common point of application, where it was at that moment.
            const eAx = tAx - c[base + REF_DP_AX]!;
            const eAy = tAy - c[base + REF_DP_AY]!;
            const eBx = tBx - c[base + REF_DP_BX]!;
            const eBy = tBy - c[base + REF_DP_BY]!;
            const sx = shiftA * eAx + shiftB * eBx;
            const sy = shiftA * eAy + shiftB * eBy;
            bAx = c[p + R_AX]! + sx - eAx;
            bAy = c[p + R_AY]! + sy - eAy;
            bBx = c[p + R_BX]! + sx - eBx;
            bBy = c[p + R_BY]! + sy - eBy;
          }
          const approach =
            (vBx - wB * bBy - (vAx - wA * bAy)) * bnx + (vBy + wB * bBx - (vAy + wA * bAx)) * bny;
          const rnA = bAx * bny - bAy * bnx;
          const rnB = bBx * bny - bBy * bnx;
          const k = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
          const bounce = approach < 0 && k > 0 ? (-(1 + restitution) * approach) / k : 0;
          c[p + NORMAL_IMPULSE] = bounce;
          c[p + TOTAL_NORMAL_IMPULSE] += bounce;
          c[p + RELATIVE_VELOCITY] = approach;
          c[p + IMPACT] = 2;
          if (bounce > c[p + MAX_NORMAL_IMPULSE]!) c[p + MAX_NORMAL_IMPULSE] = bounce;
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
          // And forward again with the new velocities: the exact path of the collision.
          if (a !== 0) advancePose(s, a, dvAx * back, dvAy * back, dwA * back);
          if (b !== 0) advancePose(s, b, dvBx * back, dvBy * back, dwB * back);
          bounced = true;
          continue;
        }
        if (impactState === 1) c[p + IMPACT] = 0;
        if (receives && impactState !== 4 && vn < -(accumulated > 0 ? loadSpeed : impactSpeed)) {
          continue;
        }
      }
      const newImpulse = Math.max(
        accumulated - c[p + NORMAL_MASS]! * massScale * (vn + bias) - impulseScale * accumulated,
        0,
      );
      const impulse = newImpulse - accumulated;
      c[p + NORMAL_IMPULSE] = newImpulse;
      // The relax pass ends the sub-step: the accumulated impulse is what acted in it.
      if (!useBias) c[p + TOTAL_NORMAL_IMPULSE] += newImpulse;
      if (impulse > c[p + MAX_NORMAL_IMPULSE]!) c[p + MAX_NORMAL_IMPULSE] = impulse;
      vAx -= mA * impulse * nx;
      vAy -= mA * impulse * ny;
      wA -= iA * leverA * impulse;
      vBx += mB * impulse * nx;
      vBy += mB * impulse * ny;
      wB += iB * leverB * impulse;
    }

    if (bounced) {
      bounces++;
      if (a !== 0) s[marks + a / STATE_STRIDE] = 1;
      if (b !== 0) s[marks + b / STATE_STRIDE] = 1;
      // The bounce moved the bodies on: friction acts at the common point where it is now.
      const eAx = s[a + DP_X]! - c[base + REF_DP_AX]!;
      const eAy = s[a + DP_Y]! - c[base + REF_DP_AY]!;
      const eBx = s[b + DP_X]! - c[base + REF_DP_BX]!;
      const eBy = s[b + DP_Y]! - c[base + REF_DP_BY]!;
      const sx = shiftA * eAx + shiftB * eBx;
      const sy = shiftA * eAy + shiftB * eBy;
      sAx = sx - eAx;
      sAy = sy - eAy;
      sBx = sx - eBx;
      sBy = sy - eBy;
    }
    const dtA = -(sAx * nx + sAy * ny);
    const dtB = -(sBx * nx + sBy * ny);
    const friction = c[base + FRICTION]!;
    for (let j = 0; j < pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      const leverA = dtA - (c[p + R_AX]! * nx + c[p + R_AY]! * ny);
      const leverB = dtB - (c[p + R_BX]! * nx + c[p + R_BY]! * ny);
      // Slip along t = (ny, -nx).
      const vt = (vBx - vAx) * ny - (vBy - vAy) * nx + wB * leverB - wA * leverA;
      const accumulated = c[p + TANGENT_IMPULSE]!;
      const maxFriction = friction * c[p + NORMAL_IMPULSE]!;
      let newImpulse = accumulated - c[p + TANGENT_MASS]! * vt;
      if (newImpulse > maxFriction) newImpulse = maxFriction;
      else if (newImpulse < -maxFriction) newImpulse = -maxFriction;
      const impulse = newImpulse - accumulated;
      c[p + TANGENT_IMPULSE] = newImpulse;
      if (!useBias) c[p + TOTAL_TANGENT_IMPULSE] += newImpulse;
      vAx -= mA * impulse * ny;
      vAy += mA * impulse * nx;
      wA -= iA * leverA * impulse;
      vBx += mB * impulse * ny;
      vBy -= mB * impulse * nx;
      wB += iB * leverB * impulse;
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
// touching contact that approaches faster than the impact speed is an impact of its own and
// leaves at e times the approach it received, with the masses of its two bodies (a two-point
// manifold as one block). Each such impact keeps momentum and angular momentum, keeps the
// energy at e = 1, and at e = 0 stops the approach as an inelastic collision does; a chain of
// them is the sequential-impact solution (a ball dropped on an equal ball resting on the floor
// rebounds to its drop height, the bottom one stays). Kept of the paper's properties: momentum,
// energy (e = 1: never gained; e < 1: lost), and breaking of contact along the chain; given up:
// symmetry of truly simultaneous impacts (the round visits contacts in the solver's order).
// Joints: a lone bounce of the relax pass and the joints are solved together, a few Gauss-Seidel
// iterations, the impact towards its target (-e times its approach), so that a disc hitting a
// pinned rod sees the rod's pinned effective mass. Not the rounds' impacts, nor several bounces at
// once: impacts of one chain solved together towards fixed targets make energy. Resting contacts that no impact reaches are
// never visited by an impact (they approach slower than the impact speed), so stacks stay at rest
// and sleep; steps without a bounce run no round at all.

/** solveImpacts' modes. */
export const IMPACT_ROUND = 0;
export const IMPACT_CONTINUE = 1;
export const IMPACT_OPEN = 2;
export const IMPACT_CLOSE = 3;

/**
 * One pass of the impact rounds over the constraints at positions `from` to `to` of the visiting
 * order (see the note above); returns the number of impacts it started. `IMPACT_ROUND` closes the
 * last round's impacts and starts a new one: each touching point of a body an impact reached
 * (`marks`) approaching faster than `impactSpeed` (a loaded point: `loadSpeed`) gets -(1 + e)
 * times its approach, with its bodies' masses. `IMPACT_CONTINUE`
 * moves the open impacts on towards their targets (between joint passes); `IMPACT_OPEN` opens the
 * bounces of the relax pass for that; `IMPACT_CLOSE` closes all.
 */
export function solveImpacts(
  constraints: ContactConstraints,
  s: Float64Array,
  from: number,
  to: number,
  impactSpeed: number,
  loadSpeed: number,
  marks: number,
  mode: number,
): number {
  const c = constraints.data;
  const indices = constraints.bodies;
  const order = constraints.order;
  let impacts = 0;
  for (let n = from; n < to; n++) {
    const i = order[n]!;
    const base = i * STRIDE;
    const pointCount = c[base + POINT_COUNT]!;
    if (mode === IMPACT_OPEN || mode === IMPACT_CLOSE || mode === IMPACT_ROUND) {
      // States only: open (bounced in this sub-step -> in the round) or close (the reverse).
      const from2 = mode === IMPACT_OPEN ? 2 : 5;
      const to2 = mode === IMPACT_OPEN ? 5 : 2;
      for (let j = 0; j < pointCount; j++) {
        const p = base + POINTS + j * POINT_STRIDE;
        if (c[p + IMPACT]! === from2) {
          c[p + IMPACT] = to2;
          if (mode === IMPACT_OPEN) impacts++;
        }
      }
      if (mode === IMPACT_OPEN) continue;
    }
    const a = indices[2 * i]!;
    const b = indices[2 * i + 1]!;
    const markA = marks + a / STATE_STRIDE;
    const markB = marks + b / STATE_STRIDE;
    if (mode === IMPACT_CLOSE) {
      s[markA] = 0;
      s[markB] = 0;
      continue;
    }
    // Only contacts an impact has reached (a marked body): the rest of the world is not touched.
    if (mode === IMPACT_ROUND && s[markA]! + s[markB]! === 0) continue;
    const mA = c[base + INV_MASS_A]!;
    const iA = c[base + INV_I_A]!;
    const mB = c[base + INV_MASS_B]!;
    const iB = c[base + INV_I_B]!;
    const nx = c[base + NORMAL_X]!;
    const ny = c[base + NORMAL_Y]!;
    const restitution = c[base + RESTITUTION]!;
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
    // Lever arms and separations as in solveContacts.
    const shiftA = c[base + SHIFT_WEIGHT_A]!;
    const shiftB = c[base + SHIFT_WEIGHT_B]!;
    const eAx = dpAx - c[base + REF_DP_AX]!;
    const eAy = dpAy - c[base + REF_DP_AY]!;
    const eBx = dpBx - c[base + REF_DP_BX]!;
    const eBy = dpBy - c[base + REF_DP_BY]!;
    const shiftX = shiftA * eAx + shiftB * eBx;
    const shiftY = shiftA * eAy + shiftB * eBy;
    const dnA = (shiftX - eAx) * ny - (shiftY - eAy) * nx;
    const dnB = (shiftX - eBx) * ny - (shiftY - eBy) * nx;
    const qAc = s[a + Q_C]!;
    const qAs = s[a + Q_S]!;
    const qBc = s[b + Q_C]!;
    const qBs = s[b + Q_S]!;
    const nAx = qAc * nx + qAs * ny;
    const nAy = qAc * ny - qAs * nx;
    const nBx = qBc * nx + qBs * ny;
    const nBy = qBc * ny - qBs * nx;
    const dpn = (dpBx - dpAx) * nx + (dpBy - dpAy) * ny;
    let firstSequential = 0;
    if (mode === IMPACT_ROUND && c[base + BLOCK]! === 1) {
      // Both points of a face on a face approaching: one impact, solved as a block (the LCP
      // w = K x + (1 + e) vn >= 0, x >= 0, x . w = 0; cases as in solveContacts), so a flat
      // impact stays flat.
      const p1 = base + POINTS;
      const p2 = p1 + POINT_STRIDE;
      const separation1 =
        dpn +
        (c[p1 + R_BX]! * nBx + c[p1 + R_BY]! * nBy) -
        (c[p1 + R_AX]! * nAx + c[p1 + R_AY]! * nAy) +
        c[p1 + BASE_SEPARATION]!;
      const separation2 =
        dpn +
        (c[p2 + R_BX]! * nBx + c[p2 + R_BY]! * nBy) -
        (c[p2 + R_AX]! * nAx + c[p2 + R_AY]! * nAy) +
        c[p2 + BASE_SEPARATION]!;
      const n1A = c[p1 + RN_A]! + dnA;
      const n1B = c[p1 + RN_B]! + dnB;
      const n2A = c[p2 + RN_A]! + dnA;
      const n2B = c[p2 + RN_B]! + dnB;
      const dvn = (vBx - vAx) * nx + (vBy - vAy) * ny;
      const vn1 = dvn + wB * n1B - wA * n1A;
      const vn2 = dvn + wB * n2B - wA * n2A;
      const speed1 = c[p1 + NORMAL_IMPULSE]! > 0 && c[p1 + IMPACT]! !== 2 ? loadSpeed : impactSpeed;
      const speed2 = c[p2 + NORMAL_IMPULSE]! > 0 && c[p2 + IMPACT]! !== 2 ? loadSpeed : impactSpeed;
      if (
        separation1 < LINEAR_SLOP &&
        separation2 < LINEAR_SLOP &&
        vn1 < -speed1 &&
        vn2 < -speed2 &&
        c[p1 + IMPACT]! !== 4 &&
        c[p2 + IMPACT]! !== 4
      ) {
        // K from the levers as they are now, as the impulses are applied: then an e = 1 impact
        // keeps the energy exactly.
        const mAB = mA + mB;
        const k11 = mAB + iA * n1A * n1A + iB * n1B * n1B;
        const k12 = mAB + iA * n1A * n2A + iB * n1B * n2B;
        const k22 = mAB + iA * n2A * n2A + iB * n2B * n2B;
        const q1 = (1 + restitution) * vn1;
        const q2 = (1 + restitution) * vn2;
        let x1 = -1;
        let x2 = -1;
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
          impacts++;
          c[p1 + NORMAL_IMPULSE] += x1;
          c[p2 + NORMAL_IMPULSE] += x2;
          c[p1 + TOTAL_NORMAL_IMPULSE] += x1;
          c[p2 + TOTAL_NORMAL_IMPULSE] += x2;
          if (x1 > c[p1 + MAX_NORMAL_IMPULSE]!) c[p1 + MAX_NORMAL_IMPULSE] = x1;
          if (x2 > c[p2 + MAX_NORMAL_IMPULSE]!) c[p2 + MAX_NORMAL_IMPULSE] = x2;
          c[p1 + RELATIVE_VELOCITY] = vn1;
          c[p2 + RELATIVE_VELOCITY] = vn2;
          c[p1 + IMPACT] = 5;
          c[p2 + IMPACT] = 5;
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
    let changed = firstSequential === 2;
    for (let j = firstSequential; j < pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      const impact = c[p + IMPACT]!;
      if (mode === IMPACT_CONTINUE ? impact !== 5 : impact === 4 || impact === 5) continue;
      const leverA = c[p + RN_A]! + dnA;
      const leverB = c[p + RN_B]! + dnB;
      const vn = (vBx - vAx) * nx + (vBy - vAy) * ny + wB * leverB - wA * leverA;
      const accumulated = c[p + NORMAL_IMPULSE]!;
      // The effective mass with the levers as they are now (see the block above).
      const k = mA + mB + iA * leverA * leverA + iB * leverB * leverB;
      if (!(k > 0)) continue;
      let impulse: number;
      if (mode === IMPACT_CONTINUE) {
        // Towards the target -e * approach, the impulse of this impact never below zero.
        const target = -restitution * c[p + RELATIVE_VELOCITY]!;
        impulse = Math.max((target - vn) / k, -accumulated);
      } else {
        // A loaded point (pushing, not a bounce of this sub-step) only when it approaches faster
        // than a load presses (see solveContacts).
        if (vn >= -(accumulated > 0 && impact !== 2 ? loadSpeed : impactSpeed)) continue;
        const separation =
          dpn +
          (c[p + R_BX]! * nBx + c[p + R_BY]! * nBy) -
          (c[p + R_AX]! * nAx + c[p + R_AY]! * nAy) +
          c[p + BASE_SEPARATION]!;
        if (separation >= LINEAR_SLOP) continue;
        impulse = (-(1 + restitution) * vn) / k;
        impacts++;
        c[p + RELATIVE_VELOCITY] = vn;
        c[p + IMPACT] = 5;
        if (impulse > c[p + MAX_NORMAL_IMPULSE]!) c[p + MAX_NORMAL_IMPULSE] = impulse;
      }
      c[p + NORMAL_IMPULSE] = accumulated + impulse;
      c[p + TOTAL_NORMAL_IMPULSE] += impulse;
      vAx -= mA * impulse * nx;
      vAy -= mA * impulse * ny;
      wA -= iA * leverA * impulse;
      vBx += mB * impulse * nx;
      vBy += mB * impulse * ny;
      wB += iB * leverB * impulse;
      changed = true;
    }
    if (!changed) continue;
    if (a !== 0) {
      s[a + V_X] = vAx;
      s[a + V_Y] = vAy;
      s[a + W] = wA;
      s[markA] = 1;
    }
    if (b !== 0) {
      s[b + V_X] = vBx;
      s[b + V_Y] = vBy;
      s[b + W] = wB;
      s[markB] = 1;
    }
  }
  return impacts;
}

/**
 * Copies the accumulated impulses back to the contacts' slots for warm starting, and the impulses
 * the step delivered (sum over the sub-steps, plus restitution) for events.
 */
export function storeImpulses(
  constraints: ContactConstraints,
  contactData: Float64Array,
  from: number,
  to: number,
): void {
  const c = constraints.data;
  const slots = constraints.slots;
  const order = constraints.order;
  for (let n = from; n < to; n++) {
    const i = order[n]!;
    const base = i * STRIDE;
    const m = slots[i]! * CONTACT_STRIDE;
    const pointCount = c[base + POINT_COUNT]!;
    let bounced = 0;
    for (let j = 0; j < pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      const mp = m + C_POINTS + j * C_POINT_STRIDE;
      const impact = c[p + IMPACT]!;
      if (impact === 2 || impact === 3) bounced = 1;
      contactData[mp + C_NORMAL_IMPULSE] =
        impact === 2 || impact === 6 ? 0 : c[p + NORMAL_IMPULSE]!;
      contactData[mp + C_TANGENT_IMPULSE] = c[p + TANGENT_IMPULSE]!;
      contactData[mp + C_MAX_NORMAL_IMPULSE] = c[p + MAX_NORMAL_IMPULSE]!;
      contactData[mp + C_RELATIVE_VELOCITY] = c[p + RELATIVE_VELOCITY]!;
      contactData[mp + C_STEP_NORMAL_IMPULSE] = c[p + TOTAL_NORMAL_IMPULSE]!;
      contactData[mp + C_STEP_TANGENT_IMPULSE] = c[p + TOTAL_TANGENT_IMPULSE]!;
    }
    contactData[m + C_BOUNCING_STEPS] = bounced === 1 ? contactData[m + C_BOUNCING_STEPS]! + 1 : 0;
  }
}

// Shock propagation for heavy bodies resting on light ones (Guendelman, Bridson and Fedkiw,
// "Nonconvex rigid bodies with stacking", SIGGRAPH 2003, section 7; Erleben's thesis, 2004).
//
// Why: sequential impulses move a heavy body by m_light / m_heavy of what a contact under it asks
// per pass, because the light body in between takes the rest; at 1000:1 a heavy box sinks a
// quarter of a metre into the 1 kg box it stands on, in every engine we measured.
//
// What: once per step the bodies are ordered by how many contacts separate them from the ground
// (static, sleeping or kinematic bodies). After the solve and after the relax pass of each
// sub-step, a sweep visits each contact where a heavy body rests on a lighter one (more than
// twice lighter, already pushing last step, normal within 60 degrees of up), and the contacts
// under it down to the ground, from the ground up, and removes what approach is left as if the
// lower body could not move: the heavy body stops on the light one at once. The sweep moves only
// upper bodies and is not accumulated: the forces stay the ordinary passes' (the swept contacts
// are rigid there and visited last, ground up, so the weight reaches the ground in a few steps).
// Steps without such a contact pay nothing; stacks of like bodies, impacts and free collisions
// are solved as before.
//
// It lives here because it reads the constraint layout above, whose offsets stay module-local
// constants: V8 does not fold exported module constants into the solver's loops (7 % of a
// pyramid's step on the unbundled build, measured).

/** The sweep of one step: which constraints, in which order, and which side is below. */
/** Slip (m/s) the sweep's friction leaves to the ordinary passes. */
const SWEEP_SLIP = 1e-3;

export class ShockPropagation {
  /** Constraints to sweep (the first `count`), from the top down: swept backwards. */
  order: Int32Array = new Int32Array(64);
  /** 1 where the constraint's body A is the lower one, per entry of `order`. */
  lowerIsA: Uint8Array = new Uint8Array(64);
  /** Per entry of `order`: the contact's restitution while its bounce is due (at first touch). */
  private restitution: Float64Array = new Float64Array(64);
  count = 0;
  // Scratch: a level per solver slot, and a flag per slot (supports a swept contact) and per
  // constraint (swept).
  private level: Int32Array = new Int32Array(64);
  private supports: Uint8Array = new Uint8Array(64);
  private swept: Uint8Array = new Uint8Array(64);
  // Per constraint: its two solver slots, its rank (see prepare); the resting constraints.
  private ends: Int32Array = new Int32Array(128);
  private rank: Int32Array = new Int32Array(64);
  private edges: Int32Array = new Int32Array(64);

  /**
   * Finds the contacts to sweep for this step's constraints; `bodyCount` is the number of awake
   * bodies (solver slots 1..bodyCount; slot 0 is every immovable body). The swept contacts push
   * out overlap at `biasRate`, as contacts with the ground do.
   */
  prepare(
    constraints: ContactConstraints,
    bodyCount: number,
    biasRate: number,
    gravityX: number,
    gravityY: number,
  ): void {
    this.count = 0;
    const gravity = Math.hypot(gravityX, gravityY);
    if (constraints.heavyOnLightCount === 0 || gravity === 0) return;
    const count = constraints.count;
    const c = constraints.data;
    const indices = constraints.bodies;
    if (this.level.length <= bodyCount) {
      this.level = new Int32Array(2 * bodyCount + 2);
      this.supports = new Uint8Array(2 * bodyCount + 2);
    }
    if (this.swept.length < count) {
      this.swept = new Uint8Array(2 * count);
      this.order = new Int32Array(2 * count);
      this.lowerIsA = new Uint8Array(2 * count);
      this.restitution = new Float64Array(2 * count);
      this.ends = new Int32Array(4 * count);
      this.rank = new Int32Array(2 * count);
      this.edges = new Int32Array(2 * count);
    }
    const level = this.level;
    const supports = this.supports;
    const swept = this.swept;
    const ends = this.ends;
    const rank = this.rank;
    const edges = this.edges;

    // Each constraint's two solver slots (immovable bodies are slot 0), and the resting ones
    // (pushing since last step): only they hold a body up.
    let edgeCount = 0;
    for (let i = 0; i < count; i++) {
      const base = i * STRIDE;
      ends[2 * i] = c[base + INV_MASS_A] === 0 ? 0 : indices[2 * i]! / STATE_STRIDE;
      ends[2 * i + 1] = c[base + INV_MASS_B] === 0 ? 0 : indices[2 * i + 1]! / STATE_STRIDE;
      if (this.resting(c, i)) edges[edgeCount++] = i;
    }
    // Levels: resting contacts from the ground (slot 0), relaxed until no level shrinks (a stack
    // of n bodies takes at most n sweeps of the resting contacts). A body that only bounces or
    // flies has none: nothing holds it up.
    const far = 1 << 30;
    level.fill(far, 0, bodyCount + 1);
    level[0] = 0;
    for (let changed = true; changed;) {
      changed = false;
      for (let e = 0; e < edgeCount; e++) {
        const i = edges[e]!;
        const na = ends[2 * i]!;
        const nb = ends[2 * i + 1]!;
        const la = level[na]!;
        const lb = level[nb]!;
        if (la + 1 < lb) level[nb] = la + 1;
        else if (lb + 1 < la) level[na] = lb + 1;
        else continue;
        changed = true;
      }
    }
    // A contact's rank: its lower body's level + 1 (0 between equal or unheld bodies).
    let maxRank = 0;
    for (let i = 0; i < count; i++) {
      const la = level[ends[2 * i]!]!;
      const lb = level[ends[2 * i + 1]!]!;
      const r = la === lb || Math.min(la, lb) === far ? 0 : Math.min(la, lb) + 1;
      rank[i] = r;
      if (r > maxRank) maxRank = r;
    }

    // From the top down: a heavy-on-light contact on a resting light body is swept, and so is
    // every resting contact under a body that a swept contact stands on (down to the ground), so
    // the sweep starts from solid ground.
    supports.fill(0, 0, bodyCount + 1);
    swept.fill(0, 0, count);
    for (let k = maxRank; k >= 1; k--) {
      for (let i = 0; i < count; i++) {
        if (rank[i] !== k) continue;
        const aLower = level[ends[2 * i]!]! < level[ends[2 * i + 1]!]!;
        const lower = ends[2 * i + (aLower ? 0 : 1)]!;
        const upper = ends[2 * i + (aLower ? 1 : 0)]!;
        const base = i * STRIDE;
        const mLower = c[base + (aLower ? INV_MASS_A : INV_MASS_B)]!;
        const mUpper = c[base + (aLower ? INV_MASS_B : INV_MASS_A)]!;
        // Heavy on light: the lower body more than twice lighter, the normal within 60 degrees of
        // up (a body beside another is not resting on it).
        const up =
          (aLower ? -1 : 1) * (c[base + NORMAL_X]! * gravityX + c[base + NORMAL_Y]! * gravityY);
        const heavyOnLight = mLower > 2 * mUpper && up >= 0.5 * gravity;
        if (heavyOnLight || (supports[upper] === 1 && level[upper] === k && this.resting(c, i))) {
          swept[i] = 1;
          supports[lower] = 1;
          // Listed from the top down; the sweeps read the list backwards, ground up.
          this.order[this.count] = i;
          this.lowerIsA[this.count] = aLower ? 1 : 0;
          // A contact approaching at the step's start may bounce (restitution), once, at first
          // touch (a resting one does not approach: the last relax pass stopped it). A heavy
          // body bounces off the light one here, not in the contact solver: there, its bounce
          // would send the light body into the ground, again each sub-step.
          this.restitution[this.count++] = c[base + RESTITUTION]!;
          if (heavyOnLight) c[base + RESTITUTION] = 0;
          // Rigid in the ordinary passes: a soft contact lets its impulse leak each pass, so the
          // weight above would not reach the ground.
          c[base + BIAS_RATE] = biasRate;
          c[base + MASS_SCALE] = 1;
          c[base + IMPULSE_SCALE] = 0;
        }
      }
    }
    // The ordinary passes visit the swept contacts last, ground up (see the note above).
    const order = constraints.order;
    let kept = 0;
    for (let n = 0; n < count; n++) {
      const i = order[n]!;
      if (swept[i] === 0) order[kept++] = i;
    }
    for (let n = this.count - 1; n >= 0; n--) order[kept++] = this.order[n]!;
  }

  /**
   * Sweeps the prepared contacts once: each upper body stops approaching the body below it, as if
   * that body could not move. With `useBias`, overlap is pushed out at `biasRate` (at most
   * `maxPushSpeed`), as against the ground; without, only the approach is removed (relax pass).
   * A new contact faster than `restitutionThreshold` bounces at its first touch.
   */
  solve(
    constraints: ContactConstraints,
    s: Float64Array,
    inverseH: number,
    biasRate: number,
    maxPushSpeed: number,
    restitutionThreshold: number,
    useBias: boolean,
  ): void {
    const c = constraints.data;
    const indices = constraints.bodies;
    for (let n = this.count - 1; n >= 0; n--) {
      const restitution = this.restitution[n]!;
      const bounce = restitution > 0;
      let wait = false;
      const i = this.order[n]!;
      const base = i * STRIDE;
      const a = indices[2 * i]!;
      const b = indices[2 * i + 1]!;
      const aLower = this.lowerIsA[n] === 1;
      // The upper body takes the whole impulse, along +n if it is B and -n if it is A.
      const u = aLower ? b : a;
      const sign = aLower ? 1 : -1;
      const mU = c[base + (aLower ? INV_MASS_B : INV_MASS_A)]!;
      const iU = c[base + (aLower ? INV_I_B : INV_I_A)]!;
      const nx = c[base + NORMAL_X]!;
      const ny = c[base + NORMAL_Y]!;
      const vAx = s[a + V_X]!;
      const vAy = s[a + V_Y]!;
      const wA = s[a + W]!;
      const vBx = s[b + V_X]!;
      const vBy = s[b + V_Y]!;
      const wB = s[b + W]!;
      const dpx = s[b + DP_X]! - s[a + DP_X]!;
      const dpy = s[b + DP_Y]! - s[a + DP_Y]!;
      const qAc = s[a + Q_C]!;
      const qAs = s[a + Q_S]!;
      const qBc = s[b + Q_C]!;
      const qBs = s[b + Q_S]!;
      const pointCount = c[base + POINT_COUNT]!;
      // Per point: the target q = vn + bias (>= 0 wanted) and the upper body's lever rn = r x n.
      let q1 = 0;
      let q2 = 0;
      let rn1 = 0;
      let rn2 = 0;
      // For the friction below: the passes' normal impulses per point and friction impulse, and
      // the levers (A's and B's) to the manifold's middle.
      let n1 = 0;
      let n2 = 0;
      let applied = 0;
      let lAx = 0;
      let lAy = 0;
      let lBx = 0;
      let lBy = 0;
      for (let j = 0; j < pointCount; j++) {
        const p = base + POINTS + j * POINT_STRIDE;
        const rAx = c[p + R_AX]!;
        const rAy = c[p + R_AY]!;
        const rBx = c[p + R_BX]!;
        const rBy = c[p + R_BY]!;
        const dx = dpx + (qBc * rBx - qBs * rBy) - (qAc * rAx - qAs * rAy);
        const dy = dpy + (qBs * rBx + qBc * rBy) - (qAs * rAx + qAc * rAy);
        const separation = dx * nx + dy * ny + c[p + BASE_SEPARATION]!;
        let bias = 0;
        const approach = c[p + RELATIVE_VELOCITY]!;
        const due = bounce && approach < -restitutionThreshold;
        if (separation > 0) {
          // A bounce is due when it touches: not slowed before, as the contact solver waits too.
          if (due) wait = true;
          bias = separation * inverseH;
        } else {
          if (useBias) bias = Math.max(biasRate * separation, -maxPushSpeed);
          // First touch of a new contact: leave at e times the approach, as off the ground
          // (a light body squeezed between a heavy one and the ground passes the bounce on).
          if (due) {
            bias = restitution * approach;
            // A bounce is a one-off impulse, not a force to warm-start (contact-solver.ts does
            // the same): the contact solver's share of this impact is dropped, or undoing it
            // next sub-step would throw the light body up.
            c[p + NORMAL_IMPULSE] = 0;
          }
          this.restitution[n] = 0;
        }
        const vn =
          (vBx - wB * rBy - (vAx - wA * rAy)) * nx + (vBy + wB * rBx - (vAy + wA * rAx)) * ny;
        const rn = aLower ? rBx * ny - rBy * nx : rAx * ny - rAy * nx;
        if (j === 0) {
          q1 = vn + bias;
          rn1 = rn;
          n1 = c[p + NORMAL_IMPULSE]!;
        } else {
          q2 = vn + bias;
          rn2 = rn;
          n2 = c[p + NORMAL_IMPULSE]!;
        }
        applied += c[p + TANGENT_IMPULSE]!;
        lAx += rAx / pointCount;
        lAy += rAy / pointCount;
        lBx += rBx / pointCount;
        lBy += rBy / pointCount;
      }
      if (wait) continue;
      // The LCP  w = K x + q >= 0, x >= 0, x . w = 0  with K the upper body's inverse mass seen
      // by the points (one point: a scalar; two: the 2x2 block, cases as in contact-solver.ts).
      const k11 = mU + iU * rn1 * rn1;
      let x1 = 0;
      let x2 = 0;
      if (pointCount === 1) {
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
      if (x1 !== 0 || x2 !== 0) {
        const impulse = sign * (x1 + x2);
        s[u + V_X] = s[u + V_X]! + mU * impulse * nx;
        s[u + V_Y] = s[u + V_Y]! + mU * impulse * ny;
        s[u + W] = s[u + W]! + sign * iU * (rn1 * x1 + rn2 * x2);
      }
      // Friction the same way: the upper body stops sliding on the lower one as if that could
      // not move, within the cone of the contact's whole normal impulse (the passes' and this
      // sweep's) less the friction the passes already applied. Sequential friction moves a heavy
      // body on a light one as little as the normal impulses do: a 100:1 stack slid 3 m down a
      // 10 degree slope with friction 0.6 (tan 10 degrees is 0.18).
      const limit = c[base + FRICTION]! * (x1 + x2 + n1 + n2);
      if (limit <= 0) continue;
      // The slip there (B relative to A along t = (ny, -nx), as the contact solver measures it)
      // and the upper body's lever across t.
      const rt = aLower ? -lBx * nx - lBy * ny : -lAx * nx - lAy * ny;
      const k = mU + iU * rt * rt;
      if (!(k > 0)) continue;
      // The lower body's turning is left out: a light body rocks under a heavy one, and the heavy
      // one following that rocking walks off (10:1 on a 20 degree slope slid 4 m with it).
      const turnA = aLower ? 0 : s[a + W]!;
      const turnB = aLower ? s[b + W]! : 0;
      const slip =
        (s[b + V_X]! - turnB * lBy - (s[a + V_X]! - turnA * lAy)) * ny -
        (s[b + V_Y]! + turnB * lBx - (s[a + V_Y]! + turnA * lAx)) * nx;
      if (Math.abs(slip) < SWEEP_SLIP) continue;
      const friction = Math.max(-limit - applied, Math.min(limit - applied, -slip / k));
      s[u + V_X] = s[u + V_X]! + sign * mU * friction * ny;
      s[u + V_Y] = s[u + V_Y]! - sign * mU * friction * nx;
      s[u + W] = s[u + W]! + sign * iU * rt * friction;
    }
  }

  /** True when constraint i was pushing at the end of last step (a resting contact). */
  private resting(c: Float64Array, i: number): boolean {
    const base = i * STRIDE;
    for (let j = 0; j < c[base + POINT_COUNT]!; j++) {
      if (c[base + POINTS + j * POINT_STRIDE + NORMAL_IMPULSE]! > 0) return true;
    }
    return false;
  }
}
