import { readOnly } from '../../core/errors.ts';
import { JointBatch } from './joint-batch.ts';
import { KIND_REVOLUTE } from './joint-pass-codes.ts';
import type { Vec2Like } from '../../math/vec2.ts';
import { DP_X, DP_Y, V_X, V_Y, W } from '../body-state.ts';
import { PinChains, type PinJoint } from './pin-chains.ts';
import {
  AXIAL_MASS,
  LINEAR_IMPULSE_X,
  LINEAR_IMPULSE_Y,
  MAX_BIAS_SPEED,
  STRIDE,
} from './revolute-joint-solver.ts';
import {
  FRAME_SAVED,
  checkCollideConnected,
  jointLayout,
  stateLayout,
  type JointLayout,
  type JointOptions,
  type JointStateLayout,
  type JointStep,
  requireBodies,
  requirePoint,
} from './joint.ts';
import { TwoBodyJoint } from './two-body-joint.ts';
import { turnedX, turnedY } from './joint-levers.ts';
import {
  DELTA_CENTER_X,
  DELTA_CENTER_Y,
  INV_I_A,
  INV_I_B,
  INV_MASS_A,
  INV_MASS_B,
  R_AX,
  R_AY,
  R_BX,
  R_BY,
  REFERENCE_ANGLE,
  STEP_IMPULSE_X,
  STEP_IMPULSE_Y,
} from './joint-record.ts';
import {
  checkSpringMotorLimit,
  DAMPING_RATIO,
  HERTZ,
  LIMIT_ON,
  LOWER,
  LOWER_IMPULSE,
  MAX_MOTOR,
  MOTOR_IMPULSE,
  MOTOR_ON,
  MOTOR_SPEED,
  prepareSpringMotorLimit,
  SPRING_ENABLED,
  SPRING_IMPULSE,
  SPRING_MOTOR_LIMIT_IMPULSES,
  SPRING_MOTOR_LIMIT_IMPULSES_SAVED,
  springMotorLimitSaved,
  UPPER,
  writeSpringMotorLimit,
} from './spring-motor-limit.ts';

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

const NAMES = { lower: 'lowerAngle', upper: 'upperAngle', maxMotor: 'maxMotorTorque' } as const;

/**
 * @internal A revolute joint's options checked (a PhysicalError naming the first bad one), in the
 * order its constructor reads them, with defaults: the one check, also run where no joint is built
 * (a worker world's page).
 */
export function checkRevoluteJointOptions(options: RevoluteJointOptions<unknown>) {
  requireBodies(options);
  const anchor = requirePoint('anchor', options.anchor);
  checkCollideConnected(options);
  const settings = checkSpringMotorLimit(
    options,
    NAMES,
    options.lowerAngle,
    options.upperAngle,
    options.maxMotorTorque,
  );
  return { anchor, settings };
}

const LAYOUT: JointLayout = /* @__PURE__ */ jointLayout(
  STRIDE,
  [
    FRAME_SAVED,
    /* @__PURE__ */ springMotorLimitSaved(NAMES),
    { linearImpulse: ['vector', LINEAR_IMPULSE_X] },
    SPRING_MOTOR_LIMIT_IMPULSES_SAVED,
  ],
  [[LINEAR_IMPULSE_X, LINEAR_IMPULSE_Y], SPRING_MOTOR_LIMIT_IMPULSES],
);

/** @internal What a world snapshot saves of a revolute joint (see exportJointState). */
export const REVOLUTE_STATE: JointStateLayout = /* @__PURE__ */ stateLayout(LAYOUT, [
  ['lowerAngle', 'upperAngle'],
]);

/**
 * A hinge: body B turns about a point fixed on both bodies, optionally within angle limits, driven
 * by a motor or held by a torsion spring. Formulas after Box2D v3's revolute joint (Catto): a 2x2
 * point constraint, plus one angular row each for the spring, the motor and the two limits, the
 * limits speculative (they allow closing the gap within a sub-step) like contacts.
 */
