import { DELTA_ANGLE, DP_X, DP_Y, Q_C, Q_S, V_X, V_Y, W } from '../body-state.ts';
import { FlatJointBatch } from './joint-batch.ts';
import type { JointStep } from './joint.ts';
import type { RevoluteJoint } from './revolute-joint.ts';

// The revolute joints of a step in flat arrays (RevoluteBatch), doubles per joint:
export const R_AX = 0; // levers from the centres to the anchors at the step's start (m)
export const R_AY = 1;
export const R_BX = 2;
export const R_BY = 3;
export const DELTA_CENTER_X = 4; // centre of B minus centre of A at the step's start (m)
export const DELTA_CENTER_Y = 5;
export const JOINT_ANGLE_0 = 6; // joint angle at the step's start (rad)
export const AXIAL_MASS = 7;
export const INV_MASS_A = 8;
export const INV_I_A = 9;
export const INV_MASS_B = 10;
export const INV_I_B = 11;
export const SPRING_ON = 12; // 1 or 0
export const SPRING_BIAS_RATE = 13;
export const SPRING_MASS_SCALE = 14;
export const SPRING_IMPULSE_SCALE = 15;
export const MOTOR_ON = 16;
export const MOTOR_SPEED = 17;
export const MAX_MOTOR_TORQUE = 18;
export const LIMIT_ON = 19;
export const LOWER = 20;
export const UPPER = 21;
export const LINEAR_IMPULSE_X = 22; // accumulated impulses (warm-started)
export const LINEAR_IMPULSE_Y = 23;
export const SPRING_IMPULSE = 24;
export const MOTOR_IMPULSE = 25;
export const LOWER_IMPULSE = 26;
export const UPPER_IMPULSE = 27;
export const STEP_IMPULSE_X = 28; // summed over the step's relax passes, for the reaction
export const STEP_IMPULSE_Y = 29;
export const STEP_ANGULAR_IMPULSE = 30;
export const STRIDE = 32;

/**
 * @internal The revolute joints of a step: their numbers in one Float64Array and their bodies'
 * state offsets in an Int32Array, solved in one loop per pass (see JointBatch).
 */
export class RevoluteBatch extends FlatJointBatch<RevoluteJoint> {
  constructor() {
    super(STRIDE);
  }

