import { PhysicalError } from '../core/errors.ts';
import {
  describeValue,
  MAX_ANGLE,
  MAX_ANGULAR_SPEED,
  MAX_COORDINATE,
  MAX_DURATION,
  MAX_FORCE,
  MAX_SPEED,
} from '../core/validate.ts';

// How numbers are written into a snapshot, and the checked readers every section's loader uses:
// each names the offending field as `snapshot.<path>` in its PhysicalError.
//
// JSON keeps every finite double exactly (shortest round-trip printing), but turns -0 into 0 and
// infinities into null. Those three are written as the strings '-0', 'Infinity' and '-Infinity';
// NaN never occurs in a valid world and is rejected on load.

/** A number as stored: finite numbers as themselves, -0 and infinities as strings. */
export type SnapshotNumber = number | '-0' | 'Infinity' | '-Infinity';

/** Any value inside a snapshot. */
export type SnapshotValue =
  | SnapshotNumber
  | string
  | boolean
  | null
  | readonly SnapshotValue[]
  | { readonly [key: string]: SnapshotValue };

/** @internal A parsed snapshot object, not yet checked. */
export type Obj = Record<string, unknown>;

/** @internal Largest body or shape id a snapshot may hold. */
export const MAX_ID = 0x1fffffff;

// What a saved world may hold. The API's own limits bound what an app sets (a position within
// MAX_COORDINATE, a speed within MAX_SPEED); a simulated world may go past them (a body falls,
// a joint accumulates impulse), so its snapshot is read with margins above them. What the
// margins rule out is what no world reaches and what overflows a double within a step once
// squared or multiplied: a flipped byte's 1e300 centre, a 4.7e219 impulse.

/** @internal Largest |coordinate| of a saved position, centre, box or anchor (m). */
export const SAVED_COORDINATE = 1e4 * MAX_COORDINATE;
/** @internal Largest |angle| saved (rad): unwrapped angles grow with every turn. */
export const SAVED_ANGLE = 1e3 * MAX_ANGLE;
/** @internal Largest |component| of a saved linear velocity (m/s); the solver may exceed its clamp within a step. */
export const SAVED_SPEED = 100 * MAX_SPEED;
/** @internal Largest saved |angular velocity| (rad/s): the solver's clamp is a quarter turn per sub-step. */
export const SAVED_ANGULAR_SPEED = 1e3 * MAX_ANGULAR_SPEED;
/** @internal Longest saved time (s): a sleep timer or a force's time left. */
export const SAVED_DURATION = 1e3 * MAX_DURATION;
/** @internal Largest |component| of a saved force, torque or accumulated impulse (N, N m, N s). */
export const SAVED_IMPULSE = 1e6 * MAX_FORCE;
/** @internal Largest |component| of a saved reaction (impulse over the step: N, N m). */
export const SAVED_REACTION = SAVED_IMPULSE / 1e-6;

/** @internal */
export function enc(x: number): SnapshotNumber {
  if (x === 0 && 1 / x < 0) return '-0';
  if (x === Infinity) return 'Infinity';
  if (x === -Infinity) return '-Infinity';
  return x;
}

/** @internal */
export function encAll(values: ArrayLike<number>, count: number = values.length): SnapshotNumber[] {
  const out: SnapshotNumber[] = [];
  for (let i = 0; i < count; i++) out.push(enc(values[i]!));
  return out;
}

/** @internal */
export function fail(path: string, message: string): never {
  throw new PhysicalError(`snapshot.${path}`, message);
}

/** @internal */
export function describe(v: unknown): string {
  return describeValue(v);
}

/** @internal */
export function obj(path: string, v: unknown): Obj {
  if (v === null || typeof v !== 'object' || Array.isArray(v)) {
    fail(path, `must be an object, got ${describe(v)}.`);
  }
  return v as Obj;
}

/** @internal */
export function arr(path: string, v: unknown, length?: number): unknown[] {
  if (!Array.isArray(v)) fail(path, `must be an array, got ${describe(v)}.`);
  if (length !== undefined && v.length !== length) {
    fail(path, `must hold ${length} entries, got ${v.length}.`);
  }
  // A structured clone (postMessage, IndexedDB) keeps holes, and map() and forEach() skip them.
  for (let i = 0; i < v.length; i++) {
    if (!(i in v)) fail(`${path}[${i}]`, 'is missing (a hole in the array).');
  }
  return v;
}

/** @internal */
export function num(path: string, v: unknown): number {
  if (typeof v === 'number') {
    if (Number.isNaN(v)) fail(path, 'must be a number, got NaN.');
    return v;
  }
  if (v === '-0') return -0;
  if (v === 'Infinity') return Infinity;
  if (v === '-Infinity') return -Infinity;
  return fail(path, `must be a number, got ${describe(v)}.`);
}

/** @internal */
export function finite(path: string, v: unknown): number {
  const x = num(path, v);
  if (!Number.isFinite(x)) fail(path, `must be finite, got ${x}.`);
  return x;
}

/** @internal A finite number from `min` to `max`: the range the public setters allow. */
export function ranged(path: string, v: unknown, min: number, max: number): number {
  const x = finite(path, v);
  if (x < min || x > max) fail(path, `must be from ${min} to ${max}, got ${x}.`);
  return x;
}

/** @internal */
export function nonNegative(path: string, v: unknown): number {
  const x = finite(path, v);
  if (x < 0) fail(path, `must be zero or more, got ${x}.`);
  return x;
}

/** @internal */
export function positive(path: string, v: unknown): number {
  const x = finite(path, v);
  if (x <= 0) fail(path, `must be greater than zero, got ${x}.`);
  return x;
}

/** @internal */
export function finites(path: string, v: unknown, length: number): number[] {
  return arr(path, v, length).map((x, i) => finite(`${path}[${i}]`, x));
}

/** @internal `length` numbers, each from -max to max. */
export function bounded(path: string, v: unknown, length: number, max: number): number[] {
  return arr(path, v, length).map((x, i) => ranged(`${path}[${i}]`, x, -max, max));
}

/** @internal */
export function int(path: string, v: unknown, min: number, max: number): number {
  if (typeof v !== 'number' || !Number.isInteger(v) || v < min || v > max) {
    fail(path, `must be a whole number from ${min} to ${max}, got ${describe(v)}.`);
  }
  return v;
}

/** @internal */
export function bool(path: string, v: unknown): boolean {
  if (typeof v !== 'boolean') fail(path, `must be true or false, got ${describe(v)}.`);
  return v;
}

/** @internal The value of `o[key]`; a missing key names `path.key` (`key` at the top). */
export function field(o: Obj, path: string, key: string): unknown {
  if (!(key in o)) fail(path === '' ? key : `${path}.${key}`, 'is missing.');
  return o[key];
}
