import { readOnly } from '../../core/errors.ts';
import { requireNonNegative } from '../../core/validate.ts';
import type { Vec2, Vec2Like } from '../../math/vec2.ts';
import { DELTA_ANGLE, DP_X, DP_Y, Q_C, Q_S, V_X, V_Y, W } from '../body-state.ts';
import { Softness } from '../softness.ts';
import { FlatJointBatch } from './joint-batch.ts';
import {
  Joint,
  checkCollideConnected,
  type JointOptions,
  type JointState,
  type JointStateLayout,
  type JointStep,
  importLocalAnchors,
  optionalNonNegative,
  requireBodies,
  jointMax,
  requirePoint,
  stateNumber,
  stateVector,
  worldAnchor,
} from './joint.ts';

/** Options of a {@link WeldJoint}: glues two bodies together, rigidly or springily. */
export interface WeldJointOptions<UserData = unknown> extends JointOptions<UserData> {
  /** The point where the bodies are glued (world, m). */
  readonly anchor: Vec2Like;
  /** Stiffness of the position hold (Hz, >= 0); 0 is rigid. Default 0. */
  readonly linearHertz?: number;
  /** Stiffness of the angle hold (Hz, >= 0); 0 is rigid. Default 0. */
  readonly angularHertz?: number;
  /** Damping ratio of the soft holds (>= 0). Default 1. */
  readonly dampingRatio?: number;
}

/**
 * @internal A weld joint's options checked (a PhysicalError naming the first bad one), in the
 * order its constructor reads them, with defaults: the one check, also run where no joint is built
 * (a worker world's page).
 */
export function checkWeldJointOptions(options: WeldJointOptions<unknown>) {
  requireBodies(options);
  const anchor = requirePoint('anchor', options.anchor);
  checkCollideConnected(options);
  return {
    anchor,
    linearHertz: optionalNonNegative('linearHertz', options.linearHertz, 0),
    angularHertz: optionalNonNegative('angularHertz', options.angularHertz, 0),
    dampingRatio: optionalNonNegative('dampingRatio', options.dampingRatio, 1),
  };
}

/** @internal What a world snapshot saves of a weld joint (see Joint.exportState). */
export const WELD_STATE: JointStateLayout = {
  fields: {
    localAnchorA: 'vector',
    localAnchorB: 'vector',
    referenceAngle: 'finite',
    linearHertz: 'nonNegative',
    angularHertz: 'nonNegative',
    dampingRatio: 'nonNegative',
    linearImpulse: 'vector',
    angularImpulse: 'finite',
  },
  ordered: [],
};

/**
 * Holds body B at a fixed position and angle relative to body A: rigid, or a spring in position
 * and/or angle (a soft weld makes a springy diving board). Box2D v3's weld joint (Catto): an
 * angular row, then a 2x2 point block; a rigid part corrects its error with the joint softness in
 * the biased pass only, a soft part with its own softness in both passes.
 */
