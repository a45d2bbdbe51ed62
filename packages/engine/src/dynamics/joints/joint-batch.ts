import { releaseFrom } from '../../core/release.ts';
import type { Joint, JointStep } from './joint.ts';

/**
 * @internal One joint kind's solver numbers for a step, in flat arrays, so each pass is one loop
 * over numbers instead of a call per joint object (Box2D v3 keeps joint solver data in arrays the
 * same way). Between steps the joint objects hold the truth; {@link finish} writes it back.
 */
export interface JointBatch {
  /** Forgets last step's joints. */
  clear(): void;
  /** Forgets its joints (a removed body must not stay reachable through them). */
  release(): void;
  /** Adds a joint of the batch's kind, already prepared for the step. */
  add(joint: Joint): void;
  warmStart(s: Float64Array): void;
  solve(s: Float64Array, step: JointStep, useBias: boolean): void;
  /** Writes the step's impulses back to the joints. */
  finish(): void;
}

/** @internal What a joint kind gives its batch: its numbers into a slot and back. */
export interface BatchedJoint extends Joint {
  /** Writes this step's solver numbers into slot `slot` of `batch`, at `o` in `d`. */
  loadBatch(d: Float64Array, o: number, slot: number, batch: FlatJointBatch<BatchedJoint>): void;
  /** Takes the step's impulses back from the slot at `o`. */
  storeBatch(d: Float64Array, o: number): void;
}

/**
 * @internal The storage every kind's batch shares: `stride` doubles per joint in `data`, the two
 * bodies' state offsets per joint in `states` (A, B), growing by doubling (allocation only when a
 * step has more joints of the kind than any before). The kind's solver file (`*-joint-solver.ts`,
 * or the kind's own file) adds the two pass loops, over its own module-local layout offsets.
 */
export abstract class FlatJointBatch<J extends BatchedJoint> implements JointBatch {
  count = 0;
  data: Float64Array;
  protected states: Int32Array = new Int32Array(2 * 16);
  private readonly joints: J[] = [];

  constructor(private readonly stride: number) {
    this.data = new Float64Array(stride * 16);
  }

  clear(): void {
    this.count = 0;
  }

  release(): void {
    this.count = 0;
    releaseFrom(this.joints, 0);
  }

  add(joint: Joint): void {
    const batched = joint as J;
    const i = this.count++;
    if (this.states.length < 2 * this.count) {
      const data = new Float64Array(2 * this.data.length);
      data.set(this.data);
      this.data = data;
      const states = new Int32Array(2 * this.states.length);
      states.set(this.states);
      this.states = states;
    }
    this.states[2 * i] = batched.stateA;
    this.states[2 * i + 1] = batched.stateB;
    this.joints[i] = batched; // at most at its length: appends, never a hole
    batched.loadBatch(this.data, i * this.stride, i, this);
  }

  finish(): void {
    for (let i = 0; i < this.count; i++) this.joints[i]!.storeBatch(this.data, i * this.stride);
  }

  abstract warmStart(s: Float64Array): void;
  abstract solve(s: Float64Array, step: JointStep, useBias: boolean): void;
}
