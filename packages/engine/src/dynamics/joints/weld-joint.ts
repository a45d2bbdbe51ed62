import { requireNonNegative } from '../../core/validate.ts';
import type { Vec2, Vec2Like } from '../../math/vec2.ts';
import { DELTA_ANGLE, DP_X, DP_Y, Q_C, Q_S, V_X, V_Y, W } from '../body-state.ts';
import { Softness } from '../softness.ts';
import {
  Joint,
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
  readonly type = 'weld' as const;
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
    requireBodies(options);
    const anchor = requirePoint('anchor', options.anchor);
    super(options, options.bodyA, options.bodyB);
    const localA = this.bodyA.getLocalPoint(anchor);
    const localB = this.bodyB.getLocalPoint(anchor);
    this.localAnchorAX = localA.x;
    this.localAnchorAY = localA.y;
    this.localAnchorBX = localB.x;
    this.localAnchorBY = localB.y;
    this.referenceAngle = this.bodyB.angle - this.bodyA.angle;
    this.linearFrequency = optionalNonNegative('linearHertz', options.linearHertz, 0);
    this.angularFrequency = optionalNonNegative('angularHertz', options.angularHertz, 0);
    this.ratio = optionalNonNegative('dampingRatio', options.dampingRatio, 1);
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
  override warmStart(s: Float64Array): void {
    const a = this.stateA;
    const b = this.stateB;
    const rAx = s[a + Q_C]! * this.rAx - s[a + Q_S]! * this.rAy;
    const rAy = s[a + Q_S]! * this.rAx + s[a + Q_C]! * this.rAy;
    const rBx = s[b + Q_C]! * this.rBx - s[b + Q_S]! * this.rBy;
    const rBy = s[b + Q_S]! * this.rBx + s[b + Q_C]! * this.rBy;
    const px = this.linearImpulseX;
    const py = this.linearImpulseY;
    const angular = this.angularImpulse;
    s[a + V_X] -= this.invMassA * px;
    s[a + V_Y] -= this.invMassA * py;
    s[a + W] -= this.invInertiaA * (rAx * py - rAy * px + angular);
    s[b + V_X] += this.invMassB * px;
    s[b + V_Y] += this.invMassB * py;
    s[b + W] += this.invInertiaB * (rBx * py - rBy * px + angular);
  }

  /** @internal */
  override solve(s: Float64Array, step: JointStep, useBias: boolean): void {
    const a = this.stateA;
    const b = this.stateB;
    const mA = this.invMassA;
    const iA = this.invInertiaA;
    const mB = this.invMassB;
    const iB = this.invInertiaB;
    let vAx = s[a + V_X]!;
    let vAy = s[a + V_Y]!;
    let wA = s[a + W]!;
    let vBx = s[b + V_X]!;
    let vBy = s[b + V_Y]!;
    let wB = s[b + W]!;
    const rigid = step.softness;

    // Angle.
    {
      let bias = 0;
      let massScale = 1;
      let impulseScale = 0;
      const springy = this.angularFrequency > 0;
      if (useBias || springy) {
        const soft = springy ? this.angularSoftness : rigid;
        const c = this.deltaAngle + s[b + DELTA_ANGLE]! - s[a + DELTA_ANGLE]!;
        bias = soft.biasRate * c;
        massScale = soft.massScale;
        impulseScale = soft.impulseScale;
      }
      const impulse =
        -this.axialMass * massScale * (wB - wA + bias) - impulseScale * this.angularImpulse;
      this.angularImpulse += impulse;
      wA -= iA * impulse;
      wB += iB * impulse;
    }

    // Position of the anchor.
    {
      const qAc = s[a + Q_C]!;
      const qAs = s[a + Q_S]!;
      const qBc = s[b + Q_C]!;
      const qBs = s[b + Q_S]!;
      const rAx = qAc * this.rAx - qAs * this.rAy;
      const rAy = qAs * this.rAx + qAc * this.rAy;
      const rBx = qBc * this.rBx - qBs * this.rBy;
      const rBy = qBs * this.rBx + qBc * this.rBy;
      let biasX = 0;
      let biasY = 0;
      let massScale = 1;
      let impulseScale = 0;
      const springy = this.linearFrequency > 0;
      if (useBias || springy) {
        const soft = springy ? this.linearSoftness : rigid;
        const cx = s[b + DP_X]! - s[a + DP_X]! + rBx - rAx + this.deltaCenterX;
        const cy = s[b + DP_Y]! - s[a + DP_Y]! + rBy - rAy + this.deltaCenterY;
        biasX = soft.biasRate * cx;
        biasY = soft.biasRate * cy;
        massScale = soft.massScale;
        impulseScale = soft.impulseScale;
      }
      const cdotX = vBx - wB * rBy - (vAx - wA * rAy);
      const cdotY = vBy + wB * rBx - (vAy + wA * rAx);
      const k11 = mA + mB + rAy * rAy * iA + rBy * rBy * iB;
      const k12 = -rAy * rAx * iA - rBy * rBx * iB;
      const k22 = mA + mB + rAx * rAx * iA + rBx * rBx * iB;
      // 2x2 solve inlined: a call with number arguments would box them (allocate) per call.
      const bX = cdotX + biasX;
      const bY = cdotY + biasY;
      let det = k11 * k22 - k12 * k12;
      if (det !== 0) det = 1 / det;
      const solvedX = det * (k22 * bX - k12 * bY);
      const solvedY = det * (k11 * bY - k12 * bX);
      const px = -massScale * solvedX - impulseScale * this.linearImpulseX;
      const py = -massScale * solvedY - impulseScale * this.linearImpulseY;
      this.linearImpulseX += px;
      this.linearImpulseY += py;
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
      this.stepImpulseX += this.linearImpulseX;
      this.stepImpulseY += this.linearImpulseY;
      this.stepAngularImpulse += this.angularImpulse;
    }
  }
}
