import { DELTA_ANGLE, V_X, V_Y, W } from '../body-state.ts';
import { JointBatch } from './joint-batch.ts';
import type { SolverMemory } from '../solver-memory.ts';
import type { JointStep } from './joint.ts';
import { shiftX, shiftY, turnedX, turnedY } from './joint-levers.ts';
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

// A prismatic joint's record: the head (joint-record.ts), the spring, motor and limit on its
// translation (spring-motor-limit.ts), then these (literals, as the passes read them best;
// joint-layouts.test.ts checks they follow on and do not overlap):
export const LOCAL_AXIS_X = 42; // SPRING_MOTOR_LIMIT_END; the slide's direction in A's frame (unit)
export const LOCAL_AXIS_Y = 43; // SPRING_MOTOR_LIMIT_END + 1
export const AXIS_X = 44; // SPRING_MOTOR_LIMIT_END + 2; the axis in world orientation at the step's start
export const AXIS_Y = 45; // SPRING_MOTOR_LIMIT_END + 3
export const PERPENDICULAR_IMPULSE = 46; // SPRING_MOTOR_LIMIT_END + 4; accumulated (warm-started)
export const ANGULAR_IMPULSE = 47; // SPRING_MOTOR_LIMIT_END + 5
export const STRIDE = 48; // SPRING_MOTOR_LIMIT_END + 6

/**
 * @internal The prismatic joints of a world: their records, and the step's active ones solved in
 * one loop per pass (see JointBatch).
 */