export class RevoluteJoint<UserData = unknown> extends TwoBodyJoint<UserData> {
  get type(): 'revolute' {
    return 'revolute';
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set type(_value: never) {
    readOnly('type', 'a joint keeps its kind');
  }

  constructor(options: RevoluteJointOptions<UserData>) {
    const { anchor, settings } = checkRevoluteJointOptions(options);
    super(options, options.bodyA, options.bodyB, STRIDE);
    this.setAnchors(anchor, anchor);
    this.write(REFERENCE_ANGLE, this.bodyB.angle - this.bodyA.angle);
    writeSpringMotorLimit(this.store.data, this.base, settings);
  }

  /** @internal */
  protected get layout(): JointLayout {
    return LAYOUT;
  }

  /** Current joint angle (rad): angle of B minus angle of A, minus that difference at creation. */
  get angle(): number {
    return this.bodyB.angle - this.bodyA.angle - this.value(REFERENCE_ANGLE);
  }

  /** Relative angular velocity of B to A (rad/s). */
  get angularSpeed(): number {
    return this.bodyB.angularVelocity - this.bodyA.angularVelocity;
  }

  /** Whether the angle limits hold. Changing it wakes the bodies. */
  get enableLimit(): boolean {
    return this.flag(LIMIT_ON);
  }

  set enableLimit(value: boolean) {
    this.setSwitch('enableLimit', LIMIT_ON, value, LOWER_IMPULSE, 2);
  }

  /** Lowest joint angle (rad); must not exceed upperAngle (use setLimits to move both). */
  get lowerAngle(): number {
    return this.value(LOWER);
  }

  set lowerAngle(value: number) {
    this.setRange(NAMES.lower, NAMES.upper, LOWER, value, this.value(UPPER), 'lower');
  }

  /** Highest joint angle (rad). */
  get upperAngle(): number {
    return this.value(UPPER);
  }

  set upperAngle(value: number) {
    this.setRange(NAMES.lower, NAMES.upper, LOWER, this.value(LOWER), value, 'upper');
  }

  /** Sets both angle limits (rad) at once; wakes the bodies. */
  setLimits(lowerAngle: number, upperAngle: number): void {
    this.setRange(NAMES.lower, NAMES.upper, LOWER, lowerAngle, upperAngle, 'lower');
  }

  /** Whether the motor drives the joint. Changing it wakes the bodies. */
  get enableMotor(): boolean {
    return this.flag(MOTOR_ON);
  }

  set enableMotor(value: boolean) {
    this.setSwitch('enableMotor', MOTOR_ON, value, MOTOR_IMPULSE, 1);
  }

  /** Target relative angular velocity (rad/s). Setting it wakes the bodies. */
  get motorSpeed(): number {
    return this.value(MOTOR_SPEED);
  }

  set motorSpeed(value: number) {
    this.setNumber('motorSpeed', MOTOR_SPEED, value, 'any');
  }

  /** Strongest motor torque (N m). Setting it wakes the bodies. */
  get maxMotorTorque(): number {
    return this.value(MAX_MOTOR);
  }

  set maxMotorTorque(value: number) {
    this.setNumber(NAMES.maxMotor, MAX_MOTOR, value, 'nonNegative');
  }

  /** Torque the motor applied in the last sub-step (N m). */
  get motorTorque(): number {
    return this.value(MOTOR_IMPULSE) / this.subStepDuration;
  }

  /** Whether the torsion spring acts. Changing it wakes the bodies. */
  get enableSpring(): boolean {
    return this.flag(SPRING_ENABLED);
  }

  set enableSpring(value: boolean) {
    this.setSwitch('enableSpring', SPRING_ENABLED, value, SPRING_IMPULSE, 1);
  }

  /** Spring frequency (Hz). Setting it wakes the bodies. */
  get hertz(): number {
    return this.value(HERTZ);
  }

  set hertz(value: number) {
    this.setNumber('hertz', HERTZ, value, 'nonNegative');
  }

  /** Spring damping ratio. Setting it wakes the bodies. */
  get dampingRatio(): number {
    return this.value(DAMPING_RATIO);
  }

  set dampingRatio(value: number) {
    this.setNumber('dampingRatio', DAMPING_RATIO, value, 'nonNegative');
  }

  /** @internal */
  prepare(step: JointStep): void {
    this.prepareFrame(step);
    const d = this.store.data;
    const o = this.base;
    d[o + MAX_BIAS_SPEED] = step.maxBiasSpeed;
    const k = d[o + INV_I_A]! + d[o + INV_I_B]!;
    d[o + AXIAL_MASS] = k > 0 ? 1 / k : 0;
    prepareSpringMotorLimit(d, o, step);
  }

  /** @internal */
  override createBatch(): JointBatch {
    return new JointBatch(KIND_REVOLUTE);
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
    const d = this.store.data;
    const o = this.base;
    const a = this.stateA;
    const b = this.stateB;
    out[offset] = turnedX(s, a, d, o + R_AX);
    out[offset + 1] = turnedY(s, a, d, o + R_AX);
    out[offset + 2] = turnedX(s, b, d, o + R_BX);
    out[offset + 3] = turnedY(s, b, d, o + R_BX);
  }

  /** @internal */
  pinMasses(out: Float64Array): void {
    const d = this.store.data;
    const o = this.base;
    out[0] = d[o + INV_MASS_A]!;
    out[1] = d[o + INV_I_A]!;
    out[2] = d[o + INV_MASS_B]!;
    out[3] = d[o + INV_I_B]!;
  }

  /** @internal */
  setPinInertias(values: Float64Array): void {
    this.write(INV_I_A, values[1]!);
    this.write(INV_I_B, values[3]!);
  }

  /** @internal */
  pinError(
    s: Float64Array,
    rates: Float64Array,
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
    const gapX = s[b + DP_X]! - s[a + DP_X]! + rBx - rAx + this.value(DELTA_CENTER_X);
    const gapY = s[b + DP_Y]! - s[a + DP_Y]! + rBy - rAy + this.value(DELTA_CENTER_Y);
    if (positions) {
      out[offset] = gapX;
      out[offset + 1] = gapY;
      return;
    }
    const wA = s[a + W]!;
    const wB = s[b + W]!;
    const biasRate = rates[0]!;
    let biasX = biasRate * gapX;
    let biasY = biasRate * gapY;
    // At most maxBiasSpeed, as in the point constraint (see JointStep.maxBiasSpeed).
    const biasSquared = biasX * biasX + biasY * biasY;
    const maxBias = this.value(MAX_BIAS_SPEED);
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
    const px = this.value(LINEAR_IMPULSE_X);
    const py = this.value(LINEAR_IMPULSE_Y);
    out[offset] = Math.abs(px * this.value(R_AX) + py * this.value(R_AY));
    out[offset + 1] = Math.abs(px * this.value(R_BX) + py * this.value(R_BY));
  }

  /** @internal */
  addPinImpulse(t: Float64Array, offset: number, relax: boolean): void {
    const px = t[offset + 15]!;
    const py = t[offset + 5]!;
    const d = this.store.data;
    const o = this.base;
    d[o + LINEAR_IMPULSE_X] += px;
    d[o + LINEAR_IMPULSE_Y] += py;
    if (relax) {
      d[o + STEP_IMPULSE_X] += px;
      d[o + STEP_IMPULSE_Y] += py;
    }
  }
}
