import { readOnly } from '../../core/errors.ts';
import {
  optionalBoolean,
  requireBoolean,
  requireNonNegative,
  requireRange,
} from '../../core/validate.ts';
import type { Vec2, Vec2Like } from '../../math/vec2.ts';
import { DELTA_ANGLE, DP_X, DP_Y, Q_C, Q_S, V_X, V_Y, W } from '../body-state.ts';
import { Softness } from '../softness.ts';
import { PinChains, type PinJoint } from './pin-chains.ts';
import { FlatJointBatch, type BatchedJoint } from './joint-batch.ts';
import {
  Joint,
  type JointOptions,
  type JointState,
  type JointStateLayout,
  type JointStep,
  importLocalAnchors,
  optionalFinite,
  optionalNonNegative,
  requireBodies,
  requireOrdered,
  jointMax,
  requirePoint,
  stateBoolean,
  stateNumber,
  stateVector,
  worldAnchor,
} from './joint.ts';

/** Options of a {@link RevoluteJoint}: a hinge (a pin) through one world point. */
export interface RevoluteJointOptions<UserData = unknown> extends JointOptions<UserData> {
  /** The hinge, a world point (m); both bodies turn about it. */
  readonly anchor: Vec2Like;
  /** Keep the joint angle between lowerAngle and upperAngle. Default false. */
  readonly enableLimit?: boolean;
  /** Lowest joint angle (rad), measured from the bodies' angles at creation. Default 0. */
  readonly lowerAngle?: number;
  /** Highest joint angle (rad). Default 0. */
  readonly upperAngle?: number;
  /** Drive the relative rotation at motorSpeed with at most maxMotorTorque. Default false. */
  readonly enableMotor?: boolean;
  /** Target relative angular velocity of body B to body A (rad/s). Default 0. */
  readonly motorSpeed?: number;
  /** Strongest torque the motor may use (N m, >= 0). Default 0. */
  readonly maxMotorTorque?: number;
  /** A torsion spring toward the angle at creation. Default false. */
  readonly enableSpring?: boolean;
  /** Spring frequency (Hz, >= 0). Default 0 (no spring force). */
  readonly hertz?: number;
  /** Spring damping ratio (>= 0; 1 is critical). Default 0. */
  readonly dampingRatio?: number;
}

/** @internal What a world snapshot saves of a revolute joint (see Joint.exportState). */
export const REVOLUTE_STATE: JointStateLayout = {
  fields: {
    localAnchorA: 'vector',
    localAnchorB: 'vector',
    referenceAngle: 'finite',
    enableLimit: 'boolean',
    lowerAngle: 'finite',
    upperAngle: 'finite',
    enableMotor: 'boolean',
    motorSpeed: 'finite',
    maxMotorTorque: 'nonNegative',
    enableSpring: 'boolean',
    hertz: 'nonNegative',
    dampingRatio: 'nonNegative',
    linearImpulse: 'vector',
    springImpulse: 'finite',
    motorImpulse: 'finite',
    lowerImpulse: 'nonNegative',
    upperImpulse: 'nonNegative',
  },
  ordered: [['lowerAngle', 'upperAngle']],
};

/**
 * A hinge: body B turns about a point fixed on both bodies, optionally within angle limits, driven
 * by a motor or held by a torsion spring. Formulas after Box2D v3's revolute joint (Catto): a 2x2
 * point constraint, plus one angular row each for the spring, the motor and the two limits, the
 * limits speculative (they allow closing the gap within a sub-step) like contacts.
 */
