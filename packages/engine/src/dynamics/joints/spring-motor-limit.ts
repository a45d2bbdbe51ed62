import { optionalBoolean } from '../../core/validate.ts';
import { Softness } from '../softness.ts';
import {
  optionalFinite,
  optionalNonNegative,
  requireOrdered,
  type JointStep,
  type SavedFields,
} from './joint.ts';

// A spring, a motor and a limit on one axis of a joint: the revolute joint's angle and the
// prismatic joint's translation (Box2D v3's revolute and prismatic joints, Catto). Their settings,
// option checks, saved values and per-step preparation are the same for both kinds and written
// here once, at the same offsets of both kinds' records (after the head, joint-record.ts); each
// kind's solver rows apply them along its own axis.

export const SPRING_ENABLED = 25; // JOINT_HEAD; settings: 1 or 0
export const HERTZ = 26; // JOINT_HEAD + 1
export const DAMPING_RATIO = 27; // JOINT_HEAD + 2
export const MOTOR_ON = 28; // JOINT_HEAD + 3
export const MOTOR_SPEED = 29; // JOINT_HEAD + 4
export const MAX_MOTOR = 30; // JOINT_HEAD + 5; torque (N m) or force (N)
export const LIMIT_ON = 31; // JOINT_HEAD + 6
export const LOWER = 32; // JOINT_HEAD + 7; UPPER must follow LOWER (Joint.setLimits)
export const UPPER = 33; // JOINT_HEAD + 8
export const SPRING_ON = 34; // JOINT_HEAD + 9; this step: 1 when the spring acts (enabled, above 0 Hz)
export const SPRING_BIAS_RATE = 35; // JOINT_HEAD + 10; the spring's softness this step
export const SPRING_MASS_SCALE = 36; // JOINT_HEAD + 11
export const SPRING_IMPULSE_SCALE = 37; // JOINT_HEAD + 12
export const SPRING_IMPULSE = 38; // JOINT_HEAD + 13; accumulated impulses (warm-started)
export const MOTOR_IMPULSE = 39; // JOINT_HEAD + 14
export const LOWER_IMPULSE = 40; // JOINT_HEAD + 15; UPPER_IMPULSE must follow (enableLimit clears both)
export const UPPER_IMPULSE = 41; // JOINT_HEAD + 16
/** Where the kind's own numbers start. */
export const SPRING_MOTOR_LIMIT_END = 42; // JOINT_HEAD + 17

/** The accumulated impulses of the spring, motor and limit rows. */
export const SPRING_MOTOR_LIMIT_IMPULSES: readonly number[] = [
  SPRING_IMPULSE,
  MOTOR_IMPULSE,
  LOWER_IMPULSE,
  UPPER_IMPULSE,
];

/** The kind's names of the settings that differ between kinds (the limit's ends, the motor's strength). */
export interface SpringMotorLimitNames {
  readonly lower: string;
  readonly upper: string;
  readonly maxMotor: string;
}

/** The options the two kinds name alike. */
export interface SpringMotorLimitOptions {
  readonly enableLimit?: boolean;
  readonly enableMotor?: boolean;
  readonly motorSpeed?: number;
  readonly enableSpring?: boolean;
  readonly hertz?: number;
  readonly dampingRatio?: number;
}

/** @internal The settings checked, with their defaults. */
export interface SpringMotorLimit {
  readonly enableLimit: boolean;
  readonly lower: number;
  readonly upper: number;
  readonly enableMotor: boolean;
  readonly motorSpeed: number;
  readonly maxMotor: number;
  readonly enableSpring: boolean;
  readonly hertz: number;
  readonly dampingRatio: number;
}

/**
 * @internal Checks the spring, motor and limit options in the order the kinds document them (a
 * PhysicalError naming the first bad one): the limit, then the motor, then the spring.
 */
