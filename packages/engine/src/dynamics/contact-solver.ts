import { STRIDE } from './contact-constraint-layout.ts';
import {
  CONSTRAINT_BODIES,
  CONSTRAINT_DATA,
  CONSTRAINT_ORDER,
  KERNEL_ARGUMENTS,
  SHOCK_SCRATCH,
  SHOCK_SWEEP,
  STATES,
  type SolverMemory,
} from './solver-memory.ts';

// The contact constraints of a step, and the heavy-on-light sweep's calls. The passes over the
// constraints (prepare, warm start, solve, relax, store, the circle pairs' normals, the
// heavy-on-light sweep's choice and sweep) have one source, the kernel (wasm/contact-kernel.ts,
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
// Both halves are the kernel's (wasm/shock-propagation.ts): the choice of contacts once a step
// (prepareShockSweep) and the sweep after the solve and relax passes (shockSweep); this class
// holds the step's count and calls them over the solver memory.

/** The sweep of one step, listed in the solver memory's SHOCK_SWEEP region (shock-sweep-layout.ts). */
export class ShockPropagation {
  /** Contacts to sweep (the first `count` entries of SHOCK_SWEEP), from the top down. */
  count = 0;

  /**
   * Finds the contacts to sweep for this step's constraints, with the states at the step's
   * start, and moves them to the end of the visiting order; `bodyCount` is the number of awake
   * bodies (solver slots 1..bodyCount; slot 0 is every immovable body). The swept contacts push
   * out overlap at a bias rate, as contacts with the ground do. A light body moving along the
   * contact's normal at a rest speed or faster is not resting under the heavy one. The bias rate,
   * gravity and rest speed are in the kernel's arguments (A_SHOCK_BIAS_RATE, A_GRAVITY_X,
   * A_GRAVITY_Y, A_SHOCK_REST_SPEED: kernel-arguments.ts, stored by Solver.solve). The solver
   * memory's SHOCK_SCRATCH must hold 2 (bodyCount + 1) + 5 count int32 (Solver.solve reserves it).
   */
  prepare(constraints: ContactConstraints, bodyCount: number): void {
    this.count = 0;
    if (constraints.heavyOnLightCount === 0) return;
    const memory = constraints.memory;
    const o = memory.offsets;
    this.count = memory.kernel.prepareShockSweep(
      o[CONSTRAINT_DATA]!,
      o[CONSTRAINT_BODIES]!,
      o[CONSTRAINT_ORDER]!,
      constraints.count,
      o[STATES]!,
      o[SHOCK_SWEEP]!,
      o[SHOCK_SCRATCH]!,
      bodyCount,
      o[KERNEL_ARGUMENTS]!,
    );
  }

  /**
   * Sweeps the prepared contacts once, ground up: each upper body stops approaching the body
   * below it, as if that body could not move. With `useBias` 1 (after the solve pass), overlap is
   * pushed out at the sweep's bias rate (at most the push-out limit), as against the ground; with 0
   * (after the relax pass), only the approach is removed. A new contact faster than the
   * restitution threshold bounces at its first touch (with the sub-step velocity changes at byte
   * `marks`), an approach bounded by two bodies at maxLinearSpeed. Those numbers and the inverse
   * sub-step are in the kernel's arguments (kernel-arguments.ts, stored by Solver.solve).
   */
  solve(constraints: ContactConstraints, marks: number, useBias: number): void {
    const memory = constraints.memory;
    const o = memory.offsets;
    memory.kernel.shockSweep(
      o[CONSTRAINT_DATA]!,
      o[CONSTRAINT_BODIES]!,
      o[SHOCK_SWEEP]!,
      this.count,
      o[STATES]!,
      marks,
      o[KERNEL_ARGUMENTS]!,
      useBias,
    );
  }
}
