import { DELTA_ANGLE, V_X, V_Y, W } from '../body-state.ts';
import { JointBatch } from './joint-batch.ts';
import type { SolverMemory } from '../solver-memory.ts';
import type { JointStep } from './joint.ts';
import { turnedX, turnedY } from './joint-levers.ts';
import {
  INV_I_A,
  INV_I_B,
  INV_MASS_A,
  INV_MASS_B,
  JOINT_ANGLE_0,
  R_AX,
  R_BX,
  STEP_ANGULAR_IMPULSE,
  STEP_IMPULSE_X,
  STEP_IMPULSE_Y,
} from './joint-record.ts';
import { solveSoftPoint } from './soft-point.ts';
import {
  LIMIT_ON,
  LOWER,
  LOWER_IMPULSE,
  MAX_MOTOR,
  MOTOR_IMPULSE,
  MOTOR_ON,
  MOTOR_SPEED,
  SPRING_BIAS_RATE,
  SPRING_IMPULSE,
  SPRING_IMPULSE_SCALE,
  SPRING_MASS_SCALE,
  SPRING_ON,
  UPPER,
  UPPER_IMPULSE,
} from './spring-motor-limit.ts';

// A revolute joint's record: the head (joint-record.ts), the spring, motor and limit on its angle
// (spring-motor-limit.ts), then these (literals, as the passes read them best: see
// dynamics/README.md; joint-layouts.test.ts checks they follow on and do not overlap):
export const LINEAR_IMPULSE_X = 42; // SPRING_MOTOR_LIMIT_END; the point's accumulated impulse
export const LINEAR_IMPULSE_Y = 43; // SPRING_MOTOR_LIMIT_END + 1
export const AXIAL_MASS = 44; // SPRING_MOTOR_LIMIT_END + 2; this step: 1 / (1/IA + 1/IB)
export const MAX_BIAS_SPEED = 45; // SPRING_MOTOR_LIMIT_END + 3; this step's JointStep.maxBiasSpeed
export const STRIDE = 46; // SPRING_MOTOR_LIMIT_END + 4

/**
 * @internal The revolute joints of a world: their records, and the step's active ones solved in
 * one loop per pass (see JointBatch).
 */
export class RevoluteBatch extends JointBatch {
  warmStart(s: Float64Array, memory: SolverMemory): void {
    const d = memory.jointStore.data;
    const list = memory.jointActive;
    const end = this.start + this.active;
    for (let i = this.start; i < end; i++) {
      const o = list[3 * i]!;
      const a = list[3 * i + 1]!;
      const b = list[3 * i + 2]!;
      const mA = d[o + INV_MASS_A]!;
      const iA = d[o + INV_I_A]!;
      const mB = d[o + INV_MASS_B]!;
      const iB = d[o + INV_I_B]!;
      const rAx = turnedX(s, a, d, o + R_AX);
      const rAy = turnedY(s, a, d, o + R_AX);
      const rBx = turnedX(s, b, d, o + R_BX);
      const rBy = turnedY(s, b, d, o + R_BX);
      const px = d[o + LINEAR_IMPULSE_X]!;
      const py = d[o + LINEAR_IMPULSE_Y]!;
      const axial =
        d[o + SPRING_IMPULSE]! +
        d[o + MOTOR_IMPULSE]! +
        d[o + LOWER_IMPULSE]! -
        d[o + UPPER_IMPULSE]!;
      s[a + V_X] -= mA * px;
      s[a + V_Y] -= mA * py;
      s[a + W] -= iA * (rAx * py - rAy * px + axial);
      s[b + V_X] += mB * px;
      s[b + V_Y] += mB * py;
      s[b + W] += iB * (rBx * py - rBy * px + axial);
    }
  }

  solve(s: Float64Array, memory: SolverMemory, step: JointStep, useBias: boolean): void {
    const d = memory.jointStore.data;
    const list = memory.jointActive;
    const end = this.start + this.active;
    const soft = step.softness;
    for (let i = this.start; i < end; i++) {
      const o = list[3 * i]!;
      const a = list[3 * i + 1]!;
      const b = list[3 * i + 2]!;
      const iA = d[o + INV_I_A]!;
      const iB = d[o + INV_I_B]!;
      let wA = s[a + W]!;
      let wB = s[b + W]!;
      const jointAngle = d[o + JOINT_ANGLE_0]! + s[b + DELTA_ANGLE]! - s[a + DELTA_ANGLE]!;
      const axialMass = d[o + AXIAL_MASS]!;

      if (d[o + SPRING_ON] === 1) {
        const bias = d[o + SPRING_BIAS_RATE]! * jointAngle;
        const impulse =
          -d[o + SPRING_MASS_SCALE]! * axialMass * (wB - wA + bias) -
          d[o + SPRING_IMPULSE_SCALE]! * d[o + SPRING_IMPULSE]!;
        d[o + SPRING_IMPULSE] += impulse;
        wA -= iA * impulse;
        wB += iB * impulse;
      }

      if (d[o + MOTOR_ON] === 1) {
        const impulse = -axialMass * (wB - wA - d[o + MOTOR_SPEED]!);
        const old = d[o + MOTOR_IMPULSE]!;
        const maxImpulse = step.h * d[o + MAX_MOTOR]!;
        const accumulated = Math.max(-maxImpulse, Math.min(old + impulse, maxImpulse));
        d[o + MOTOR_IMPULSE] = accumulated;
        const applied = accumulated - old;
        wA -= iA * applied;
        wB += iB * applied;
      }

      if (d[o + LIMIT_ON] === 1) {
        // Lower limit: C = angle - lower >= 0; upper: C = upper - angle >= 0, the same row with
        // the sign turned. Speculative like contacts: a gap may close within the sub-step.
        for (let side = 1; side >= -1; side -= 2) {
          const c = side === 1 ? jointAngle - d[o + LOWER]! : d[o + UPPER]! - jointAngle;
          let bias = 0;
          let massScale = 1;
          let impulseScale = 0;
          if (c > 0) bias = c * step.inverseH;
          else if (useBias) {
            bias = soft.biasRate * c;
            massScale = soft.massScale;
            impulseScale = soft.impulseScale;
          }
          const at = side === 1 ? LOWER_IMPULSE : UPPER_IMPULSE;
          const cdot = side === 1 ? wB - wA : wA - wB;
          const old = d[o + at]!;
          const impulse = -axialMass * massScale * (cdot + bias) - impulseScale * old;
          const accumulated = Math.max(old + impulse, 0);
          const applied = accumulated - old;
          d[o + at] = accumulated;
          if (side === 1) {
            wA -= iA * applied;
            wB += iB * applied;
          } else {
            wA += iA * applied;
            wB -= iB * applied;
          }
        }
      }

      // The point constraint: both anchors at the same place.
      s[a + W] = wA;
      s[b + W] = wB;
      solveSoftPoint(s, a, b, d, o, LINEAR_IMPULSE_X, -1, useBias, step, true);

      if (!useBias) {
        d[o + STEP_IMPULSE_X] += d[o + LINEAR_IMPULSE_X]!;
        d[o + STEP_IMPULSE_Y] += d[o + LINEAR_IMPULSE_Y]!;
        d[o + STEP_ANGULAR_IMPULSE] +=
          d[o + SPRING_IMPULSE]! +
          d[o + MOTOR_IMPULSE]! +
          d[o + LOWER_IMPULSE]! -
          d[o + UPPER_IMPULSE]!;
      }
    }
  }
}
