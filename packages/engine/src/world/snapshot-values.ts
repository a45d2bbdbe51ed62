import { PhysicalError } from '../core/errors.ts';
import { describeValue } from '../core/validate.ts';

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
