import { PhysicalError } from './errors.ts';

// Validation at the entrance: every value a user hands the engine passes one of these, so a
// NaN, an absurd magnitude or a wrong type is reported where it came in instead of spreading
// through a step. Factories, setters, Force handles, joints, queries and snapshots all use them,
// and every public mutator runs them all before it changes anything (a refused call is a no-op).

// ---------------------------------------------------------------- physical ranges
// The documented ranges (packages/engine/README.md, "Valid ranges"). They are far wider than any real scene
// needs; what they rule out are magnitudes whose squares or products overflow a double inside a
// step (a radius of 1e50, a speed of 1e300), which would otherwise surface later as NaN.

/** Largest |x| or |y| of a position, point, anchor, offset or query coordinate (m). */
export const MAX_COORDINATE = 1e7;
/** Largest size: radius, width, height, length, rounding (m). */
export const MAX_SIZE = 1e5;
/** Largest density (kg/m^2). */
export const MAX_DENSITY = 1e6;
/** Smallest and largest mass of a dynamic body, given or computed (kg). */
export const MIN_MASS = 1e-9;
export const MAX_MASS = 1e15;
/** Smallest and largest moment of inertia given by hand (kg m^2). */
export const MIN_INERTIA = 1e-15;
export const MAX_INERTIA = 1e25;
/** Largest |component| of a velocity (m/s) and largest angular speed (rad/s). */
export const MAX_SPEED = 1e6;
export const MAX_ANGULAR_SPEED = 1e6;
/** Largest |angle| (rad); angles are unwrapped, so this allows 1.6e8 turns. */
export const MAX_ANGLE = 1e9;
/** Largest |component| of a force (N), torque (N m), impulse (N s) or angular impulse (N m s). */
export const MAX_FORCE = 1e18;
/** Largest |component| of gravity (m/s^2) and largest |gravityScale|. */
export const MAX_ACCELERATION = 1e6;
export const MAX_GRAVITY_SCALE = 1e3;
/** Largest linear or angular damping (1/s) and drag coefficient (N s^2/m^2). */
export const MAX_DAMPING = 1e6;
/** Largest friction coefficient and coefficient of restitution. */
export const MAX_FRICTION = 100;
export const MAX_RESTITUTION = 10;
/** Largest spring or contact stiffness (Hz) and damping ratio. */
export const MAX_HERTZ = 1e4;
export const MAX_DAMPING_RATIO = 1e4;
/**
 * Smallest non-zero and largest time step (s), and largest duration of a force or time to sleep
 * (s). A step far below a microsecond would turn a joint's impulse into an infinite force.
 */
export const MIN_TIME_STEP = 1e-6;
export const MAX_TIME_STEP = 1;
export const MAX_DURATION = 1e9;

// ---------------------------------------------------------------- rendering bad values

/** Longest rendering of a bad value in a message (characters). */
const MAX_RENDERED = 40;

/**
 * A short rendering of any value for an error message: strings quoted and cut to 40 characters,
 * arrays and objects named, never their contents (a 50 MB input gives a short message).
 */
export function describeValue(value: unknown): string {
  if (typeof value === 'string') {
    const cut = value.length > MAX_RENDERED ? `${value.slice(0, MAX_RENDERED)}...` : value;
    return `'${cut}'${value.length > MAX_RENDERED ? ` (${value.length} characters)` : ''}`;
  }
  if (Array.isArray(value)) return `an array of ${value.length}`;
  if (typeof value === 'function') return 'a function';
  if (typeof value === 'symbol') return 'a symbol';
  if (typeof value === 'bigint') return `${value}n`.slice(0, MAX_RENDERED);
  if (value !== null && typeof value === 'object') return 'an object';
  return String(value);
}

// ---------------------------------------------------------------- numbers

export function requireFinite(field: string, value: number): number {
  if (typeof value !== 'number' || !Number.isFinite(value)) {
    throw new PhysicalError(field, `must be a finite number, got ${describeValue(value)}.`);
  }
  return value;
}