export class RevoluteJoint<UserData = unknown> extends Joint<UserData> {
  get type(): 'revolute' {
    return 'revolute';
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
  private limitEnabled: boolean;
  private lower: number;
  private upper: number;
  private motorEnabled: boolean;
  private speed: number;
  private maxTorque: number;
  private springEnabled: boolean;
  private springHertz: number;
  private springDampingRatio: number;
  // Solver state of the step.
  private rAx = -0;
  private rAy = -0;
  private rBx = -0;
  private rBy = -0;
  private deltaCenterX = -0;
  private deltaCenterY = -0;
  /** JointStep.maxBiasSpeed, for the chains' pinError. */
  private maxBiasSpeed = -0;
  private deltaAngle = -0;
  private axialMass = -0;
  private readonly springSoftness = new Softness();
  // Accumulated impulses (warm-started).
  private linearImpulseX = -0;
  private linearImpulseY = -0;
  private springImpulse = -0;
  private motorImpulse = -0;
  private lowerImpulse = -0;
  private upperImpulse = -0;
  /** The batch holding the joint's numbers during a step, and its slot there. */
  private batch: FlatJointBatch<BatchedJoint> | null = null;
  private slot = 0;

  constructor(options: RevoluteJointOptions<UserData>) {
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
    this.limitEnabled = optionalBoolean('enableLimit', options.enableLimit, false);
    this.lower = optionalFinite('lowerAngle', options.lowerAngle, 0);
    this.upper = optionalFinite('upperAngle', options.upperAngle, 0);
    requireOrdered('lowerAngle', this.lower, 'upperAngle', this.upper);
    this.motorEnabled = optionalBoolean('enableMotor', options.enableMotor, false);
    this.speed = optionalFinite('motorSpeed', options.motorSpeed, 0);
    this.maxTorque = optionalNonNegative('maxMotorTorque', options.maxMotorTorque, 0);
    this.springEnabled = optionalBoolean('enableSpring', options.enableSpring, false);
    this.springHertz = optionalNonNegative('hertz', options.hertz, 0);
    this.springDampingRatio = optionalNonNegative('dampingRatio', options.dampingRatio, 0);
  }

  /** @internal */
  protected writeAnchorA(out: Vec2): void {
    worldAnchor(this.bodyA, this.localAnchorAX, this.localAnchorAY, out);
  }

  /** @internal */
  protected writeAnchorB(out: Vec2): void {
    worldAnchor(this.bodyB, this.localAnchorBX, this.localAnchorBY, out);
  }

  /** Current joint angle (rad): angle of B minus angle of A, minus that difference at creation. */
  get angle(): number {
    return this.bodyB.angle - this.bodyA.angle - this.referenceAngle;
  }

  /** Relative angular velocity of B to A (rad/s). */
  get angularSpeed(): number {
    return this.bodyB.angularVelocity - this.bodyA.angularVelocity;
  }

  /** Whether the angle limits hold. Changing it wakes the bodies. */
  get enableLimit(): boolean {
    return this.limitEnabled;
  }

  set enableLimit(value: boolean) {
    requireBoolean('enableLimit', value);
    if (value === this.limitEnabled) return;
    this.limitEnabled = value;
    this.lowerImpulse = 0;
    this.upperImpulse = 0;
    this.wakeBodies();
  }

  /** Lowest joint angle (rad); must not exceed upperAngle (use setLimits to move both). */
  get lowerAngle(): number {
    return this.lower;
  }

  set lowerAngle(value: number) {
    this.applyLimits(value, this.upper, 'lower');
  }

  /** Highest joint angle (rad). */
  get upperAngle(): number {
    return this.upper;
  }

  set upperAngle(value: number) {
    this.applyLimits(this.lower, value, 'upper');
  }

  /** Sets both angle limits (rad) at once; wakes the bodies. */
  setLimits(lowerAngle: number, upperAngle: number): void {
    this.applyLimits(lowerAngle, upperAngle, 'lower');
  }

  private applyLimits(lowerAngle: number, upperAngle: number, changed: 'lower' | 'upper'): void {
    requireRange('lowerAngle', lowerAngle, -jointMax('lowerAngle'), jointMax('lowerAngle'));
    requireRange('upperAngle', upperAngle, -jointMax('upperAngle'), jointMax('upperAngle'));
    requireOrdered('lowerAngle', lowerAngle, 'upperAngle', upperAngle, changed);
    this.lower = lowerAngle;
    this.upper = upperAngle;
    this.wakeBodies();
  }

  /** Whether the motor drives the joint. Changing it wakes the bodies. */
  get enableMotor(): boolean {
    return this.motorEnabled;
  }

  set enableMotor(value: boolean) {
    requireBoolean('enableMotor', value);
    if (value === this.motorEnabled) return;
    this.motorEnabled = value;
    this.motorImpulse = 0;
    this.wakeBodies();
  }

  /** Target relative angular velocity (rad/s). Setting it wakes the bodies. */
  get motorSpeed(): number {
    return this.speed;
  }

  set motorSpeed(value: number) {
    this.speed = requireRange('motorSpeed', value, -jointMax('motorSpeed'), jointMax('motorSpeed'));
    this.wakeBodies();
  }

  /** Strongest motor torque (N m). Setting it wakes the bodies. */
  get maxMotorTorque(): number {
    return this.maxTorque;
  }

  set maxMotorTorque(value: number) {
    this.maxTorque = requireNonNegative('maxMotorTorque', value, jointMax('maxMotorTorque'));
    this.wakeBodies();
  }

  /** Torque the motor applied in the last sub-step (N m). */
  get motorTorque(): number {
    return this.motorImpulse / this.subStepDuration;
  }

  /** Whether the torsion spring acts. Changing it wakes the bodies. */
  get enableSpring(): boolean {
    return this.springEnabled;
  }

  set enableSpring(value: boolean) {
    requireBoolean('enableSpring', value);
    if (value === this.springEnabled) return;
    this.springEnabled = value;
    this.springImpulse = 0;
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
      referenceAngle: this.referenceAngle,
      enableLimit: this.limitEnabled,
      lowerAngle: this.lower,
      upperAngle: this.upper,
      enableMotor: this.motorEnabled,
      motorSpeed: this.speed,
      maxMotorTorque: this.maxTorque,
      enableSpring: this.springEnabled,
      hertz: this.springHertz,
      dampingRatio: this.springDampingRatio,
      linearImpulse: [this.linearImpulseX, this.linearImpulseY],
      springImpulse: this.springImpulse,
      motorImpulse: this.motorImpulse,
      lowerImpulse: this.lowerImpulse,
      upperImpulse: this.upperImpulse,
    };
  }

