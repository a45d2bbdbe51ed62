import { PhysicalError, readOnly } from '../../core/errors.ts';
import {
  optionalBoolean,
  requireBoolean,
  requireNonNegative,
  requireRange,
} from '../../core/validate.ts';
import type { Vec2, Vec2Like } from '../../math/vec2.ts';
import { Softness } from '../softness.ts';
import {
  R_AX,
  R_AY,
  R_BX,
  R_BY,
  AXIS_X,
  AXIS_Y,
  DELTA_CENTER_X,
  DELTA_CENTER_Y,
  JOINT_ANGLE_0,
  INV_MASS_A,
  INV_I_A,
  INV_MASS_B,
  INV_I_B,
  SPRING_ON,
  SPRING_BIAS_RATE,
  SPRING_MASS_SCALE,
  SPRING_IMPULSE_SCALE,
  MOTOR_ON,
  MOTOR_SPEED,
  MAX_MOTOR_FORCE,
  LIMIT_ON,
  LOWER,
  UPPER,
  PERPENDICULAR_IMPULSE,
  ANGULAR_IMPULSE,
  SPRING_IMPULSE,
  MOTOR_IMPULSE,
  LOWER_IMPULSE,
  UPPER_IMPULSE,
  STEP_IMPULSE_X,
  STEP_IMPULSE_Y,
  STEP_ANGULAR_IMPULSE,
  PrismaticBatch,
} from './prismatic-joint-solver.ts';
import {
  Joint,
  checkCollideConnected,
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
import { hypot } from '../../math/hypot.ts';

/** Options of a {@link PrismaticJoint}: a slider along an axis. */
export interface PrismaticJointOptions<UserData = unknown> extends JointOptions<UserData> {
  /** A point on the slide line (world, m); the translation is 0 there. */
  readonly anchor: Vec2Like;
  /** Direction of the slide (world, any length but zero); it turns with body A. */
  readonly axis: Vec2Like;
  /** Keep the translation between lower and upper. Default false. */
  readonly enableLimit?: boolean;
  /** Lowest translation (m). Default 0. */
  readonly lower?: number;
  /** Highest translation (m). Default 0. */
  readonly upper?: number;
  /** Drive the sliding at motorSpeed with at most maxMotorForce. Default false. */
  readonly enableMotor?: boolean;
  /** Target speed of B relative to A along the axis (m/s). Default 0. */
  readonly motorSpeed?: number;
  /** Strongest force the motor may use (N, >= 0). Default 0. */
  readonly maxMotorForce?: number;
  /** A spring toward translation 0. Default false. */
  readonly enableSpring?: boolean;
  /** Spring frequency (Hz, >= 0). Default 0. */
  readonly hertz?: number;
  /** Spring damping ratio (>= 0). Default 0. */
  readonly dampingRatio?: number;
}

/**
 * @internal A prismatic joint's options checked (a PhysicalError naming the first bad one), in the
 * order its constructor reads them, with defaults: the one check, also run where no joint is built
 * (a worker world's page).
 */
export function checkPrismaticJointOptions(options: PrismaticJointOptions<unknown>) {
  requireBodies(options);
  const anchor = requirePoint('anchor', options.anchor);
  const axis = requirePoint('axis', options.axis);
  if (!(hypot(axis.x, axis.y) > 0)) throw new PhysicalError('axis', 'must not be the zero vector.');
  checkCollideConnected(options);
  const enableLimit = optionalBoolean('enableLimit', options.enableLimit, false);
  const lower = optionalFinite('lower', options.lower, 0);
  const upper = optionalFinite('upper', options.upper, 0);
  requireOrdered('lower', lower, 'upper', upper);
  return {
    anchor,
    axis,
    enableLimit,
    lower,
    upper,
    enableMotor: optionalBoolean('enableMotor', options.enableMotor, false),
    motorSpeed: optionalFinite('motorSpeed', options.motorSpeed, 0),
    maxMotorForce: optionalNonNegative('maxMotorForce', options.maxMotorForce, 0),
    enableSpring: optionalBoolean('enableSpring', options.enableSpring, false),
    hertz: optionalNonNegative('hertz', options.hertz, 0),
    dampingRatio: optionalNonNegative('dampingRatio', options.dampingRatio, 0),
  };
}

/** @internal What a world snapshot saves of a prismatic joint (see Joint.exportState). */
export const PRISMATIC_STATE: JointStateLayout = {
  fields: {
    localAnchorA: 'vector',
    localAnchorB: 'vector',
    localAxis: 'unitVector',
    referenceAngle: 'finite',
    enableLimit: 'boolean',
    lower: 'finite',
    upper: 'finite',
    enableMotor: 'boolean',
    motorSpeed: 'finite',
    maxMotorForce: 'nonNegative',
    enableSpring: 'boolean',
    hertz: 'nonNegative',
    dampingRatio: 'nonNegative',
    perpendicularImpulse: 'finite',
    angularImpulse: 'finite',
    springImpulse: 'finite',
    motorImpulse: 'finite',
    lowerImpulse: 'nonNegative',
    upperImpulse: 'nonNegative',
  },
  ordered: [['lower', 'upper']],
};

/**
 * A slider: body B moves along an axis fixed in body A and cannot turn relative to it; optional
 * translation limits, motor and spring. Box2D v3's prismatic joint (Catto): the axial rows (spring,
 * motor, limits) first, then a 2x2 block for the perpendicular offset and the relative angle.
 */
export class PrismaticJoint<UserData = unknown> extends Joint<UserData> {
  get type(): 'prismatic' {
    return 'prismatic';
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set type(_value: never) {
    readOnly('type', 'a joint keeps its kind');
  }
  /** @internal Anchors in each body's frame (relative to the body origin, m) and A's axis. */
  localAnchorAX = -0;
  /** @internal */
  localAnchorAY = -0;
  /** @internal */
  localAnchorBX = -0;
  /** @internal */
  localAnchorBY = -0;
  /** @internal */
  localAxisX = 1;
  /** @internal */
  localAxisY = -0;
  /** @internal angleB - angleA at creation (rad). */
  referenceAngle = -0;
  private limitEnabled: boolean;
  private lowerLimit: number;
  private upperLimit: number;
  private motorEnabled: boolean;
  private speed: number;
  private maxForce: number;
  private springEnabled: boolean;
  private springHertz: number;
  private springDampingRatio: number;
  private rAx = -0;
  private rAy = -0;
  private rBx = -0;
  private rBy = -0;
  private axisX = 1;
  private axisY = -0;
  private deltaCenterX = -0;
  private deltaCenterY = -0;
  private deltaAngle = -0;
  private readonly springSoftness = new Softness();
  private perpendicularImpulse = -0;
  private angularImpulse = -0;
  private springImpulse = -0;
  private motorImpulse = -0;
  private lowerImpulse = -0;
  private upperImpulse = -0;

  constructor(options: PrismaticJointOptions<UserData>) {
    const checked = checkPrismaticJointOptions(options);
    const { anchor, axis } = checked;
    const axisLength = hypot(axis.x, axis.y);
    super(options, options.bodyA, options.bodyB);
    const localA = this.bodyA.getLocalPoint(anchor);
    const localB = this.bodyB.getLocalPoint(anchor);
    this.localAnchorAX = localA.x;
    this.localAnchorAY = localA.y;
    this.localAnchorBX = localB.x;
    this.localAnchorBY = localB.y;
    const { c, s } = this.bodyA.transform;
    const ux = axis.x / axisLength;
    const uy = axis.y / axisLength;
    this.localAxisX = c * ux + s * uy;
    this.localAxisY = -s * ux + c * uy;
    this.referenceAngle = this.bodyB.angle - this.bodyA.angle;
    this.limitEnabled = checked.enableLimit;
    this.lowerLimit = checked.lower;
    this.upperLimit = checked.upper;
    this.motorEnabled = checked.enableMotor;
    this.speed = checked.motorSpeed;
    this.maxForce = checked.maxMotorForce;
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

  /** Translation of B's anchor from A's along the axis (m). */
  get translation(): number {
    const a = this.bodyA.getWorldPoint({ x: this.localAnchorAX, y: this.localAnchorAY });
    const b = this.bodyB.getWorldPoint({ x: this.localAnchorBX, y: this.localAnchorBY });
    const { c, s } = this.bodyA.transform;
    const ax = c * this.localAxisX - s * this.localAxisY;
    const ay = s * this.localAxisX + c * this.localAxisY;
    return (b.x - a.x) * ax + (b.y - a.y) * ay;
  }

  /** Whether the translation limits hold. Changing it wakes the bodies. */
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

  /** Lowest translation (m); must not exceed upper (use setLimits to move both). */
  get lower(): number {
    return this.lowerLimit;
  }

  set lower(value: number) {
    this.applyLimits(value, this.upperLimit, 'lower');
  }

  /** Highest translation (m). */
  get upper(): number {
    return this.upperLimit;
  }

  set upper(value: number) {
    this.applyLimits(this.lowerLimit, value, 'upper');
  }

  /** Sets both translation limits (m); wakes the bodies. */
  setLimits(lower: number, upper: number): void {
    this.applyLimits(lower, upper, 'lower');
  }

  private applyLimits(lower: number, upper: number, changed: 'lower' | 'upper'): void {
    requireRange('lower', lower, -jointMax('lower'), jointMax('lower'));
    requireRange('upper', upper, -jointMax('upper'), jointMax('upper'));
    requireOrdered('lower', lower, 'upper', upper, changed);
    this.lowerLimit = lower;
    this.upperLimit = upper;
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

  /** Target speed along the axis (m/s). Setting it wakes the bodies. */
  get motorSpeed(): number {
    return this.speed;
  }

  set motorSpeed(value: number) {
    this.speed = requireRange('motorSpeed', value, -jointMax('motorSpeed'), jointMax('motorSpeed'));
    this.wakeBodies();
  }

  /** Strongest motor force (N). Setting it wakes the bodies. */
  get maxMotorForce(): number {
    return this.maxForce;
  }

  set maxMotorForce(value: number) {
    this.maxForce = requireNonNegative('maxMotorForce', value, jointMax('maxMotorForce'));
    this.wakeBodies();
  }

  /** Force the motor applied in the last sub-step (N). */
  get motorForce(): number {
    return this.motorImpulse / this.subStepDuration;
  }

  /** Whether the spring acts. Changing it wakes the bodies. */
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
      localAxis: [this.localAxisX, this.localAxisY],
      referenceAngle: this.referenceAngle,
      enableLimit: this.limitEnabled,
      lower: this.lowerLimit,
      upper: this.upperLimit,
      enableMotor: this.motorEnabled,
      motorSpeed: this.speed,
      maxMotorForce: this.maxForce,
      enableSpring: this.springEnabled,
      hertz: this.springHertz,
      dampingRatio: this.springDampingRatio,
      perpendicularImpulse: this.perpendicularImpulse,
      angularImpulse: this.angularImpulse,
      springImpulse: this.springImpulse,
      motorImpulse: this.motorImpulse,
      lowerImpulse: this.lowerImpulse,
      upperImpulse: this.upperImpulse,
    };
  }

  /** @internal */
  protected importOwnState(state: JointState): void {
    importLocalAnchors(state, this);
    const axis = stateVector(state, 'localAxis');
    this.localAxisX = axis[0]!;
    this.localAxisY = axis[1]!;
    this.referenceAngle = stateNumber(state, 'referenceAngle');
    this.limitEnabled = stateBoolean(state, 'enableLimit');
    this.lowerLimit = stateNumber(state, 'lower');
    this.upperLimit = stateNumber(state, 'upper');
    this.motorEnabled = stateBoolean(state, 'enableMotor');
    this.speed = stateNumber(state, 'motorSpeed');
    this.maxForce = stateNumber(state, 'maxMotorForce');
    this.springEnabled = stateBoolean(state, 'enableSpring');
    this.springHertz = stateNumber(state, 'hertz');
    this.springDampingRatio = stateNumber(state, 'dampingRatio');
    this.perpendicularImpulse = stateNumber(state, 'perpendicularImpulse');
    this.angularImpulse = stateNumber(state, 'angularImpulse');
    this.springImpulse = stateNumber(state, 'springImpulse');
    this.motorImpulse = stateNumber(state, 'motorImpulse');
    this.lowerImpulse = stateNumber(state, 'lowerImpulse');
    this.upperImpulse = stateNumber(state, 'upperImpulse');
  }

  /** @internal */
  resetImpulses(): void {
    this.perpendicularImpulse = 0;
    this.angularImpulse = 0;
    this.springImpulse = 0;
    this.motorImpulse = 0;
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
    this.axisX = ta.c * this.localAxisX - ta.s * this.localAxisY;
    this.axisY = ta.s * this.localAxisX + ta.c * this.localAxisY;
    this.deltaCenterX = b.centerX - a.centerX;
    this.deltaCenterY = b.centerY - a.centerY;
    this.deltaAngle = b.angleValue - a.angleValue - this.referenceAngle;
    this.springSoftness.set(this.springHertz, this.springDampingRatio, step.h);
    if (!this.springEnabled || this.springHertz === 0) this.springImpulse = 0;
    if (!this.motorEnabled) this.motorImpulse = 0;
    if (!this.limitEnabled) {
      this.lowerImpulse = 0;
      this.upperImpulse = 0;
    }
  }

  /** @internal */
  override createBatch(): PrismaticBatch {
    return new PrismaticBatch();
  }

  /** @internal Writes this step's solver numbers into a batch's slot at `o`. */
  loadBatch(d: Float64Array, o: number): void {
    d[o + R_AX] = this.rAx;
    d[o + R_AY] = this.rAy;
    d[o + R_BX] = this.rBx;
    d[o + R_BY] = this.rBy;
    d[o + AXIS_X] = this.axisX;
    d[o + AXIS_Y] = this.axisY;
    d[o + DELTA_CENTER_X] = this.deltaCenterX;
    d[o + DELTA_CENTER_Y] = this.deltaCenterY;
    d[o + JOINT_ANGLE_0] = this.deltaAngle;
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
    d[o + MAX_MOTOR_FORCE] = this.maxForce;
    d[o + LIMIT_ON] = this.limitEnabled ? 1 : 0;
    d[o + LOWER] = this.lowerLimit;
    d[o + UPPER] = this.upperLimit;
    d[o + PERPENDICULAR_IMPULSE] = this.perpendicularImpulse;
    d[o + ANGULAR_IMPULSE] = this.angularImpulse;
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
    this.perpendicularImpulse = d[o + PERPENDICULAR_IMPULSE]!;
    this.angularImpulse = d[o + ANGULAR_IMPULSE]!;
    this.springImpulse = d[o + SPRING_IMPULSE]!;
    this.motorImpulse = d[o + MOTOR_IMPULSE]!;
    this.lowerImpulse = d[o + LOWER_IMPULSE]!;
    this.upperImpulse = d[o + UPPER_IMPULSE]!;
    this.stepImpulseX = d[o + STEP_IMPULSE_X]!;
    this.stepImpulseY = d[o + STEP_IMPULSE_Y]!;
    this.stepAngularImpulse = d[o + STEP_ANGULAR_IMPULSE]!;
  }
}