export class PrismaticBatch extends JointBatch {
  warmStart(s: Float64Array, memory: SolverMemory): void {
    const d = memory.jointStore.data;
    const list = memory.jointActive;
    const end = this.start + this.active;
    for (let i = this.start; i < end; i++) {
      const o = list[3 * i]!;
      const a = list[3 * i + 1]!;
      const b = list[3 * i + 2]!;
      const rAx = turnedX(s, a, d, o + R_AX);
      const rAy = turnedY(s, a, d, o + R_AX);
      const rBx = turnedX(s, b, d, o + R_BX);
      const rBy = turnedY(s, b, d, o + R_BX);
      const dx = shiftX(s, a, b, d, o) + rBx - rAx;
      const dy = shiftY(s, a, b, d, o) + rBy - rAy;
      const ax = turnedX(s, a, d, o + AXIS_X);
      const ay = turnedY(s, a, d, o + AXIS_X);
      // Lever arms of the axial and perpendicular rows (A's arm reaches B's anchor: d + rA).
      const a1 = (dx + rAx) * ay - (dy + rAy) * ax;
      const a2 = rBx * ay - rBy * ax;
      const px = -ay;
      const py = ax;
      const s1 = (dx + rAx) * py - (dy + rAy) * px;
      const s2 = rBx * py - rBy * px;
      const axial =
        d[o + SPRING_IMPULSE]! +
        d[o + MOTOR_IMPULSE]! +
        d[o + LOWER_IMPULSE]! -
        d[o + UPPER_IMPULSE]!;
      const perpendicular = d[o + PERPENDICULAR_IMPULSE]!;
      const angular = d[o + ANGULAR_IMPULSE]!;
      const fx = axial * ax + perpendicular * px;
      const fy = axial * ay + perpendicular * py;
      const lA = axial * a1 + perpendicular * s1 + angular;
      const lB = axial * a2 + perpendicular * s2 + angular;
      s[a + V_X] -= d[o + INV_MASS_A]! * fx;
      s[a + V_Y] -= d[o + INV_MASS_A]! * fy;
      s[a + W] -= d[o + INV_I_A]! * lA;
      s[b + V_X] += d[o + INV_MASS_B]! * fx;
      s[b + V_Y] += d[o + INV_MASS_B]! * fy;
      s[b + W] += d[o + INV_I_B]! * lB;
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
      const mA = d[o + INV_MASS_A]!;
      const iA = d[o + INV_I_A]!;
      const mB = d[o + INV_MASS_B]!;
      const iB = d[o + INV_I_B]!;
      let vAx = s[a + V_X]!;
      let vAy = s[a + V_Y]!;
      let wA = s[a + W]!;
      let vBx = s[b + V_X]!;
      let vBy = s[b + V_Y]!;
      let wB = s[b + W]!;
      const rAx = turnedX(s, a, d, o + R_AX);
      const rAy = turnedY(s, a, d, o + R_AX);
      const rBx = turnedX(s, b, d, o + R_BX);
      const rBy = turnedY(s, b, d, o + R_BX);
      const dx = shiftX(s, a, b, d, o) + rBx - rAx;
      const dy = shiftY(s, a, b, d, o) + rBy - rAy;
      const ax = turnedX(s, a, d, o + AXIS_X);
      const ay = turnedY(s, a, d, o + AXIS_X);
      const translation = ax * dx + ay * dy;
      const a1 = (dx + rAx) * ay - (dy + rAy) * ax;
      const a2 = rBx * ay - rBy * ax;
      const kAxial = mA + mB + iA * a1 * a1 + iB * a2 * a2;
      const axialMass = kAxial > 0 ? 1 / kAxial : 0;

      // The rows along the axis, one after another, each on the velocities the one before left:
      // the spring (row 0), the motor (1), translation >= lower (2) and translation <= upper (3).
      // Each gives the impulse `push` on B along the axis (on A the opposite), applied in one place.
      for (let row = 0; row < 4; row++) {
        if (d[o + (row === 0 ? SPRING_ON : row === 1 ? MOTOR_ON : LIMIT_ON)] !== 1) continue;
        let push: number;
        if (row < 2) {
          const cdot = ax * (vBx - vAx) + ay * (vBy - vAy) + a2 * wB - a1 * wA;
          if (row === 0) {
            push =
              -d[o + SPRING_MASS_SCALE]! *
                axialMass *
                (cdot + d[o + SPRING_BIAS_RATE]! * translation) -
              d[o + SPRING_IMPULSE_SCALE]! * d[o + SPRING_IMPULSE]!;
            d[o + SPRING_IMPULSE] += push;
          } else {
            const impulse = axialMass * (d[o + MOTOR_SPEED]! - cdot);
            const old = d[o + MOTOR_IMPULSE]!;
            const maxImpulse = step.h * d[o + MAX_MOTOR]!;
            const accumulated = Math.max(-maxImpulse, Math.min(old + impulse, maxImpulse));
            d[o + MOTOR_IMPULSE] = accumulated;
            push = accumulated - old;
          }
        } else {
          // Lower: translation - lower >= 0; upper: upper - translation >= 0, the same row with
          // the sign turned. Speculative like contacts: a gap may close within the sub-step.
          const lower = row === 2;
          const c = lower ? translation - d[o + LOWER]! : d[o + UPPER]! - translation;
          let bias = 0;
          let massScale = 1;
          let impulseScale = 0;
          if (c > 0) bias = c * step.inverseH;
          else if (useBias) {
            bias = soft.biasRate * c;
            massScale = soft.massScale;
            impulseScale = soft.impulseScale;
          }
          const cdot = lower
            ? ax * (vBx - vAx) + ay * (vBy - vAy) + a2 * wB - a1 * wA
            : ax * (vAx - vBx) + ay * (vAy - vBy) + a1 * wA - a2 * wB;
          const at = lower ? LOWER_IMPULSE : UPPER_IMPULSE;
          const old = d[o + at]!;
          const impulse = -axialMass * massScale * (cdot + bias) - impulseScale * old;
          const accumulated = Math.max(old + impulse, 0);
          d[o + at] = accumulated;
          push = lower ? accumulated - old : -(accumulated - old);
        }
        vAx -= mA * push * ax;
        vAy -= mA * push * ay;
        wA -= iA * push * a1;
        vBx += mB * push * ax;
        vBy += mB * push * ay;
        wB += iB * push * a2;
      }

      // Perpendicular offset and relative angle, solved together.
      {
        const px = -ay;
        const py = ax;
        const s1 = (dx + rAx) * py - (dy + rAy) * px;
        const s2 = rBx * py - rBy * px;
        const cdot1 = px * (vBx - vAx) + py * (vBy - vAy) + s2 * wB - s1 * wA;
        const cdot2 = wB - wA;
        let bias1 = 0;
        let bias2 = 0;
        let massScale = 1;
        let impulseScale = 0;
        if (useBias) {
          bias1 = soft.biasRate * (px * dx + py * dy);
          bias2 =
            soft.biasRate * (d[o + JOINT_ANGLE_0]! + s[b + DELTA_ANGLE]! - s[a + DELTA_ANGLE]!);
          massScale = soft.massScale;
          impulseScale = soft.impulseScale;
        }
        const k11 = mA + mB + iA * s1 * s1 + iB * s2 * s2;
        const k12 = iA * s1 + iB * s2;
        let k22 = iA + iB;
        if (k22 === 0) k22 = 1; // neither body turns: the angle row is idle
        const bX = cdot1 + bias1;
        const bY = cdot2 + bias2;
        let det = k11 * k22 - k12 * k12;
        if (det !== 0) det = 1 / det;
        const solvedX = det * (k22 * bX - k12 * bY);
        const solvedY = det * (k11 * bY - k12 * bX);
        const impulse1 = -massScale * solvedX - impulseScale * d[o + PERPENDICULAR_IMPULSE]!;
        const impulse2 = -massScale * solvedY - impulseScale * d[o + ANGULAR_IMPULSE]!;
        d[o + PERPENDICULAR_IMPULSE] += impulse1;
        d[o + ANGULAR_IMPULSE] += impulse2;
        const fx = impulse1 * px;
        const fy = impulse1 * py;
        const lA = impulse1 * s1 + impulse2;
        const lB = impulse1 * s2 + impulse2;
        vAx -= mA * fx;
        vAy -= mA * fy;
        wA -= iA * lA;
        vBx += mB * fx;
        vBy += mB * fy;
        wB += iB * lB;

        if (!useBias) {
          const axial =
            d[o + SPRING_IMPULSE]! +
            d[o + MOTOR_IMPULSE]! +
            d[o + LOWER_IMPULSE]! -
            d[o + UPPER_IMPULSE]!;
          d[o + STEP_IMPULSE_X] += axial * ax + d[o + PERPENDICULAR_IMPULSE]! * px;
          d[o + STEP_IMPULSE_Y] += axial * ay + d[o + PERPENDICULAR_IMPULSE]! * py;
          d[o + STEP_ANGULAR_IMPULSE] += d[o + ANGULAR_IMPULSE]!;
        }
      }

      s[a + V_X] = vAx;
      s[a + V_Y] = vAy;
      s[a + W] = wA;
      s[b + V_X] = vBx;
      s[b + V_Y] = vBy;
      s[b + W] = wB;
    }
  }
}