export function checkSpringMotorLimit(
  options: SpringMotorLimitOptions,
  names: SpringMotorLimitNames,
  lower: number | undefined,
  upper: number | undefined,
  maxMotor: number | undefined,
): SpringMotorLimit {
  const enableLimit = optionalBoolean('enableLimit', options.enableLimit, false);
  const lowerValue = optionalFinite(names.lower, lower, 0);
  const upperValue = optionalFinite(names.upper, upper, 0);
  requireOrdered(names.lower, lowerValue, names.upper, upperValue);
  return {
    enableLimit,
    lower: lowerValue,
    upper: upperValue,
    enableMotor: optionalBoolean('enableMotor', options.enableMotor, false),
    motorSpeed: optionalFinite('motorSpeed', options.motorSpeed, 0),
    maxMotor: optionalNonNegative(names.maxMotor, maxMotor, 0),
    enableSpring: optionalBoolean('enableSpring', options.enableSpring, false),
    hertz: optionalNonNegative('hertz', options.hertz, 0),
    dampingRatio: optionalNonNegative('dampingRatio', options.dampingRatio, 0),
  };
}

/** @internal Writes checked settings into a joint's record at `o`. */
export function writeSpringMotorLimit(
  d: Float64Array,
  o: number,
  settings: SpringMotorLimit,
): void {
  d[o + LIMIT_ON] = settings.enableLimit ? 1 : 0;
  d[o + LOWER] = settings.lower;
  d[o + UPPER] = settings.upper;
  d[o + MOTOR_ON] = settings.enableMotor ? 1 : 0;
  d[o + MOTOR_SPEED] = settings.motorSpeed;
  d[o + MAX_MOTOR] = settings.maxMotor;
  d[o + SPRING_ENABLED] = settings.enableSpring ? 1 : 0;
  d[o + HERTZ] = settings.hertz;
  d[o + DAMPING_RATIO] = settings.dampingRatio;
}

/** @internal The settings a snapshot saves, by the kind's names, in the order it saves them. */
export function springMotorLimitSaved(names: SpringMotorLimitNames): SavedFields {
  return {
    enableLimit: ['boolean', LIMIT_ON],
    [names.lower]: ['finite', LOWER],
    [names.upper]: ['finite', UPPER],
    enableMotor: ['boolean', MOTOR_ON],
    motorSpeed: ['finite', MOTOR_SPEED],
    [names.maxMotor]: ['nonNegative', MAX_MOTOR],
    enableSpring: ['boolean', SPRING_ENABLED],
    hertz: ['nonNegative', HERTZ],
    dampingRatio: ['nonNegative', DAMPING_RATIO],
  };
}

/** @internal The impulses a snapshot saves, after the kind's own. */
export const SPRING_MOTOR_LIMIT_IMPULSES_SAVED: SavedFields = {
  springImpulse: ['finite', SPRING_IMPULSE],
  motorImpulse: ['finite', MOTOR_IMPULSE],
  lowerImpulse: ['nonNegative', LOWER_IMPULSE],
  upperImpulse: ['nonNegative', UPPER_IMPULSE],
};

const scratch = /* @__PURE__ */ new Softness();

/**
 * @internal The step's spring softness, and the impulses of the rows that are off
 * cleared, so they do not warm-start.
 */
export function prepareSpringMotorLimit(d: Float64Array, o: number, step: JointStep): void {
  scratch.set(d[o + HERTZ]!, d[o + DAMPING_RATIO]!, step.h);
  scratch.store(d, o + SPRING_BIAS_RATE);
  // A spring of 0 Hz exerts nothing (Box2D's soft constraint of 0 Hz would lock the motion).
  const springOn = d[o + SPRING_ENABLED] === 1 && d[o + HERTZ]! > 0;
  d[o + SPRING_ON] = springOn ? 1 : 0;
  if (!springOn) d[o + SPRING_IMPULSE] = 0;
  if (d[o + MOTOR_ON] !== 1) d[o + MOTOR_IMPULSE] = 0;
  if (d[o + LIMIT_ON] !== 1) {
    d[o + LOWER_IMPULSE] = 0;
    d[o + UPPER_IMPULSE] = 0;
  }
}