  /** @internal */
  protected importOwnState(state: JointState): void {
    importLocalAnchors(state, this);
    const impulse = stateVector(state, 'linearImpulse');
    this.referenceAngle = stateNumber(state, 'referenceAngle');
    this.limitEnabled = stateBoolean(state, 'enableLimit');
    this.lower = stateNumber(state, 'lowerAngle');
    this.upper = stateNumber(state, 'upperAngle');
    this.motorEnabled = stateBoolean(state, 'enableMotor');
    this.speed = stateNumber(state, 'motorSpeed');
    this.maxTorque = stateNumber(state, 'maxMotorTorque');
    this.springEnabled = stateBoolean(state, 'enableSpring');
    this.springHertz = stateNumber(state, 'hertz');
    this.springDampingRatio = stateNumber(state, 'dampingRatio');
    this.linearImpulseX = impulse[0]!;
    this.linearImpulseY = impulse[1]!;
    this.springImpulse = stateNumber(state, 'springImpulse');
    this.motorImpulse = stateNumber(state, 'motorImpulse');
    this.lowerImpulse = stateNumber(state, 'lowerImpulse');
    this.upperImpulse = stateNumber(state, 'upperImpulse');
  }

  /** @internal */
  resetImpulses(): void {
    this.linearImpulseX = 0;
    this.linearImpulseY = 0;
    this.springImpulse = 0;
    this.motorImpulse = 0;
    this.lowerImpulse = 0;
    this.upperImpulse = 0;
  }

  /** @internal */
  prepare(step: JointStep): void {
    this.prepareBodies(step);
    this.maxBiasSpeed = step.maxBiasSpeed;
    const a = this.bodyA;
    const b = this.bodyB;
    const ta = a.transform;
    const tb = b.transform;
    // Lever arms from the centres of mass, in world orientation at the step's start; the sub-steps
    // turn them by each body's rotation since (state Q_C, Q_S).
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
    this.springSoftness.set(this.springHertz, this.springDampingRatio, step.h);
    if (!this.springEnabled || this.springHertz === 0) this.springImpulse = 0;
    if (!this.motorEnabled) this.motorImpulse = 0;
    if (!this.limitEnabled) {
      this.lowerImpulse = 0;
      this.upperImpulse = 0;
    }
  }