  warmStart(s: Float64Array): void {
    const d = this.data;
    const states = this.states;
    for (let i = 0; i < this.count; i++) {
      const o = i * STRIDE;
      const a = states[2 * i]!;
      const b = states[2 * i + 1]!;
      const mA = d[o + INV_MASS_A]!;
      const iA = d[o + INV_I_A]!;
      const mB = d[o + INV_MASS_B]!;
      const iB = d[o + INV_I_B]!;
      const rAx = s[a + Q_C]! * d[o + R_AX]! - s[a + Q_S]! * d[o + R_AY]!;
      const rAy = s[a + Q_S]! * d[o + R_AX]! + s[a + Q_C]! * d[o + R_AY]!;
      const rBx = s[b + Q_C]! * d[o + R_BX]! - s[b + Q_S]! * d[o + R_BY]!;
      const rBy = s[b + Q_S]! * d[o + R_BX]! + s[b + Q_C]! * d[o + R_BY]!;
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

  solve(s: Float64Array, step: JointStep, useBias: boolean): void {
    const d = this.data;
    const states = this.states;
    const soft = step.softness;
    const maxBias = step.maxBiasSpeed;
    for (let i = 0; i < this.count; i++) {
      const o = i * STRIDE;
      const a = states[2 * i]!;
      const b = states[2 * i + 1]!;
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
        const maxImpulse = step.h * d[o + MAX_MOTOR_TORQUE]!;
        const accumulated = Math.max(-maxImpulse, Math.min(old + impulse, maxImpulse));
        d[o + MOTOR_IMPULSE] = accumulated;
        const applied = accumulated - old;
        wA -= iA * applied;
        wB += iB * applied;
      }

      if (d[o + LIMIT_ON] === 1) {
        // Lower limit: C = angle - lower >= 0.
        {
          const c = jointAngle - d[o + LOWER]!;
          let bias = 0;
          let massScale = 1;
          let impulseScale = 0;
          if (c > 0) bias = c * step.inverseH;
          else if (useBias) {
            bias = soft.biasRate * c;
            massScale = soft.massScale;
            impulseScale = soft.impulseScale;
          }
          const old = d[o + LOWER_IMPULSE]!;
          const impulse = -axialMass * massScale * (wB - wA + bias) - impulseScale * old;
          const accumulated = Math.max(old + impulse, 0);
          const applied = accumulated - old;
          d[o + LOWER_IMPULSE] = accumulated;
          wA -= iA * applied;
          wB += iB * applied;
        }
        // Upper limit: C = upper - angle >= 0, the same row with the sign turned.
        {
          const c = d[o + UPPER]! - jointAngle;
          let bias = 0;
          let massScale = 1;
          let impulseScale = 0;
          if (c > 0) bias = c * step.inverseH;
          else if (useBias) {
            bias = soft.biasRate * c;
            massScale = soft.massScale;
            impulseScale = soft.impulseScale;
          }
          const old = d[o + UPPER_IMPULSE]!;
          const impulse = -axialMass * massScale * (wA - wB + bias) - impulseScale * old;
          const accumulated = Math.max(old + impulse, 0);
          const applied = accumulated - old;
          d[o + UPPER_IMPULSE] = accumulated;
          wA += iA * applied;
          wB -= iB * applied;
        }
      }

      // The point constraint: both anchors at the same place.
      {
        const qAc = s[a + Q_C]!;
        const qAs = s[a + Q_S]!;
        const qBc = s[b + Q_C]!;
        const qBs = s[b + Q_S]!;
        const rAx = qAc * d[o + R_AX]! - qAs * d[o + R_AY]!;
        const rAy = qAs * d[o + R_AX]! + qAc * d[o + R_AY]!;
        const rBx = qBc * d[o + R_BX]! - qBs * d[o + R_BY]!;
        const rBy = qBs * d[o + R_BX]! + qBc * d[o + R_BY]!;
        const cdotX = vBx - wB * rBy - (vAx - wA * rAy);
        const cdotY = vBy + wB * rBx - (vAy + wA * rAx);
        let biasX = 0;
        let biasY = 0;
        let massScale = 1;
        let impulseScale = 0;
        if (useBias) {
          const sepX = s[b + DP_X]! - s[a + DP_X]! + rBx - rAx + d[o + DELTA_CENTER_X]!;
          const sepY = s[b + DP_Y]! - s[a + DP_Y]! + rBy - rAy + d[o + DELTA_CENTER_Y]!;
          biasX = soft.biasRate * sepX;
          biasY = soft.biasRate * sepY;
          // At most maxBiasSpeed (see JointStep.maxBiasSpeed).
          const biasSquared = biasX * biasX + biasY * biasY;
          if (biasSquared > maxBias * maxBias) {
            const ratio = maxBias / Math.sqrt(biasSquared);
            biasX *= ratio;
            biasY *= ratio;
          }
          massScale = soft.massScale;
          impulseScale = soft.impulseScale;
        }
        const k11 = mA + mB + rAy * rAy * iA + rBy * rBy * iB;
        const k12 = -rAy * rAx * iA - rBy * rBx * iB;
        const k22 = mA + mB + rAx * rAx * iA + rBx * rBx * iB;
        const bX = cdotX + biasX;
        const bY = cdotY + biasY;
        let det = k11 * k22 - k12 * k12;
        if (det !== 0) det = 1 / det;
        const solvedX = det * (k22 * bX - k12 * bY);
        const solvedY = det * (k11 * bY - k12 * bX);
        const px = -massScale * solvedX - impulseScale * d[o + LINEAR_IMPULSE_X]!;
        const py = -massScale * solvedY - impulseScale * d[o + LINEAR_IMPULSE_Y]!;
        d[o + LINEAR_IMPULSE_X] += px;
        d[o + LINEAR_IMPULSE_Y] += py;
        vAx -= mA * px;
        vAy -= mA * py;
        wA -= iA * (rAx * py - rAy * px);
        vBx += mB * px;
        vBy += mB * py;
        wB += iB * (rBx * py - rBy * px);
      }

      s[a + V_X] = vAx;
      s[a + V_Y] = vAy;
      s[a + W] = wA;
      s[b + V_X] = vBx;
      s[b + V_Y] = vBy;
      s[b + W] = wB;

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