export class WeldJoint<UserData = unknown> extends Joint<UserData> {
  get type(): 'weld' {
    return 'weld';
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set type(_value: never) {
    readOnly('type', 'a joint keeps its kind');
  }
  /** @internal Anchor in each body's frame (relative to the body origin, m). */
  localAnchorAX = -0;
  /** @internal */
  localAnchorAY = -0;
  /** @internal */
  localAnchorBX = -0;
  /** @internal */
  localAnchorBY = -0;
  /** @internal angleB - angleA at creation (rad). */
  referenceAngle = -0;
  private linearFrequency: number;
  private angularFrequency: number;
  private ratio: number;
  private rAx = -0;
  private rAy = -0;
  private rBx = -0;
  private rBy = -0;
  private deltaCenterX = -0;
  private deltaCenterY = -0;
  private deltaAngle = -0;
  private axialMass = -0;
  private readonly linearSoftness = new Softness();
  private readonly angularSoftness = new Softness();
  private linearImpulseX = -0;
  private linearImpulseY = -0;
  private angularImpulse = -0;

  constructor(options: WeldJointOptions<UserData>) {
    const checked = checkWeldJointOptions(options);
    const anchor = checked.anchor;
    super(options, options.bodyA, options.bodyB);
    const localA = this.bodyA.getLocalPoint(anchor);
    const localB = this.bodyB.getLocalPoint(anchor);
    this.localAnchorAX = localA.x;
    this.localAnchorAY = localA.y;
    this.localAnchorBX = localB.x;
    this.localAnchorBY = localB.y;
    this.referenceAngle = this.bodyB.angle - this.bodyA.angle;
    this.linearFrequency = checked.linearHertz;
    this.angularFrequency = checked.angularHertz;
    this.ratio = checked.dampingRatio;
  }

  /** @internal */
  protected writeAnchorA(out: Vec2): void {
    worldAnchor(this.bodyA, this.localAnchorAX, this.localAnchorAY, out);
  }

  /** @internal */
  protected writeAnchorB(out: Vec2): void {
    worldAnchor(this.bodyB, this.localAnchorBX, this.localAnchorBY, out);
  }

  /** Stiffness of the position hold (Hz); 0 is rigid. Setting it wakes the bodies. */
  get linearHertz(): number {
    return this.linearFrequency;
  }

  set linearHertz(value: number) {
    this.linearFrequency = requireNonNegative('linearHertz', value, jointMax('linearHertz'));
    this.wakeBodies();
  }

  /** Stiffness of the angle hold (Hz); 0 is rigid. Setting it wakes the bodies. */
  get angularHertz(): number {
    return this.angularFrequency;
  }

  set angularHertz(value: number) {
    this.angularFrequency = requireNonNegative('angularHertz', value, jointMax('angularHertz'));
    this.wakeBodies();
  }

  /** Damping ratio of the soft holds. Setting it wakes the bodies. */
  get dampingRatio(): number {
    return this.ratio;
  }

  set dampingRatio(value: number) {
    this.ratio = requireNonNegative('dampingRatio', value, jointMax('dampingRatio'));
    this.wakeBodies();
  }

  /** @internal */
  protected exportOwnState(): JointState {
    return {
      localAnchorA: [this.localAnchorAX, this.localAnchorAY],
      localAnchorB: [this.localAnchorBX, this.localAnchorBY],
      referenceAngle: this.referenceAngle,
      linearHertz: this.linearFrequency,
      angularHertz: this.angularFrequency,
      dampingRatio: this.ratio,
      linearImpulse: [this.linearImpulseX, this.linearImpulseY],
      angularImpulse: this.angularImpulse,
    };
  }

  /** @internal */
  protected importOwnState(state: JointState): void {
    importLocalAnchors(state, this);
    const impulse = stateVector(state, 'linearImpulse');
    this.referenceAngle = stateNumber(state, 'referenceAngle');
    this.linearFrequency = stateNumber(state, 'linearHertz');
    this.angularFrequency = stateNumber(state, 'angularHertz');
    this.ratio = stateNumber(state, 'dampingRatio');
    this.linearImpulseX = impulse[0]!;
    this.linearImpulseY = impulse[1]!;
    this.angularImpulse = stateNumber(state, 'angularImpulse');
  }

  /** @internal */
  resetImpulses(): void {
    this.linearImpulseX = 0;
    this.linearImpulseY = 0;
    this.angularImpulse = 0;
  }

  /** @internal */
  prepare(step: JointStep): void {
    this.prepareBodies(step);
    const a = this.bodyA;
    const b = this.bodyB;
    const ta = a.transform;
    const tb = b.transform;
    const lAx = this.localAnchorAX - a.localCenterX;
    const lAy = this.localAnchorAY - a.localCenterY;
    const lBx = this.localAnchorBX - b.localCenterX;
    const lBy = this.localAnchorBY - b.localCenterY;
    this.rAx = ta.c * lAx - ta.s * lAy;
    this.rAy = ta.s * lAx + ta.c * lAy;
    this.rBx = tb.c * lBx - tb.s * lBy;
    this.rBy = tb.s * lBx + tb.c * lBy;
    this.deltaCenterX = b.centerX - a.centerX;
    this.deltaCenterY = b.centerY - a.centerY;
    this.deltaAngle = b.angleValue - a.angleValue - this.referenceAngle;
    const k = this.invInertiaA + this.invInertiaB;
    this.axialMass = k > 0 ? 1 / k : 0;
    if (this.linearFrequency === 0) this.linearSoftness.set(0, 0, step.h);
    else this.linearSoftness.set(this.linearFrequency, this.ratio, step.h);
    if (this.angularFrequency === 0) this.angularSoftness.set(0, 0, step.h);
    else this.angularSoftness.set(this.angularFrequency, this.ratio, step.h);
  }

  /** @internal */
  override createBatch(): WeldBatch {
    return new WeldBatch();
  }

  /** @internal Writes this step's solver numbers into a batch's slot at `o`. */
  loadBatch(d: Float64Array, o: number): void {
    d[o + R_AX] = this.rAx;
    d[o + R_AY] = this.rAy;
    d[o + R_BX] = this.rBx;
    d[o + R_BY] = this.rBy;
    d[o + DELTA_CENTER_X] = this.deltaCenterX;
    d[o + DELTA_CENTER_Y] = this.deltaCenterY;
    d[o + JOINT_ANGLE_0] = this.deltaAngle;
    d[o + AXIAL_MASS] = this.axialMass;
    d[o + INV_MASS_A] = this.invMassA;
    d[o + INV_I_A] = this.invInertiaA;
    d[o + INV_MASS_B] = this.invMassB;
    d[o + INV_I_B] = this.invInertiaB;
    d[o + LINEAR_SPRINGY] = this.linearFrequency > 0 ? 1 : 0;
    d[o + LINEAR_BIAS_RATE] = this.linearSoftness.biasRate;
    d[o + LINEAR_MASS_SCALE] = this.linearSoftness.massScale;
    d[o + LINEAR_IMPULSE_SCALE] = this.linearSoftness.impulseScale;
    d[o + ANGULAR_SPRINGY] = this.angularFrequency > 0 ? 1 : 0;
    d[o + ANGULAR_BIAS_RATE] = this.angularSoftness.biasRate;
    d[o + ANGULAR_MASS_SCALE] = this.angularSoftness.massScale;
    d[o + ANGULAR_IMPULSE_SCALE] = this.angularSoftness.impulseScale;
    d[o + LINEAR_IMPULSE_X] = this.linearImpulseX;
    d[o + LINEAR_IMPULSE_Y] = this.linearImpulseY;
    d[o + ANGULAR_IMPULSE] = this.angularImpulse;
    d[o + STEP_IMPULSE_X] = this.stepImpulseX;
    d[o + STEP_IMPULSE_Y] = this.stepImpulseY;
    d[o + STEP_ANGULAR_IMPULSE] = this.stepAngularImpulse;
  }

  /** @internal Takes the step's impulses back from the batch's slot at `o`. */
  storeBatch(d: Float64Array, o: number): void {
    this.linearImpulseX = d[o + LINEAR_IMPULSE_X]!;
    this.linearImpulseY = d[o + LINEAR_IMPULSE_Y]!;
    this.angularImpulse = d[o + ANGULAR_IMPULSE]!;
    this.stepImpulseX = d[o + STEP_IMPULSE_X]!;
    this.stepImpulseY = d[o + STEP_IMPULSE_Y]!;
    this.stepAngularImpulse = d[o + STEP_ANGULAR_IMPULSE]!;
  }
}

// The weld joints of a step in flat arrays (WeldBatch), doubles per joint:
const R_AX = 0; // levers from the centres to the anchors at the step's start (m)
const R_AY = 1;
const R_BX = 2;
const R_BY = 3;
const DELTA_CENTER_X = 4; // centre of B minus centre of A at the step's start (m)
const DELTA_CENTER_Y = 5;
const JOINT_ANGLE_0 = 6; // angle error at the step's start (rad)
const AXIAL_MASS = 7;
const INV_MASS_A = 8;
const INV_I_A = 9;
const INV_MASS_B = 10;
const INV_I_B = 11;
const LINEAR_SPRINGY = 12; // 1: the position hold has its own softness, in both passes; 0: rigid
const LINEAR_BIAS_RATE = 13;
const LINEAR_MASS_SCALE = 14;
const LINEAR_IMPULSE_SCALE = 15;
const ANGULAR_SPRINGY = 16; // the same for the angle hold
const ANGULAR_BIAS_RATE = 17;
const ANGULAR_MASS_SCALE = 18;
const ANGULAR_IMPULSE_SCALE = 19;
const LINEAR_IMPULSE_X = 20; // accumulated impulses (warm-started)
const LINEAR_IMPULSE_Y = 21;
const ANGULAR_IMPULSE = 22;
const STEP_IMPULSE_X = 23; // summed over the step's relax passes, for the reaction
const STEP_IMPULSE_Y = 24;
const STEP_ANGULAR_IMPULSE = 25;
const STRIDE = 26;

/**
 * @internal The weld joints of a step: their numbers in one Float64Array and their bodies' state
 * offsets in an Int32Array, solved in one loop per pass (see JointBatch).
 */
export class WeldBatch extends FlatJointBatch<WeldJoint> {
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
      const rAx = s[a + Q_C]! * d[o + R_AX]! - s[a + Q_S]! * d[o + R_AY]!;
      const rAy = s[a + Q_S]! * d[o + R_AX]! + s[a + Q_C]! * d[o + R_AY]!;
      const rBx = s[b + Q_C]! * d[o + R_BX]! - s[b + Q_S]! * d[o + R_BY]!;
      const rBy = s[b + Q_S]! * d[o + R_BX]! + s[b + Q_C]! * d[o + R_BY]!;
      const px = d[o + LINEAR_IMPULSE_X]!;
      const py = d[o + LINEAR_IMPULSE_Y]!;
      const angular = d[o + ANGULAR_IMPULSE]!;
      s[a + V_X] -= d[o + INV_MASS_A]! * px;
      s[a + V_Y] -= d[o + INV_MASS_A]! * py;
      s[a + W] -= d[o + INV_I_A]! * (rAx * py - rAy * px + angular);
      s[b + V_X] += d[o + INV_MASS_B]! * px;
      s[b + V_Y] += d[o + INV_MASS_B]! * py;
      s[b + W] += d[o + INV_I_B]! * (rBx * py - rBy * px + angular);
    }
  }

  solve(s: Float64Array, step: JointStep, useBias: boolean): void {
    const d = this.data;
    const states = this.states;
    const rigid = step.softness;
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

      // Angle.
      {
        let bias = 0;
        let massScale = 1;
        let impulseScale = 0;
        const springy = d[o + ANGULAR_SPRINGY] === 1;
        if (useBias || springy) {
          const c = d[o + JOINT_ANGLE_0]! + s[b + DELTA_ANGLE]! - s[a + DELTA_ANGLE]!;
          if (springy) {
            bias = d[o + ANGULAR_BIAS_RATE]! * c;
            massScale = d[o + ANGULAR_MASS_SCALE]!;
            impulseScale = d[o + ANGULAR_IMPULSE_SCALE]!;
          } else {
            bias = rigid.biasRate * c;
            massScale = rigid.massScale;
            impulseScale = rigid.impulseScale;
          }
        }
        const impulse =
          -d[o + AXIAL_MASS]! * massScale * (wB - wA + bias) -
          impulseScale * d[o + ANGULAR_IMPULSE]!;
        d[o + ANGULAR_IMPULSE] += impulse;
        wA -= iA * impulse;
        wB += iB * impulse;
      }

      // Position of the anchor.
      {
        const qAc = s[a + Q_C]!;
        const qAs = s[a + Q_S]!;
        const qBc = s[b + Q_C]!;
        const qBs = s[b + Q_S]!;
        const rAx = qAc * d[o + R_AX]! - qAs * d[o + R_AY]!;
        const rAy = qAs * d[o + R_AX]! + qAc * d[o + R_AY]!;
        const rBx = qBc * d[o + R_BX]! - qBs * d[o + R_BY]!;
        const rBy = qBs * d[o + R_BX]! + qBc * d[o + R_BY]!;
        let biasX = 0;
        let biasY = 0;
        let massScale = 1;
        let impulseScale = 0;
        const springy = d[o + LINEAR_SPRINGY] === 1;
        if (useBias || springy) {
          const cx = s[b + DP_X]! - s[a + DP_X]! + rBx - rAx + d[o + DELTA_CENTER_X]!;
          const cy = s[b + DP_Y]! - s[a + DP_Y]! + rBy - rAy + d[o + DELTA_CENTER_Y]!;
          if (springy) {
            biasX = d[o + LINEAR_BIAS_RATE]! * cx;
            biasY = d[o + LINEAR_BIAS_RATE]! * cy;
            massScale = d[o + LINEAR_MASS_SCALE]!;
            impulseScale = d[o + LINEAR_IMPULSE_SCALE]!;
          } else {
            biasX = rigid.biasRate * cx;
            biasY = rigid.biasRate * cy;
            massScale = rigid.massScale;
            impulseScale = rigid.impulseScale;
          }
        }
        const cdotX = vBx - wB * rBy - (vAx - wA * rAy);
        const cdotY = vBy + wB * rBx - (vAy + wA * rAx);
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
        d[o + STEP_ANGULAR_IMPULSE] += d[o + ANGULAR_IMPULSE]!;
      }
    }
  }
}