  /** @internal */
  override createBatch(): RevoluteBatch {
    return new RevoluteBatch();
  }

  /** @internal Writes this step's solver numbers into a batch's slot at `o`. */
  loadBatch(d: Float64Array, o: number, slot: number, batch: FlatJointBatch<BatchedJoint>): void {
    this.batch = batch;
    this.slot = slot;
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
    // A spring of 0 Hz exerts nothing (Box2D's soft constraint of 0 Hz would lock the motion).
    d[o + SPRING_ON] = this.springEnabled && this.springHertz > 0 ? 1 : 0;
    d[o + SPRING_BIAS_RATE] = this.springSoftness.biasRate;
    d[o + SPRING_MASS_SCALE] = this.springSoftness.massScale;
    d[o + SPRING_IMPULSE_SCALE] = this.springSoftness.impulseScale;
    d[o + MOTOR_ON] = this.motorEnabled ? 1 : 0;
    d[o + MOTOR_SPEED] = this.speed;
    d[o + MAX_MOTOR_TORQUE] = this.maxTorque;
    d[o + LIMIT_ON] = this.limitEnabled ? 1 : 0;
    d[o + LOWER] = this.lower;
    d[o + UPPER] = this.upper;
    d[o + LINEAR_IMPULSE_X] = this.linearImpulseX;
    d[o + LINEAR_IMPULSE_Y] = this.linearImpulseY;
    d[o + SPRING_IMPULSE] = this.springImpulse;
    d[o + MOTOR_IMPULSE] = this.motorImpulse;
    d[o + LOWER_IMPULSE] = this.lowerImpulse;
    d[o + UPPER_IMPULSE] = this.upperImpulse;
    d[o + STEP_IMPULSE_X] = this.stepImpulseX;
    d[o + STEP_IMPULSE_Y] = this.stepImpulseY;
    d[o + STEP_ANGULAR_IMPULSE] = this.stepAngularImpulse;
  }

  /** @internal Takes the step's impulses back from the batch's slot at `o`. */
  storeBatch(d: Float64Array, o: number): void {
    this.batch = null;
    this.linearImpulseX = d[o + LINEAR_IMPULSE_X]!;
    this.linearImpulseY = d[o + LINEAR_IMPULSE_Y]!;
    this.springImpulse = d[o + SPRING_IMPULSE]!;
    this.motorImpulse = d[o + MOTOR_IMPULSE]!;
    this.lowerImpulse = d[o + LOWER_IMPULSE]!;
    this.upperImpulse = d[o + UPPER_IMPULSE]!;
    this.stepImpulseX = d[o + STEP_IMPULSE_X]!;
    this.stepImpulseY = d[o + STEP_IMPULSE_Y]!;
    this.stepAngularImpulse = d[o + STEP_ANGULAR_IMPULSE]!;
  }

  /** @internal */
  override pinJoint(): PinJoint {
    return this;
  }

  /** @internal */
  override createChains(): PinChains {
    return new PinChains();
  }

  /** @internal */
  pinLevers(s: Float64Array, out: Float64Array, offset: number): void {
    const a = this.stateA;
    const b = this.stateB;
    const qAc = s[a + Q_C]!;
    const qAs = s[a + Q_S]!;
    const qBc = s[b + Q_C]!;
    const qBs = s[b + Q_S]!;
    out[offset] = qAc * this.rAx - qAs * this.rAy;
    out[offset + 1] = qAs * this.rAx + qAc * this.rAy;
    out[offset + 2] = qBc * this.rBx - qBs * this.rBy;
    out[offset + 3] = qBs * this.rBx + qBc * this.rBy;
  }

