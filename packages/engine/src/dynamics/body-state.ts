// Solver body state: the velocities and the pose change of one step, packed for the solver loops.
// Slot 0 is the identity state that static (and sleeping) bodies share, so the contact loops need
// no branch for them: its velocity stays zero because every static body has zero inverse mass.
//
// Layout per body, stride 8 doubles (one 64-byte cache line):
//   0 vx, 1 vy, 2 w        velocity (m/s, rad/s)
//   3 deltaAngle            rotation this step, exact sum of h w (rad)
//   4 dpx, 5 dpy            translation of the centre of mass this step (m)
//   6 qc, 7 qs              rotation this step as cosine/sine (for the contact anchors)
// After the states, MARK_STRIDE numbers per state (from BodyStates.marks):
//   0 mark                  1 while an impact of this sub-step has reached the body (the contact
//                           kernel's impacts, wasm/contact-kernel.ts), else 0
//   1 kvx, 2 kvy, 3 kw      the velocity change of this sub-step's integration (gravity, forces,
//                           damping), so that a bounce reverses the approach at the moment of
//                           contact, not the sub-step's average (the kernel's solve)

import type { SolverMemory } from './solver-memory.ts';

// The body table: per body of the world (by world index), what preparing a contact needs of it,
// written by Solver.gatherBodies, so the preparation reads numbers instead of contact and body
// objects (their first loads were most of its time):
//   0 solver slot (0: immovable this step)
//   1 inverse mass, 2 inverse inertia (0 when immovable this step)
//   3 cx, 4 cy   centre of mass at the step's start (m)
export const TABLE_SLOT = 0;
export const TABLE_INV_MASS = 1;
export const TABLE_INV_I = 2;
export const TABLE_CENTER_X = 3;
export const TABLE_CENTER_Y = 4;
export const TABLE_STRIDE = 5;

export const STATE_STRIDE = 8;
export const V_X = 0;
export const V_Y = 1;
export const W = 2;
export const DELTA_ANGLE = 3;
export const DP_X = 4;
export const DP_Y = 5;
export const Q_C = 6;
export const Q_S = 7;

export const MARK_STRIDE = 4;
export const MARK = 0;
export const KICK_VX = 1;
export const KICK_VY = 2;
export const KICK_W = 3;

/** Growable array of solver body states, in the solver's memory (solver-memory.ts). */
export class BodyStates {
  constructor(private readonly memory: SolverMemory) {}

  /** The states; a view that a later reserve of the same memory replaces. */
  get data(): Float64Array {
    return this.memory.states;
  }

  /** Where the impact marks and sub-step velocity changes start in `data` (see the layout above). */
  marks = 0;

  /**
   * Makes room for `count` states plus the identity slot and their impact marks and velocity
   * changes, resets the identity slot and clears the marks and changes.
   */
  reserve(count: number): Float64Array {
    const d = this.memory.reserveStates(stateDoubles(count));
    d.fill(0, 0, STATE_STRIDE);
    d[Q_C] = 1;
    this.marks = (count + 1) * STATE_STRIDE;
    d.fill(0, this.marks, this.marks + (count + 1) * MARK_STRIDE);
    return d;
  }
}

/**
 * The state numbers of `count` bodies: the identity slot, the states, and a mark and velocity
 * change per state.
 */
export function stateDoubles(count: number): number {
  return (count + 1) * (STATE_STRIDE + MARK_STRIDE);
}
