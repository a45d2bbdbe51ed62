import {
  DP_X,
  DP_Y,
  KICK_VX,
  KICK_VY,
  KICK_W,
  MARK_STRIDE,
  Q_C,
  Q_S,
  STATE_STRIDE,
  V_X,
  V_Y,
  W,
} from './body-state.ts';
import {
  BASE_SEPARATION,
  BIAS_RATE,
  CENTER_DX,
  CENTER_DY,
  FRICTION,
  IMPULSE_SCALE,
  INV_I_A,
  INV_I_B,
  INV_MASS_A,
  INV_MASS_B,
  MASS_SCALE,
  NORMAL_IMPULSE,
  NORMAL_MASS,
  NORMAL_X,
  NORMAL_Y,
  POINT_COUNT,
  POINT_STRIDE,
  POINTS,
  R_AX,
  R_AY,
  R_BX,
  R_BY,
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
  STRIDE,
  constraintBase,
  TANGENT_IMPULSE,
  TANGENT_MASS,
} from './contact-constraint-layout.ts';
import type { SolverMemory } from './solver-memory.ts';
import { hypot } from '../math/hypot.ts';

// The contact constraints of a step and the JavaScript that reads them between the kernel's passes
// (the circle pairs' normals, the heavy-on-light sweep). The passes themselves (prepare, warm
// start, solve, relax, store) have one source, the contact kernel (wasm/contact-kernel.ts), built
// to WebAssembly and to JavaScript (contact-kernel.ts picks one).

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
    const base = constraintBase(i);
    const a = indices[2 * i]!;
    const b = indices[2 * i + 1]!;
    const dpAx = s[a + DP_X]!;
    const dpAy = s[a + DP_Y]!;
    const dpBx = s[b + DP_X]!;
    const dpBy = s[b + DP_Y]!;
    const dx = c[base + 2 * CENTER_DX]! + dpBx - dpAx;
    const dy = c[base + 2 * CENTER_DY]! + dpBy - dpAy;
    const length = Math.sqrt(dx * dx + dy * dy);
    if (!(length > 1e-12)) continue; // coincident centres: keep the last normal
    const nx = dx / length;
    const ny = dy / length;
    const radiusA = c[base + 2 * RADIUS_A]!;
    const radiusB = c[base + 2 * RADIUS_B]!;
    // Both arms end at the same point, midway across the gap (or overlap), so that a friction
    // impulse too acts on one line for both particles.
    const halfGap = 0.5 * (length - radiusA - radiusB);
    const armA = radiusA + halfGap;
    const armB = radiusB + halfGap;
    const rAx = nx * armA;
    const rAy = ny * armA;
    const rBx = -nx * armB;
    const rBy = -ny * armB;
    c[base + 2 * NORMAL_X] = nx;
    c[base + 2 * NORMAL_Y] = ny;
    c[base + 2 * REF_DP_AX] = dpAx;
    c[base + 2 * REF_DP_AY] = dpAy;
    c[base + 2 * REF_DP_BX] = dpBx;
    c[base + 2 * REF_DP_BY] = dpBy;
    const p = base + 2 * POINTS;
    c[p + 2 * R_AX] = rAx;
    c[p + 2 * R_AY] = rAy;
    c[p + 2 * R_BX] = rBx;
    c[p + 2 * R_BY] = rBy;
    // Along the line of centres: no arm across n.
    c[p + 2 * RN_A] = 0;
    c[p + 2 * RN_B] = 0;
    // Baseline such that the solver's separation formula gives the exact gap now.
    const qAc = s[a + Q_C]!;
    const qAs = s[a + Q_S]!;
    const qBc = s[b + Q_C]!;
    const qBs = s[b + Q_S]!;
    const gx = dpBx - dpAx + (qBc * rBx - qBs * rBy) - (qAc * rAx - qAs * rAy);
    const gy = dpBy - dpAy + (qBs * rBx + qBc * rBy) - (qAs * rAx + qAc * rAy);
    c[p + 2 * BASE_SEPARATION] = length - radiusA - radiusB - (gx * nx + gy * ny);
    const mA = c[base + 2 * INV_MASS_A]!;
    const mB = c[base + 2 * INV_MASS_B]!;
    const kNormal = mA + mB;
    c[p + 2 * NORMAL_MASS] = kNormal > 0 ? 1 / kNormal : 0;
    const kTangent =
      kNormal + c[base + 2 * INV_I_A]! * armA * armA + c[base + 2 * INV_I_B]! * armB * armB;
    c[p + 2 * TANGENT_MASS] = kTangent > 0 ? 1 / kTangent : 0;
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
// It reads the constraint layout of contact-constraint-layout.ts, the one definition the kernel's
// mirror is generated from. (Module-local offsets were measured 7 % faster in the JavaScript
// passes, which are now generated from the kernel; this sweep runs only in steps with
// heavy-on-light contacts.)

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
  /** The fastest approach a bounce reverses: two bodies each at maxLinearSpeed (set by prepare). */
  private maxApproach = Infinity;

  /**
   * Finds the contacts to sweep for this step's constraints, with the states `s` at the step's
   * start; `bodyCount` is the number of awake bodies (solver slots 1..bodyCount; slot 0 is every
   * immovable body). The swept contacts push out overlap at `biasRate`, as contacts with the
   * ground do. A light body moving along the contact's normal at `restSpeed` or faster is not
   * resting under the heavy one (see below).
   */
  prepare(
    constraints: ContactConstraints,
    s: Float64Array,
    bodyCount: number,
    biasRate: number,
    gravityX: number,
    gravityY: number,
    restSpeed: number,
    maxLinearSpeed: number,
  ): void {
    this.count = 0;
    this.maxApproach = 2 * maxLinearSpeed;
    const gravity = hypot(gravityX, gravityY);
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
      const base = constraintBase(i);
      ends[2 * i] = c[base + 2 * INV_MASS_A] === 0 ? 0 : indices[2 * i]! / STATE_STRIDE;
      ends[2 * i + 1] = c[base + 2 * INV_MASS_B] === 0 ? 0 : indices[2 * i + 1]! / STATE_STRIDE;
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
        const base = constraintBase(i);
        const mLower = c[base + 2 * (aLower ? INV_MASS_A : INV_MASS_B)]!;
        const mUpper = c[base + 2 * (aLower ? INV_MASS_B : INV_MASS_A)]!;
        // Heavy on light: the lower body more than twice lighter, the normal within 60 degrees of
        // up (a body beside another is not resting on it).
        const up =
          (aLower ? -1 : 1) *
          (c[base + 2 * NORMAL_X]! * gravityX + c[base + 2 * NORMAL_Y]! * gravityY);
        // And the light body resting there: not moving along the normal (as fast as a load
        // presses, see Solver's MIN_LOADED_IMPACT_SPEED). The sweep's bounce treats it as held
        // still by what is under it; a light ball sliding fast along the floor into a heavy one
        // is not held along a slanted normal, and treating it so reflected the heavy ball off a
        // surface moving at the light ball's speed (a 16-ball gas gained 90 % of its energy in
        // one step). Such a hit is an impact of two bodies, passed on to the floor by the impact
        // rounds (wasm/contact-kernel.ts).
        const vLower = mLower === 0 ? 0 : indices[2 * i + (aLower ? 0 : 1)]!;
        const heavyOnLight =
          mLower > 2 * mUpper &&
          up >= 0.5 * gravity &&
          Math.abs(
            s[vLower + V_X]! * c[base + 2 * NORMAL_X]! + s[vLower + V_Y]! * c[base + 2 * NORMAL_Y]!,
          ) < restSpeed;
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
          this.restitution[this.count++] = c[base + 2 * RESTITUTION]!;
          if (heavyOnLight) c[base + 2 * RESTITUTION] = 0;
          // Rigid in the ordinary passes: a soft contact lets its impulse leak each pass, so the
          // weight above would not reach the ground.
          c[base + 2 * BIAS_RATE] = biasRate;
          c[base + 2 * MASS_SCALE] = 1;
          c[base + 2 * IMPULSE_SCALE] = 0;
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
   * A new contact faster than `restitutionThreshold` bounces at its first touch, reversing its
   * approach at that moment (with the sub-step velocity changes after `marks` in `s`).
   */
  solve(
    constraints: ContactConstraints,
    s: Float64Array,
    marks: number,
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
      const base = constraintBase(i);
      const a = indices[2 * i]!;
      const b = indices[2 * i + 1]!;
      const aLower = this.lowerIsA[n] === 1;
      // The upper body takes the whole impulse, along +n if it is B and -n if it is A.
      const u = aLower ? b : a;
      const sign = aLower ? 1 : -1;
      const mU = c[base + 2 * (aLower ? INV_MASS_B : INV_MASS_A)]!;
      const iU = c[base + 2 * (aLower ? INV_I_B : INV_I_A)]!;
      const nx = c[base + 2 * NORMAL_X]!;
      const ny = c[base + 2 * NORMAL_Y]!;
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
      const pointCount = c[base + 2 * POINT_COUNT]!;
      // The upper body's velocity change by this sub-step's integration (gravity, forces): the
      // lower body is held, so only the upper one's adds to the approach.
      const kick = marks + (u / STATE_STRIDE) * MARK_STRIDE;
      const kickN = sign * (s[kick + KICK_VX]! * nx + s[kick + KICK_VY]! * ny);
      const kickW = sign * s[kick + KICK_W]!;
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
        const p = base + 2 * (POINTS + j * POINT_STRIDE);
        const rAx = c[p + 2 * R_AX]!;
        const rAy = c[p + 2 * R_AY]!;
        const rBx = c[p + 2 * R_BX]!;
        const rBy = c[p + 2 * R_BY]!;
        const dx = dpx + (qBc * rBx - qBs * rBy) - (qAc * rAx - qAs * rAy);
        const dy = dpy + (qBs * rBx + qBc * rBy) - (qAs * rAx + qAc * rAy);
        const separation = dx * nx + dy * ny + c[p + 2 * BASE_SEPARATION]!;
        let bias = 0;
        const rn = aLower ? rBx * ny - rBy * nx : rAx * ny - rAy * nx;
        const approach = c[p + 2 * RELATIVE_VELOCITY]!;
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
            if (useBias) {
              c[p + 2 * RELATIVE_VELOCITY] = Math.max(
                approach + kickN + kickW * rn,
                -this.maxApproach,
              );
            }
          }
          bias = separation * inverseH;
        } else {
          if (useBias) bias = Math.max(biasRate * separation, -maxPushSpeed);
          // First touch of a new contact: leave at e times the approach, as off the ground
          // (a light body squeezed between a heavy one and the ground passes the bounce on),
          // the approach at the moment of touching: the end of the sub-step it touched in, half a
          // velocity change after its middle (see the kernel's bounce in wasm/contact-kernel.ts).
          if (due) {
            bias = restitution * Math.max(approach + 0.5 * (kickN + kickW * rn), -this.maxApproach);
            // A bounce is a one-off impulse, not a force to warm-start (contact-solver.ts does
            // the same): the contact solver's share of this impact is dropped, or undoing it
            // next sub-step would throw the light body up.
            c[p + 2 * NORMAL_IMPULSE] = 0;
          }
          this.restitution[n] = 0;
        }
        const vn =
          (vBx - wB * rBy - (vAx - wA * rAy)) * nx + (vBy + wB * rBx - (vAy + wA * rAx)) * ny;
        if (j === 0) {
          q1 = vn + bias;
          rn1 = rn;
          n1 = c[p + 2 * NORMAL_IMPULSE]!;
        } else {
          q2 = vn + bias;
          rn2 = rn;
          n2 = c[p + 2 * NORMAL_IMPULSE]!;
        }
        applied += c[p + 2 * TANGENT_IMPULSE]!;
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
      const limit = c[base + 2 * FRICTION]! * (x1 + x2 + n1 + n2);
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
    const base = constraintBase(i);
    for (let j = 0; j < c[base + 2 * POINT_COUNT]!; j++) {
      if (c[base + 2 * (POINTS + j * POINT_STRIDE + NORMAL_IMPULSE)]! > 0) return true;
    }
    return false;
  }
}
