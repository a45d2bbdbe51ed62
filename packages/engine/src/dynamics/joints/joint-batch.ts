import type { Joint, JointStep } from './joint.ts';
import {
  REACTION_ANGULAR,
  REACTION_X,
  REACTION_Y,
  STATE_A,
  STATE_B,
  STEP_ANGULAR_IMPULSE,
  STEP_IMPULSE_X,
  STEP_IMPULSE_Y,
} from './joint-record.ts';
import { JointStore } from './joint-store.ts';

/**
 * @internal One joint kind in a world: its joints' records (the one copy of their numbers, see
 * JointStore) and the step's active joints among them, solved in one loop per pass instead of a
 * call per joint object (Box2D v3 keeps joint solver data in arrays the same way).
 */
export interface JointBatch {
  /** The kind's records; a joint of the kind is moved here before its first step in the world. */
  readonly store: JointStore;
  /** Forgets last step's active joints. */
  clear(): void;
  /** Adds a joint of the batch's kind, prepared for the step, to the step's active joints. */
  add(joint: Joint): void;
  warmStart(s: Float64Array): void;
  solve(s: Float64Array, step: JointStep, useBias: boolean): void;
  /** Turns the step's summed impulses into each active joint's reaction (N, N m). */
  finish(dt: number): void;
}

/**
 * @internal The storage every kind's batch shares: the kind's store, the offsets of the step's
 * active records in `offsets` (in the world's joint order, the order they are solved in) and their
 * two bodies' state offsets in `states` (A, B), growing by doubling (allocation only when a step
 * has more joints of the kind than any before). The kind's solver file (`*-joint-solver.ts`, or
 * the kind's own file) adds the two pass loops, over its own layout offsets.
 */
export abstract class FlatJointBatch extends JointStore implements JointBatch {
  /** Active joints this step. */
  active = 0;
  protected offsets: Int32Array = new Int32Array(16);
  protected states: Int32Array = new Int32Array(2 * 16);

  constructor(stride: number) {
    super(stride, 16, false);
  }

  get store(): JointStore {
    return this;
  }

  clear(): void {
    this.active = 0;
  }

  add(joint: Joint): void {
    const i = this.active++;
    if (this.offsets.length < this.active) {
      const offsets = new Int32Array(2 * this.offsets.length);
      offsets.set(this.offsets);
      this.offsets = offsets;
      const states = new Int32Array(2 * this.states.length);
      states.set(this.states);
      this.states = states;
    }
    const o = joint.base;
    const d = this.data;
    this.offsets[i] = o;
    this.states[2 * i] = d[o + STATE_A]!;
    this.states[2 * i + 1] = d[o + STATE_B]!;
  }

  finish(dt: number): void {
    const d = this.data;
    for (let i = 0; i < this.active; i++) {
      const o = this.offsets[i]!;
      d[o + REACTION_X] = d[o + STEP_IMPULSE_X]! / dt;
      d[o + REACTION_Y] = d[o + STEP_IMPULSE_Y]! / dt;
      d[o + REACTION_ANGULAR] = d[o + STEP_ANGULAR_IMPULSE]! / dt;
    }
  }

  abstract warmStart(s: Float64Array): void;
  abstract solve(s: Float64Array, step: JointStep, useBias: boolean): void;
}
