import { DP_X, DP_Y, V_X, V_Y, W } from '../body-state.ts';
import type { JointStep } from './joint.ts';
import { turnedX, turnedY } from './joint-levers.ts';
import {
  DELTA_CENTER_X,
  DELTA_CENTER_Y,
  INV_I_A,
  INV_I_B,
  INV_MASS_A,
  INV_MASS_B,
  R_AX,
  R_BX,
} from './joint-record.ts';

/**
 * @internal The soft point constraint of one joint in a sub-step: B's anchor held on A's, both
 * directions solved together as a 2x2 block (Box2D v3's revolute and weld joints, Catto; the
 * softness is the soft step's, "Solver2D"). Reads the levers, masses and centre offset from the
 * record's head at `o` in `d`, the bodies' velocities and motion since the step's start from the
 * states `s` at `a` and `b`, and writes back both velocities and the accumulated impulse (at
 * `impulse`, x then y).
 *
 * The position error is corrected (a bias) in the biased pass with the step's joint softness, or
 * in both passes with the record's own (`softAt`: 1 when it applies, then bias rate, mass scale and
 * impulse scale; -1 when the record has none). `clamp` bounds the bias at the step's maxBiasSpeed.
 * Only integers cross the call (see dynamics/README.md: no fractional arguments).
 */
export function solveSoftPoint(
  s: Float64Array,
  a: number,
  b: number,
  d: Float64Array,
  o: number,
  impulse: number,
  softAt: number,
  useBias: boolean,
  step: JointStep,
  clamp: boolean,
): void {
  const mA = d[o + INV_MASS_A]!;
  const iA = d[o + INV_I_A]!;
  const mB = d[o + INV_MASS_B]!;
  const iB = d[o + INV_I_B]!;
  const vAx = s[a + V_X]!;
  const vAy = s[a + V_Y]!;
  const wA = s[a + W]!;
  const vBx = s[b + V_X]!;
  const vBy = s[b + V_Y]!;
  const wB = s[b + W]!;
  const rAx = turnedX(s, a, d, o + R_AX);
  const rAy = turnedY(s, a, d, o + R_AX);
  const rBx = turnedX(s, b, d, o + R_BX);
  const rBy = turnedY(s, b, d, o + R_BX);
  const cdotX = vBx - wB * rBy - (vAx - wA * rAy);
  const cdotY = vBy + wB * rBx - (vAy + wA * rAx);
  let biasX = 0;
  let biasY = 0;
  let massScale = 1;
  let impulseScale = 0;
  const springy = softAt >= 0 && d[o + softAt] === 1;
  if (useBias || springy) {
    // Summed in this order, not the other kinds' shiftX(...) + rBx - rAx: the bridge's, car's and
    // ragdoll's recorded hashes depend on it.
    const sepX = s[b + DP_X]! - s[a + DP_X]! + rBx - rAx + d[o + DELTA_CENTER_X]!;
    const sepY = s[b + DP_Y]! - s[a + DP_Y]! + rBy - rAy + d[o + DELTA_CENTER_Y]!;
    if (springy) {
      biasX = d[o + softAt + 1]! * sepX;
      biasY = d[o + softAt + 1]! * sepY;
      massScale = d[o + softAt + 2]!;
      impulseScale = d[o + softAt + 3]!;
    } else {
      const soft = step.softness;
      biasX = soft.biasRate * sepX;
      biasY = soft.biasRate * sepY;
      massScale = soft.massScale;
      impulseScale = soft.impulseScale;
    }
    if (clamp) {
      // At most maxBiasSpeed (see JointStep.maxBiasSpeed).
      const maxBias = step.maxBiasSpeed;
      const biasSquared = biasX * biasX + biasY * biasY;
      if (biasSquared > maxBias * maxBias) {
        const ratio = maxBias / Math.sqrt(biasSquared);
        biasX *= ratio;
        biasY *= ratio;
      }
    }
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
  const px = -massScale * solvedX - impulseScale * d[o + impulse]!;
  const py = -massScale * solvedY - impulseScale * d[o + impulse + 1]!;
  d[o + impulse] += px;
  d[o + impulse + 1] += py;
  s[a + V_X] = vAx - mA * px;
  s[a + V_Y] = vAy - mA * py;
  s[a + W] = wA - iA * (rAx * py - rAy * px);
  s[b + V_X] = vBx + mB * px;
  s[b + V_Y] = vBy + mB * py;
  s[b + W] = wB + iB * (rBx * py - rBy * px);
}
