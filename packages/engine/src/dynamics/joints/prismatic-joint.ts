import { PhysicalError, readOnly } from '../../core/errors.ts';
import { JointBatch } from './joint-batch.ts';
import { KIND_PRISMATIC } from './joint-pass-codes.ts';
import type { Vec2Like } from '../../math/vec2.ts';
import { hypot } from '../../math/hypot.ts';
import {
  AXIS_X,
  AXIS_Y,
  ANGULAR_IMPULSE,
  LOCAL_AXIS_X,
  LOCAL_AXIS_Y,
  PERPENDICULAR_IMPULSE,
  STRIDE,
} from './prismatic-joint-solver.ts';
import {
  checkCollideConnected,
  jointLayout,
  stateLayout,
  type JointLayout,
  type JointStateLayout,
  type JointStep,
  requireBodies,
  requirePoint,
} from './joint.ts';
import { TwoBodyJoint } from './two-body-joint.ts';
import type { JointOptions } from './joint.ts';
import { LOCAL_ANCHOR_AX, LOCAL_ANCHOR_BX, REFERENCE_ANGLE } from './joint-record.ts';
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

const NAMES = { lower: 'lower', upper: 'upper', maxMotor: 'maxMotorForce' } as const;

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
  const settings = checkSpringMotorLimit(
    options,
    NAMES,
    options.lower,
    options.upper,
    options.maxMotorForce,
  );
  return { anchor, axis, settings };
}

const LAYOUT: JointLayout = /* @__PURE__ */ jointLayout(
  STRIDE,
  [
    {
      localAnchorA: ['vector', LOCAL_ANCHOR_AX],
      localAnchorB: ['vector', LOCAL_ANCHOR_BX],
      localAxis: ['unitVector', LOCAL_AXIS_X],
      referenceAngle: ['finite', REFERENCE_ANGLE],
    },
    /* @__PURE__ */ springMotorLimitSaved(NAMES),
    {
      perpendicularImpulse: ['finite', PERPENDICULAR_IMPULSE],
      angularImpulse: ['finite', ANGULAR_IMPULSE],
    },
    SPRING_MOTOR_LIMIT_IMPULSES_SAVED,
  ],
  [[PERPENDICULAR_IMPULSE, ANGULAR_IMPULSE], SPRING_MOTOR_LIMIT_IMPULSES],
);

/** @internal What a world snapshot saves of a prismatic joint (see exportJointState). */
export const PRISMATIC_STATE: JointStateLayout = /* @__PURE__ */ stateLayout(LAYOUT, [
  ['lower', 'upper'],
]);

/**
 * A slider: body B moves along an axis fixed in body A and cannot turn relative to it; optional
 * translation limits, motor and spring. Box2D v3's prismatic joint (Catto): the axial rows (spring,
 * motor, limits) first, then a 2x2 block for the perpendicular offset and the relative angle.
 */
export class PrismaticJoint<UserData = unknown> extends TwoBodyJoint<UserData> {
  get type(): 'prismatic' {
    return 'prismatic';
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set type(_value: never) {
    readOnly('type', 'a joint keeps its kind');
  }

  constructor(options: PrismaticJointOptions<UserData>) {
    const { anchor, axis, settings } = checkPrismaticJointOptions(options);
    const axisLength = hypot(axis.x, axis.y);
    super(options, options.bodyA, options.bodyB, STRIDE);
    this.setAnchors(anchor, anchor);
    const { c, s } = this.bodyA.transform;
    const ux = axis.x / axisLength;
    const uy = axis.y / axisLength;
    this.write(LOCAL_AXIS_X, c * ux + s * uy);
    this.write(LOCAL_AXIS_Y, -s * ux + c * uy);
    this.write(REFERENCE_ANGLE, this.bodyB.angle - this.bodyA.angle);
    writeSpringMotorLimit(this.store.data, this.base, settings);
  }

  /** @internal */
  protected get layout(): JointLayout {
    return LAYOUT;
  }

  /** Translation of B's anchor from A's along the axis (m). */
  get translation(): number {
    const a = this.anchorA;
    const ax0 = a.x;
    const ay0 = a.y;
    const b = this.anchorB;
    const { c, s } = this.bodyA.transform;
    const localX = this.value(LOCAL_AXIS_X);
    const localY = this.value(LOCAL_AXIS_Y);
    const ax = c * localX - s * localY;
    const ay = s * localX + c * localY;
    return (b.x - ax0) * ax + (b.y - ay0) * ay;
  }

  /** Whether the translation limits hold. Changing it wakes the bodies. */
  get enableLimit(): boolean {
    return this.flag(LIMIT_ON);
  }

  set enableLimit(value: boolean) {
    this.setSwitch('enableLimit', LIMIT_ON, value, LOWER_IMPULSE, 2);
  }

  /** Lowest translation (m); must not exceed upper (use setLimits to move both). */
  get lower(): number {
    return this.value(LOWER);
  }

  set lower(value: number) {
    this.setRange(NAMES.lower, NAMES.upper, LOWER, value, this.value(UPPER), 'lower');
  }

  /** Highest translation (m). */
  get upper(): number {
    return this.value(UPPER);
  }

  set upper(value: number) {
    this.setRange(NAMES.lower, NAMES.upper, LOWER, this.value(LOWER), value, 'upper');
  }

  /** Sets both translation limits (m); wakes the bodies. */
  setLimits(lower: number, upper: number): void {
    this.setRange(NAMES.lower, NAMES.upper, LOWER, lower, upper, 'lower');
  }

  /** Whether the motor drives the joint. Changing it wakes the bodies. */
  get enableMotor(): boolean {
    return this.flag(MOTOR_ON);
  }

  set enableMotor(value: boolean) {
    this.setSwitch('enableMotor', MOTOR_ON, value, MOTOR_IMPULSE, 1);
  }

  /** Target speed along the axis (m/s). Setting it wakes the bodies. */
  get motorSpeed(): number {
    return this.value(MOTOR_SPEED);
  }

  set motorSpeed(value: number) {
    this.setNumber('motorSpeed', MOTOR_SPEED, value, 'any');
  }

  /** Strongest motor force (N). Setting it wakes the bodies. */
  get maxMotorForce(): number {
    return this.value(MAX_MOTOR);
  }

  set maxMotorForce(value: number) {
    this.setNumber(NAMES.maxMotor, MAX_MOTOR, value, 'nonNegative');
  }

  /** Force the motor applied in the last sub-step (N). */
  get motorForce(): number {
    return this.value(MOTOR_IMPULSE) / this.subStepDuration;
  }

  /** Whether the spring acts. Changing it wakes the bodies. */
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
    const ta = this.bodyA.transform;
    d[o + AXIS_X] = ta.c * d[o + LOCAL_AXIS_X]! - ta.s * d[o + LOCAL_AXIS_Y]!;
    d[o + AXIS_Y] = ta.s * d[o + LOCAL_AXIS_X]! + ta.c * d[o + LOCAL_AXIS_Y]!;
    prepareSpringMotorLimit(d, o, step);
  }

  /** @internal */
  override createBatch(): JointBatch {
    return new JointBatch(KIND_PRISMATIC);
  }
}