  /** @internal */
  pinError(
    s: Float64Array,
    biasRate: number,
    positions: boolean,
    out: Float64Array,
    offset: number,
  ): void {
    const a = this.stateA;
    const b = this.stateB;
    this.pinLevers(s, out, offset);
    const rAx = out[offset]!;
    const rAy = out[offset + 1]!;
    const rBx = out[offset + 2]!;
    const rBy = out[offset + 3]!;
    const gapX = s[b + DP_X]! - s[a + DP_X]! + rBx - rAx + this.deltaCenterX;
    const gapY = s[b + DP_Y]! - s[a + DP_Y]! + rBy - rAy + this.deltaCenterY;
    if (positions) {
      out[offset] = gapX;
      out[offset + 1] = gapY;
      return;
    }
    const wA = s[a + W]!;
    const wB = s[b + W]!;
    let biasX = biasRate * gapX;
    let biasY = biasRate * gapY;
    // At most maxBiasSpeed, as in the batch's solve (see JointStep.maxBiasSpeed).
    const biasSquared = biasX * biasX + biasY * biasY;
    const maxBias = this.maxBiasSpeed;
    if (biasSquared > maxBias * maxBias) {
      const ratio = maxBias / Math.sqrt(biasSquared);
      biasX *= ratio;
      biasY *= ratio;
    }
    out[offset] = s[b + V_X]! - wB * rBy - (s[a + V_X]! - wA * rAy) + biasX;
    out[offset + 1] = s[b + V_Y]! + wB * rBx - (s[a + V_Y]! + wA * rAx) + biasY;
  }

  /** @internal */
  pinLoad(out: Float64Array, offset: number): void {
    // The chains read it while they prepare, before the joint joins its batch.
    const batch = this.batch;
    const px =
      batch === null ? this.linearImpulseX : batch.data[this.slot * STRIDE + LINEAR_IMPULSE_X]!;
    const py =
      batch === null ? this.linearImpulseY : batch.data[this.slot * STRIDE + LINEAR_IMPULSE_Y]!;
    out[offset] = Math.abs(px * this.rAx + py * this.rAy);
    out[offset + 1] = Math.abs(px * this.rBx + py * this.rBy);
  }

  /** @internal */
  addPinImpulse(t: Float64Array, offset: number, relax: boolean): void {
    const px = t[offset + 15]!;
    const py = t[offset + 5]!;
    const d = this.batch!.data;
    const o = this.slot * STRIDE;
    d[o + LINEAR_IMPULSE_X] += px;
    d[o + LINEAR_IMPULSE_Y] += py;
    if (relax) {
      d[o + STEP_IMPULSE_X] += px;
      d[o + STEP_IMPULSE_Y] += py;
    }
  }
}

// The revolute joints of a step in flat arrays (RevoluteBatch), doubles per joint:
const R_AX = 0; // levers from the centres to the anchors at the step's start (m)
const R_AY = 1;
const R_BX = 2;
const R_BY = 3;
const DELTA_CENTER_X = 4; // centre of B minus centre of A at the step's start (m)
const DELTA_CENTER_Y = 5;
const JOINT_ANGLE_0 = 6; // joint angle at the step's start (rad)
const AXIAL_MASS = 7;
const INV_MASS_A = 8;
const INV_I_A = 9;
const INV_MASS_B = 10;
const INV_I_B = 11;
const SPRING_ON = 12; // 1 or 0
const SPRING_BIAS_RATE = 13;
const SPRING_MASS_SCALE = 14;
const SPRING_IMPULSE_SCALE = 15;
const MOTOR_ON = 16;
const MOTOR_SPEED = 17;
const MAX_MOTOR_TORQUE = 18;
const LIMIT_ON = 19;
const LOWER = 20;
const UPPER = 21;
const LINEAR_IMPULSE_X = 22; // accumulated impulses (warm-started)
const LINEAR_IMPULSE_Y = 23;
const SPRING_IMPULSE = 24;
const MOTOR_IMPULSE = 25;
const LOWER_IMPULSE = 26;
const UPPER_IMPULSE = 27;
const STEP_IMPULSE_X = 28; // summed over the step's relax passes, for the reaction
const STEP_IMPULSE_Y = 29;
const STEP_ANGULAR_IMPULSE = 30;
const STRIDE = 32;

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