/** A finite number from `min` to `max` (inclusive); `unit` names it in the message. */
export function requireRange(
  field: string,
  value: number,
  min: number,
  max: number,
  unit: string = '',
): number {
  requireFinite(field, value);
  if (value < min || value > max) {
    const u = unit === '' ? '' : ` ${unit}`;
    throw new PhysicalError(field, `must be from ${min} to ${max}${u}, got ${value}.`);
  }
  return value;
}

export function requirePositive(field: string, value: number, max: number = Infinity): number {
  requireFinite(field, value);
  if (value <= 0) {
    throw new PhysicalError(field, `must be greater than zero, got ${value}.`);
  }
  if (value > max) {
    throw new PhysicalError(field, `must be at most ${max}, got ${value}.`);
  }
  return value;
}

export function requireNonNegative(field: string, value: number, max: number = Infinity): number {
  requireFinite(field, value);
  if (value < 0) {
    throw new PhysicalError(field, `must be zero or more, got ${value}.`);
  }
  if (value > max) {
    throw new PhysicalError(field, `must be at most ${max}, got ${value}.`);
  }
  return value;
}

/** A size (m): greater than zero, at most MAX_SIZE. */
export function requireSize(field: string, value: number): number {
  return requirePositive(field, value, MAX_SIZE);
}

/** A coordinate (m): |value| <= MAX_COORDINATE. */
export function requireCoordinate(field: string, value: number): number {
  return requireRange(field, value, -MAX_COORDINATE, MAX_COORDINATE, 'm');
}

/** An angle (rad): |value| <= MAX_ANGLE. */
export function requireAngle(field: string, value: number): number {
  return requireRange(field, value, -MAX_ANGLE, MAX_ANGLE, 'rad');
}

/**
 * A vector { x, y } whose components are finite and at most `limit` in size (default
 * MAX_COORDINATE: a point in metres).
 */
export function requireVector(
  field: string,
  value: { readonly x: number; readonly y: number },
  limit: number = MAX_COORDINATE,
): void {
  if (value === null || typeof value !== 'object') {
    throw new PhysicalError(field, `must be a vector { x, y }, got ${describeValue(value)}.`);
  }
  requireRange(`${field}.x`, value.x, -limit, limit);
  requireRange(`${field}.y`, value.y, -limit, limit);
}

// ---------------------------------------------------------------- other kinds

/** A boolean: true or false, nothing that merely converts to one. */
export function requireBoolean(field: string, value: unknown): boolean {
  if (typeof value !== 'boolean') {
    throw new PhysicalError(field, `must be true or false, got ${describeValue(value)}.`);
  }
  return value;
}

/** An optional boolean: `fallback` when undefined, else true or false. */
export function optionalBoolean(field: string, value: unknown, fallback: boolean): boolean {
  return value === undefined ? fallback : requireBoolean(field, value);
}

/** One of a fixed set of strings. */
export function requireOneOf<T extends string>(
  field: string,
  value: unknown,
  allowed: readonly T[],
): T {
  if (typeof value !== 'string' || !(allowed as readonly string[]).includes(value)) {
    const names = allowed.map((a) => `'${a}'`).join(', ');
    throw new PhysicalError(field, `must be one of ${names}, got ${describeValue(value)}.`);
  }
  return value as T;
}

/** An object (not null, not an array); `what` says what it should be. */
export function requireObject(field: string, value: unknown, what: string): void {
  if (value === null || typeof value !== 'object' || Array.isArray(value)) {
    throw new PhysicalError(field, `must be ${what}, got ${describeValue(value)}.`);
  }
}

/** An optional options object: undefined is fine, anything else must be an object. */
export function optionalObject(field: string, value: unknown, what: string): void {
  if (value !== undefined) requireObject(field, value, what);
}

/** A function (a listener or a visitor). */
export function requireFunction(field: string, value: unknown): void {
  if (typeof value !== 'function') {
    throw new PhysicalError(field, `must be a function, got ${describeValue(value)}.`);
  }
}
