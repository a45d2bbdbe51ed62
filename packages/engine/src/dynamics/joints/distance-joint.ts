import { PhysicalError, readOnly } from '../../core/errors.ts';
import {
  optionalBoolean,
  requireBoolean,
  requireNonNegative,
  requireRange,
} from '../../core/validate.ts';
import type { Vec2, Vec2Like } from '../../math/vec2.ts';
import { DP_X, DP_Y, Q_C, Q_S, V_X, V_Y, W } from '../body-state.ts';
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
  requireOrdered,
  jointMax,
  requirePoint,
  stateBoolean,
  stateNumber,
  worldAnchor,
} from './joint.ts';
import { hypot } from '../../math/hypot.ts';

/**
 * Options of a {@link DistanceJoint}: a rod between two points (rigid), or a spring of given
 * frequency and damping; with minLength and maxLength the length stays within a range (a rope is
 * a spring of 0 Hz with a maxLength).
 */
export interface DistanceJointOptions<UserData = unknown> extends JointOptions<UserData> {
  /** Point on body A (world, m). */
  readonly anchorA: Vec2Like;
  /** Point on body B (world, m). */
  readonly anchorB: Vec2Like;
  /** Rest length (m, >= 0). Default: the anchors' distance now. */
  readonly length?: number;
  /** Shortest length (m, >= 0). Default none (0). */
  readonly minLength?: number;
  /** Longest length (m). Default none. */
  readonly maxLength?: number;
  /** A spring instead of a rigid rod. Default false. */
  readonly enableSpring?: boolean;
  /** Spring frequency (Hz, >= 0); 0 means no spring force (only the length range holds). Default 0. */
  readonly hertz?: number;
  /** Spring damping ratio (>= 0; 1 is critical). Default 0. */
  readonly dampingRatio?: number;
}

/**
 * @internal A distance joint's options checked (a PhysicalError naming the first bad one), in the
 * order its constructor reads them, with defaults: the one check, also run where no joint is built
 * (a worker world's page).
 */
export function checkDistanceJointOptions(options: DistanceJointOptions<unknown>) {
  requireBodies(options);
  const anchorA = requirePoint('anchorA', options.anchorA);
  const anchorB = requirePoint('anchorB', options.anchorB);
  checkCollideConnected(options);
  const distance = hypot(anchorB.x - anchorA.x, anchorB.y - anchorA.y);
  const length = optionalNonNegative('length', options.length, distance);
  const minLength = optionalNonNegative('minLength', options.minLength, 0);
  const maxLength =
    options.maxLength === undefined
      ? Infinity
      : requireNonNegative('maxLength', options.maxLength, jointMax('maxLength'));
  requireOrdered('minLength', minLength, 'maxLength', maxLength);
  requireInRange(length, minLength, maxLength);
  return {
    anchorA,
    anchorB,
    length,
    minLength,
    maxLength,
    enableSpring: optionalBoolean('enableSpring', options.enableSpring, false),
    hertz: optionalNonNegative('hertz', options.hertz, 0),
    dampingRatio: optionalNonNegative('dampingRatio', options.dampingRatio, 0),
  };
}

/** @internal What a world snapshot saves of a distance joint (see Joint.exportState). */
export const DISTANCE_STATE: JointStateLayout = {
  fields: {
    localAnchorA: 'vector',
    localAnchorB: 'vector',
    length: 'nonNegative',
    minLength: 'nonNegative',
    maxLength: 'nonNegativeOrInfinity',
    enableSpring: 'boolean',
    hertz: 'nonNegative',
    dampingRatio: 'nonNegative',
    impulse: 'finite',
    lowerImpulse: 'nonNegative',
    upperImpulse: 'nonNegative',
  },
  ordered: [
    ['minLength', 'length'],
    ['length', 'maxLength'],
  ],
};

/**
 * Keeps two points at a distance, rigidly or as a damped spring, within an optional length range.
 * Box2D v3's distance joint (Catto): one row along the line between the anchors, recomputed each
 * pass from the current anchors; the rigid row softened by the joint softness, the spring by its
 * own, the range limits one-sided and speculative like contacts.
 */
