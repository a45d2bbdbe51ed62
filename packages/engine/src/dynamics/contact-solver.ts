import { STATE_STRIDE, V_X, V_Y } from './body-state.ts';
import {
  BIAS_RATE,
  IMPULSE_SCALE,
  INV_MASS_A,
  INV_MASS_B,
  MASS_SCALE,
  NORMAL_IMPULSE,
  NORMAL_X,
  NORMAL_Y,
  POINT_COUNT,
  POINT_STRIDE,
  POINTS,
  RESTITUTION,
  STRIDE,
  constraintBase,
} from './contact-constraint-layout.ts';
import {
  SWEEP_CONSTRAINT,
  SWEEP_LOWER_IS_A,
  SWEEP_RESTITUTION,
  SWEEP_STRIDE,
} from './shock-sweep-layout.ts';
import type { SolverMemory } from './solver-memory.ts';
import { hypot } from '../math/hypot.ts';

// The contact constraints of a step, and the heavy-on-light sweep's choice of contacts, made once a
// step. The passes over the constraints (prepare, warm start, solve, relax, store, the circle
// pairs' normals, the heavy-on-light sweep) have one source, the kernel (wasm/contact-kernel.ts,
// circle-pairs.ts, shock-propagation.ts), built to WebAssembly and to JavaScript
// (contact-kernel.ts picks one).

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
// The choice (prepare, below, once a step) reads the constraint layout of
// contact-constraint-layout.ts, the one definition the kernel's mirror is generated from; the
// sweep itself, each sub-step, is the kernel's (wasm/shock-propagation.ts).

/**
 * The sweep of one step: which constraints, in which order, and which side is below, listed in
 * the solver memory's SHOCK_SWEEP region (shock-sweep-layout.ts) for the kernel's sweep
 * (wasm/shock-propagation.ts), which the solver calls after the solve and relax passes.
 */
export class ShockPropagation {
  /** Contacts to sweep (the first `count` entries of SHOCK_SWEEP), from the top down. */
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
  maxApproach = Infinity;

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
    // The list (SHOCK_SWEEP): room for every constraint, made with the constraints'.
    const list = constraints.memory.shockSweep;

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
          const entry = this.count++ * SWEEP_STRIDE;
          list[entry + SWEEP_CONSTRAINT] = i;
          list[entry + SWEEP_LOWER_IS_A] = aLower ? 1 : 0;
          // A contact approaching at the step's start may bounce (restitution), once, at first
          // touch (a resting one does not approach: the last relax pass stopped it). A heavy
          // body bounces off the light one here, not in the contact solver: there, its bounce
          // would send the light body into the ground, again each sub-step.
          list[entry + SWEEP_RESTITUTION] = c[base + 2 * RESTITUTION]!;
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
    for (let n = this.count - 1; n >= 0; n--) {
      order[kept++] = list[n * SWEEP_STRIDE + SWEEP_CONSTRAINT]!;
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
