import { JointBatch } from './joint-batch.ts';
import type { JointStep } from './joint.ts';
import { JOINT_ACTIVE, JOINT_RECORDS, STATES, type SolverMemory } from '../solver-memory.ts';
import { SPRING_MOTOR_LIMIT_END } from './spring-motor-limit.ts';

// A prismatic joint's record: the head (joint-record.ts), the spring, motor and limit on its
// translation (spring-motor-limit.ts), then these. The kernel's passes read them from the layout
// the build script generates from this file (J_PRISMATIC_..., wasm/contact-layout.ts).
/** The slide's direction in A's frame (unit). */
export const LOCAL_AXIS_X: number = SPRING_MOTOR_LIMIT_END;
export const LOCAL_AXIS_Y: number = SPRING_MOTOR_LIMIT_END + 1;
/** The axis in world orientation at the step's start. */
export const AXIS_X: number = SPRING_MOTOR_LIMIT_END + 2;
export const AXIS_Y: number = SPRING_MOTOR_LIMIT_END + 3;
/** Accumulated impulses (warm-started). */
export const PERPENDICULAR_IMPULSE: number = SPRING_MOTOR_LIMIT_END + 4;
export const ANGULAR_IMPULSE: number = SPRING_MOTOR_LIMIT_END + 5;
export const STRIDE: number = SPRING_MOTOR_LIMIT_END + 6;

/**
 * @internal The prismatic joints of a world: the step's active ones, solved by the kernel's
 * passes (wasm/joint-passes.ts: warmStartPrismatic, solvePrismatic), one call per pass.
 */
export class PrismaticBatch extends JointBatch {
  warmStart(memory: SolverMemory): void {
    const o = memory.offsets;
    memory.joints.warmStartPrismatic(
      o[JOINT_RECORDS]!,
      o[JOINT_ACTIVE]!,
      o[STATES]!,
      this.start,
      this.start + this.active,
    );
  }

  solve(memory: SolverMemory, step: JointStep, useBias: boolean): void {
    const o = memory.offsets;
    const soft = step.softness;
    memory.joints.solvePrismatic(
      o[JOINT_RECORDS]!,
      o[JOINT_ACTIVE]!,
      o[STATES]!,
      this.start,
      this.start + this.active,
      step.h,
      step.inverseH,
      soft.biasRate,
      soft.massScale,
      soft.impulseScale,
      useBias ? 1 : 0,
    );
  }
}
