import {
  A_JOINT_BIAS_RATE,
  A_JOINT_H,
  A_JOINT_IMPULSE_SCALE,
  A_JOINT_INVERSE_H,
  A_JOINT_MASS_SCALE,
  A_JOINT_MAX_BIAS_SPEED,
} from '../kernel-arguments.ts';
import {
  JOINT_ACTIVE,
  JOINT_RECORDS,
  KERNEL_ARGUMENTS,
  STATES,
  type SolverMemory,
} from '../solver-memory.ts';
import { createJointKernel } from './joint-kernel-loader.ts';
import type { JointStep } from './joint.ts';
import {
  REACTION_ANGULAR,
  REACTION_X,
  REACTION_Y,
  STEP_ANGULAR_IMPULSE,
  STEP_IMPULSE_X,
  STEP_IMPULSE_Y,
} from './joint-record.ts';

/**
 * @internal One joint kind in a world: the step's active joints of the kind, solved in one loop
 * per pass instead of a call per joint object (Box2D v3 keeps joint solver data in arrays the same
 * way). Their records are in the world's joint store (joint-store.ts, the solver memory's
 * JOINT_RECORDS region); the step's active joints are listed in the memory's JOINT_ACTIVE region,
 * grouped by kind (record offset, state A offset, state B offset each), this kind's from `start`,
 * `active` of them, in the world's joint order (the order they are solved in).
 */
export class JointBatch {
  /** Where this kind's active joints start in JOINT_ACTIVE (in joints, not int32s). */
  start = 0;
  /** Active joints of the kind this step. */
  active = 0;

  /** `kind`: the kind's code (KIND_...). */
  constructor(private readonly kind: number) {}

  /**
   * Loads the joints' passes (a module of their own, joint-kernel-loader.ts) over `memory`, when
   * the world makes its first batch: only the joints' code references the module, so apps without
   * joints do not ship it.
   */
  load(memory: SolverMemory): void {
    memory.loadJoints(createJointKernel);
  }

  /**
   * Every active joint of the kind through the kernel's pass `pass` (PASS_...: the warm start, a
   * solve with the position bias, or a relax pass), with the step's numbers.
   */
  run(memory: SolverMemory, step: JointStep, pass: number): void {
    const o = memory.offsets;
    const soft = step.softness;
    // Through the memory: V8 can box each double passed to WebAssembly (kernel-arguments.ts).
    const args = memory.kernelArguments;
    args[A_JOINT_H] = step.h;
    args[A_JOINT_INVERSE_H] = step.inverseH;
    args[A_JOINT_BIAS_RATE] = soft.biasRate;
    args[A_JOINT_MASS_SCALE] = soft.massScale;
    args[A_JOINT_IMPULSE_SCALE] = soft.impulseScale;
    args[A_JOINT_MAX_BIAS_SPEED] = step.maxBiasSpeed;
    memory.joints.jointPass(
      this.kind,
      pass,
      o[JOINT_RECORDS]!,
      o[JOINT_ACTIVE]!,
      o[STATES]!,
      this.start,
      this.start + this.active,
      o[KERNEL_ARGUMENTS]!,
    );
  }

  /** Turns the step's summed impulses into each active joint's reaction (N, N m). */
  finish(memory: SolverMemory, dt: number): void {
    const d = memory.jointStore.data;
    const list = memory.jointActive;
    const end = this.start + this.active;
    for (let i = this.start; i < end; i++) {
      const o = list[3 * i]!;
      d[o + REACTION_X] = d[o + STEP_IMPULSE_X]! / dt;
      d[o + REACTION_Y] = d[o + STEP_IMPULSE_Y]! / dt;
      d[o + REACTION_ANGULAR] = d[o + STEP_ANGULAR_IMPULSE]! / dt;
    }
  }
}