export class DistanceJoint<UserData = unknown> extends Joint<UserData> {
  get type(): 'distance' {
    return 'distance';
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set type(_value: never) {
    readOnly('type', 'a joint keeps its kind');
  }
  /** @internal Anchors in each body's frame (relative to the body origin, m). */
  localAnchorAX = -0;
  /** @internal */
  localAnchorAY = -0;
  /** @internal */
  localAnchorBX = -0;
  /** @internal */
  localAnchorBY = -0;
  private rest: number;
  private min: number;
  private max: number;
  private springEnabled: boolean;
  private springHertz: number;
  private springDampingRatio: number;
  private rAx = -0;
  private rAy = -0;
  private rBx = -0;
  private rBy = -0;
  private deltaCenterX = -0;
  private deltaCenterY = -0;
  private readonly springSoftness = new Softness();
  private impulse = -0;
  /**
   * A spring slow enough for the sub-step (omega h <= 1) acts as a force, integrated by
   * semi-implicit Euler like gravity: symplectic, so an undamped spring keeps its energy. A soft
   * constraint (Box2D's spring) is implicit Euler and loses about 15 % of the amplitude per period
   * at 1 Hz. Stiffer springs stay soft constraints, which are stable at any stiffness.
   */
  private explicitSpring = false;
  private springOmega = -0;
  /** The explicit spring's impulse in the current sub-step (N s), for the reaction force. */
  private springSubStepImpulse = -0;
  private lowerImpulse = -0;
  private upperImpulse = -0;

  constructor(options: DistanceJointOptions<UserData>) {
    const checked = checkDistanceJointOptions(options);
    const { anchorA, anchorB } = checked;
    super(options, options.bodyA, options.bodyB);
    const localA = this.bodyA.getLocalPoint(anchorA);
    const localB = this.bodyB.getLocalPoint(anchorB);
    this.localAnchorAX = localA.x;
    this.localAnchorAY = localA.y;
    this.localAnchorBX = localB.x;
    this.localAnchorBY = localB.y;
    this.rest = checked.length;
    this.min = checked.minLength;
    this.max = checked.maxLength;
    this.springEnabled = checked.enableSpring;
    this.springHertz = checked.hertz;
    this.springDampingRatio = checked.dampingRatio;
  }

  /** @internal */
  protected writeAnchorA(out: Vec2): void {
    worldAnchor(this.bodyA, this.localAnchorAX, this.localAnchorAY, out);
  }

  /** @internal */
  protected writeAnchorB(out: Vec2): void {
    worldAnchor(this.bodyB, this.localAnchorBX, this.localAnchorBY, out);
  }

  /** Distance between the anchors now (m). */
  get currentLength(): number {
    const a = this.bodyA.getWorldPoint({ x: this.localAnchorAX, y: this.localAnchorAY });
    const b = this.bodyB.getWorldPoint({ x: this.localAnchorBX, y: this.localAnchorBY });
    return hypot(b.x - a.x, b.y - a.y);
  }

  /** Rest length (m), within [minLength, maxLength]. Setting it wakes the bodies. */
  get length(): number {
    return this.rest;
  }

  set length(value: number) {
    requireNonNegative('length', value, jointMax('length'));
    requireInRange(value, this.min, this.max);
    this.rest = value;
    this.wakeBodies();
  }

  /** Shortest length (m). */
  get minLength(): number {
    return this.min;
  }

  /** Longest length (m); Infinity when there is none. */
  get maxLength(): number {
    return this.max;
  }

  /** Sets the length range (m; maxLength may be Infinity for none); wakes the bodies. */
  setLengthRange(minLength: number, maxLength: number): void {
    requireNonNegative('minLength', minLength, jointMax('minLength'));
    if (maxLength !== Infinity) requireNonNegative('maxLength', maxLength, jointMax('maxLength'));
    requireOrdered('minLength', minLength, 'maxLength', maxLength);
    requireInRange(this.rest, minLength, maxLength);
    this.min = minLength;
    this.max = maxLength;
    this.wakeBodies();
  }

  /** Whether the joint is a spring (else a rigid rod). Changing it wakes the bodies. */
  get enableSpring(): boolean {
    return this.springEnabled;
  }

  set enableSpring(value: boolean) {
    requireBoolean('enableSpring', value);
    if (value === this.springEnabled) return;
    this.springEnabled = value;
    this.impulse = 0;
    this.wakeBodies();
  }

  /** Spring frequency (Hz). Setting it wakes the bodies. */
  get hertz(): number {
    return this.springHertz;
  }

  set hertz(value: number) {
    this.springHertz = requireNonNegative('hertz', value, jointMax('hertz'));
    this.wakeBodies();
  }

  /** Spring damping ratio. Setting it wakes the bodies. */
  get dampingRatio(): number {
    return this.springDampingRatio;
  }

  set dampingRatio(value: number) {
    this.springDampingRatio = requireNonNegative('dampingRatio', value, jointMax('dampingRatio'));
    this.wakeBodies();
  }

  /** @internal */
  protected exportOwnState(): JointState {
    return {
      localAnchorA: [this.localAnchorAX, this.localAnchorAY],
      localAnchorB: [this.localAnchorBX, this.localAnchorBY],
      length: this.rest,
      minLength: this.min,
      maxLength: this.max,
      enableSpring: this.springEnabled,
      hertz: this.springHertz,
      dampingRatio: this.springDampingRatio,
      impulse: this.impulse,
      lowerImpulse: this.lowerImpulse,
      upperImpulse: this.upperImpulse,
    };
  }

  /** @internal */
  protected importOwnState(state: JointState): void {
    importLocalAnchors(state, this);
    this.rest = stateNumber(state, 'length');
    this.min = stateNumber(state, 'minLength');
    this.max = stateNumber(state, 'maxLength');
    this.springEnabled = stateBoolean(state, 'enableSpring');
    this.springHertz = stateNumber(state, 'hertz');
    this.springDampingRatio = stateNumber(state, 'dampingRatio');
    this.impulse = stateNumber(state, 'impulse');
    this.lowerImpulse = stateNumber(state, 'lowerImpulse');
    this.upperImpulse = stateNumber(state, 'upperImpulse');
  }

  /** @internal */
  resetImpulses(): void {
    this.impulse = 0;
    this.lowerImpulse = 0;
    this.upperImpulse = 0;
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
    this.springSoftness.set(this.springHertz, this.springDampingRatio, step.h);
    if (this.springEnabled && this.springHertz === 0) this.impulse = 0;
    this.springOmega = 2 * Math.PI * this.springHertz;
    this.explicitSpring =
      this.springEnabled && this.springHertz > 0 && this.springOmega * step.h <= 1;
    // An explicit spring is a force of this sub-step, not a constraint impulse to warm start.
    if (this.explicitSpring) this.impulse = 0;
    this.springSubStepImpulse = 0;
    if (this.min === 0) this.lowerImpulse = 0;
    if (this.max === Infinity) this.upperImpulse = 0;
  }

  /** @internal */
  override createBatch(): DistanceBatch {
    return new DistanceBatch();
  }

  /** @internal Writes this step's solver numbers into a batch's slot at `o`. */
  loadBatch(d: Float64Array, o: number): void {
    d[o + R_AX] = this.rAx;
    d[o + R_AY] = this.rAy;
    d[o + R_BX] = this.rBx;
    d[o + R_BY] = this.rBy;
    d[o + DELTA_CENTER_X] = this.deltaCenterX;
    d[o + DELTA_CENTER_Y] = this.deltaCenterY;
    d[o + INV_MASS_A] = this.invMassA;
    d[o + INV_I_A] = this.invInertiaA;
    d[o + INV_MASS_B] = this.invMassB;
    d[o + INV_I_B] = this.invInertiaB;
    d[o + REST] = this.rest;
    d[o + MIN_LENGTH] = this.min;
    d[o + MAX_LENGTH] = this.max;
    d[o + EXPLICIT_SPRING] = this.explicitSpring ? 1 : 0;
    d[o + SPRING_OMEGA] = this.springOmega;
    d[o + SPRING_DAMPING_RATIO] = this.springDampingRatio;
    d[o + LENGTH_ROW_ON] = !this.springEnabled || this.springHertz > 0 ? 1 : 0;
    d[o + SPRING_ON] = this.springEnabled ? 1 : 0;
    d[o + SPRING_BIAS_RATE] = this.springSoftness.biasRate;
    d[o + SPRING_MASS_SCALE] = this.springSoftness.massScale;
    d[o + SPRING_IMPULSE_SCALE] = this.springSoftness.impulseScale;
    d[o + LOWER_ON] = this.springEnabled && this.min > 0 ? 1 : 0;
    d[o + UPPER_ON] = this.springEnabled && this.max !== Infinity ? 1 : 0;
    d[o + IMPULSE] = this.impulse;
    d[o + LOWER_IMPULSE] = this.lowerImpulse;
    d[o + UPPER_IMPULSE] = this.upperImpulse;
    d[o + SPRING_SUB_STEP_IMPULSE] = this.springSubStepImpulse;
    d[o + STEP_IMPULSE_X] = this.stepImpulseX;
    d[o + STEP_IMPULSE_Y] = this.stepImpulseY;
  }

  /** @internal Takes the step's impulses back from the batch's slot at `o`. */
  storeBatch(d: Float64Array, o: number): void {
    this.impulse = d[o + IMPULSE]!;
    this.lowerImpulse = d[o + LOWER_IMPULSE]!;
    this.upperImpulse = d[o + UPPER_IMPULSE]!;
    this.springSubStepImpulse = d[o + SPRING_SUB_STEP_IMPULSE]!;
    this.stepImpulseX = d[o + STEP_IMPULSE_X]!;
    this.stepImpulseY = d[o + STEP_IMPULSE_Y]!;
  }
}

/** Below this anchor distance (m) the joint has no direction and does nothing. */
const LENGTH_EPSILON = 1e-9;

// The distance joints of a step in flat arrays (DistanceBatch), doubles per joint. The joint has
// no angular row: its stepAngularImpulse stays on the joint, as prepareBodies cleared it.
const R_AX = 0; // levers from the centres to the anchors at the step's start (m)
const R_AY = 1;
const R_BX = 2;
const R_BY = 3;
const DELTA_CENTER_X = 4; // centre of B minus centre of A at the step's start (m)
const DELTA_CENTER_Y = 5;
const INV_MASS_A = 6;
const INV_I_A = 7;
const INV_MASS_B = 8;
const INV_I_B = 9;
const REST = 10; // rest length, shortest and longest length (m)
const MIN_LENGTH = 11;
const MAX_LENGTH = 12;
const EXPLICIT_SPRING = 13; // 1 or 0: the spring acts as a force (see explicitSpring)
const SPRING_OMEGA = 14;
const SPRING_DAMPING_RATIO = 15;
const LENGTH_ROW_ON = 16; // 1 or 0: the rod, or the spring as a soft constraint
const SPRING_ON = 17; // 1 or 0: enableSpring
const SPRING_BIAS_RATE = 18;
const SPRING_MASS_SCALE = 19;
const SPRING_IMPULSE_SCALE = 20;
const LOWER_ON = 21; // 1 or 0: the minLength row
const UPPER_ON = 22; // 1 or 0: the maxLength row
const IMPULSE = 23; // accumulated impulses (warm-started)
const LOWER_IMPULSE = 24;
const UPPER_IMPULSE = 25;
const SPRING_SUB_STEP_IMPULSE = 26; // the explicit spring's impulse in the current sub-step
const STEP_IMPULSE_X = 27; // summed over the step's relax passes, for the reaction
const STEP_IMPULSE_Y = 28;
const STRIDE = 29;

/**
 * @internal The distance joints of a step: their numbers in one Float64Array and their bodies'
 * state offsets in an Int32Array, solved in one loop per pass (see JointBatch).
 */
export class DistanceBatch extends FlatJointBatch<DistanceJoint> {
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
      const qAc = s[a + Q_C]!;
      const qAs = s[a + Q_S]!;
      const qBc = s[b + Q_C]!;
      const qBs = s[b + Q_S]!;
      const rAx = qAc * d[o + R_AX]! - qAs * d[o + R_AY]!;
      const rAy = qAs * d[o + R_AX]! + qAc * d[o + R_AY]!;
      const rBx = qBc * d[o + R_BX]! - qBs * d[o + R_BY]!;
      const rBy = qBs * d[o + R_BX]! + qBc * d[o + R_BY]!;
      const dx = s[b + DP_X]! - s[a + DP_X]! + d[o + DELTA_CENTER_X]! + rBx - rAx;
      const dy = s[b + DP_Y]! - s[a + DP_Y]! + d[o + DELTA_CENTER_Y]! + rBy - rAy;
      const length = Math.sqrt(dx * dx + dy * dy);
      if (!(length > LENGTH_EPSILON)) continue;
      const axial = d[o + IMPULSE]! + d[o + LOWER_IMPULSE]! - d[o + UPPER_IMPULSE]!;
      const px = (axial * dx) / length;
      const py = (axial * dy) / length;
      s[a + V_X] -= d[o + INV_MASS_A]! * px;
      s[a + V_Y] -= d[o + INV_MASS_A]! * py;
      s[a + W] -= d[o + INV_I_A]! * (rAx * py - rAy * px);
      s[b + V_X] += d[o + INV_MASS_B]! * px;
      s[b + V_Y] += d[o + INV_MASS_B]! * py;
      s[b + W] += d[o + INV_I_B]! * (rBx * py - rBy * px);
    }
  }

  solve(s: Float64Array, step: JointStep, useBias: boolean): void {
    const d = this.data;
    const states = this.states;
    const soft = step.softness;
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
      const qAc = s[a + Q_C]!;
      const qAs = s[a + Q_S]!;
      const qBc = s[b + Q_C]!;
      const qBs = s[b + Q_S]!;
      const rAx = qAc * d[o + R_AX]! - qAs * d[o + R_AY]!;
      const rAy = qAs * d[o + R_AX]! + qAc * d[o + R_AY]!;
      const rBx = qBc * d[o + R_BX]! - qBs * d[o + R_BY]!;
      const rBy = qBs * d[o + R_BX]! + qBc * d[o + R_BY]!;
      const dx = s[b + DP_X]! - s[a + DP_X]! + d[o + DELTA_CENTER_X]! + rBx - rAx;
      const dy = s[b + DP_Y]! - s[a + DP_Y]! + d[o + DELTA_CENTER_Y]! + rBy - rAy;
      const length = Math.sqrt(dx * dx + dy * dy);
      // Coincident anchors have no direction to push along.
      if (length > LENGTH_EPSILON) {
        const nx = dx / length;
        const ny = dy / length;
        const crA = rAx * ny - rAy * nx;
        const crB = rBx * ny - rBy * nx;
        const k = mA + mB + iA * crA * crA + iB * crB * crB;
        const axialMass = k > 0 ? 1 / k : 0;

        // The rod or the spring: C = length - rest.
        if (d[o + EXPLICIT_SPRING] === 1) {
          if (useBias) {
            // Spring force -k C - c Cdot over the sub-step, with k and c for the effective mass;
            // the damping part implicit, so no damping ratio can reverse the motion.
            const omega = d[o + SPRING_OMEGA]!;
            const damping = 2 * d[o + SPRING_DAMPING_RATIO]! * omega;
            const cdot =
              (vBx - wB * rBy - vAx + wA * rAy) * nx + (vBy + wB * rBx - vAy - wA * rAx) * ny;
            const impulse =
              (-axialMass * step.h * (omega * omega * (length - d[o + REST]!) + damping * cdot)) /
              (1 + damping * step.h);
            d[o + SPRING_SUB_STEP_IMPULSE] = impulse;
            const px = impulse * nx;
            const py = impulse * ny;
            vAx -= mA * px;
            vAy -= mA * py;
            wA -= iA * (rAx * py - rAy * px);
            vBx += mB * px;
            vBy += mB * py;
            wB += iB * (rBx * py - rBy * px);
          }
        } else if (d[o + LENGTH_ROW_ON] === 1) {
          let bias = 0;
          let massScale = 1;
          let impulseScale = 0;
          if (d[o + SPRING_ON] === 1) {
            bias = d[o + SPRING_BIAS_RATE]! * (length - d[o + REST]!);
            massScale = d[o + SPRING_MASS_SCALE]!;
            impulseScale = d[o + SPRING_IMPULSE_SCALE]!;
          } else if (useBias) {
            bias = soft.biasRate * (length - d[o + REST]!);
            massScale = soft.massScale;
            impulseScale = soft.impulseScale;
          }
          const cdot =
            (vBx - wB * rBy - vAx + wA * rAy) * nx + (vBy + wB * rBx - vAy - wA * rAx) * ny;
          const impulse = -massScale * axialMass * (cdot + bias) - impulseScale * d[o + IMPULSE]!;
          d[o + IMPULSE] += impulse;
          const px = impulse * nx;
          const py = impulse * ny;
          vAx -= mA * px;
          vAy -= mA * py;
          wA -= iA * (rAx * py - rAy * px);
          vBx += mB * px;
          vBy += mB * py;
          wB += iB * (rBx * py - rBy * px);
        }

        if (d[o + LOWER_ON] === 1) {
          // length >= minLength: pushes apart only.
          const c = length - d[o + MIN_LENGTH]!;
          let bias = 0;
          let massScale = 1;
          let impulseScale = 0;
          if (c > 0) bias = c * step.inverseH;
          else if (useBias) {
            bias = soft.biasRate * c;
            massScale = soft.massScale;
            impulseScale = soft.impulseScale;
          }
          const cdot =
            (vBx - wB * rBy - vAx + wA * rAy) * nx + (vBy + wB * rBx - vAy - wA * rAx) * ny;
          const old = d[o + LOWER_IMPULSE]!;
          const impulse = -massScale * axialMass * (cdot + bias) - impulseScale * old;
          const accumulated = Math.max(old + impulse, 0);
          const applied = accumulated - old;
          d[o + LOWER_IMPULSE] = accumulated;
          const px = applied * nx;
          const py = applied * ny;
          vAx -= mA * px;
          vAy -= mA * py;
          wA -= iA * (rAx * py - rAy * px);
          vBx += mB * px;
          vBy += mB * py;
          wB += iB * (rBx * py - rBy * px);
        }

        if (d[o + UPPER_ON] === 1) {
          // length <= maxLength: pulls together only (a rope).
          const c = d[o + MAX_LENGTH]! - length;
          let bias = 0;
          let massScale = 1;
          let impulseScale = 0;
          if (c > 0) bias = c * step.inverseH;
          else if (useBias) {
            bias = soft.biasRate * c;
            massScale = soft.massScale;
            impulseScale = soft.impulseScale;
          }
          const cdot = -(
            (vBx - wB * rBy - vAx + wA * rAy) * nx +
            (vBy + wB * rBx - vAy - wA * rAx) * ny
          );
          const old = d[o + UPPER_IMPULSE]!;
          const impulse = -massScale * axialMass * (cdot + bias) - impulseScale * old;
          const accumulated = Math.max(old + impulse, 0);
          const applied = accumulated - old;
          d[o + UPPER_IMPULSE] = accumulated;
          const px = -applied * nx;
          const py = -applied * ny;
          vAx -= mA * px;
          vAy -= mA * py;
          wA -= iA * (rAx * py - rAy * px);
          vBx += mB * px;
          vBy += mB * py;
          wB += iB * (rBx * py - rBy * px);
        }

        if (!useBias) {
          const axial =
            d[o + IMPULSE]! +
            d[o + SPRING_SUB_STEP_IMPULSE]! +
            d[o + LOWER_IMPULSE]! -
            d[o + UPPER_IMPULSE]!;
          d[o + STEP_IMPULSE_X] += axial * nx;
          d[o + STEP_IMPULSE_Y] += axial * ny;
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

function requireInRange(length: number, min: number, max: number): void {
  requireRange('length', length, -jointMax('length'), jointMax('length'));
  if (length < min || length > max) {
    throw new PhysicalError(
      'length',
      `must lie between minLength (${min}) and maxLength (${max}), got ${length}.`,
    );
  }
}
