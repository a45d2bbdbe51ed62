import { PhysicalError } from '../core/errors.ts';
import { describeValue } from '../core/validate.ts';

/**
 * Which shapes collide, by bits and groups (Box2D's collision filter semantics):
 * - `category`: the bits this shape is (usually one bit), default 1;
 * - `mask`: the categories it collides with, default 0xFFFFFFFF (everything);
 * - `group`: shapes with the same non-zero group always collide when it is positive and never
 *   when it is negative (the parts of a ragdoll share a negative group), whatever the bits say;
 *   otherwise two shapes collide when each one's category is in the other's mask.
 *
 * Bits are unsigned 32-bit integers; the group is a whole number from -2^31 to 2^31 - 1.
 */
export interface FilterOptions {
  readonly category?: number;
  readonly mask?: number;
  readonly group?: number;
}

/** A resolved filter: every field present. */
export interface Filter {
  readonly category: number;
  readonly mask: number;
  readonly group: number;
}

/** Default category bits: the first category. */
export const DEFAULT_CATEGORY = 1;
/** Default mask: collide with every category. */
export const DEFAULT_MASK = 0xffffffff;

/** Validates filter options and fills the defaults. Throws a PhysicalError naming the field. */
export function resolveFilter(field: string, options: FilterOptions | undefined): Filter {
  if (options === undefined) return { category: DEFAULT_CATEGORY, mask: DEFAULT_MASK, group: 0 };
  if (options === null || typeof options !== 'object') {
    throw new PhysicalError(
      field,
      `must be an object { category?, mask?, group? }, got ${describeValue(options)}.`,
    );
  }
  return {
    category: requireBits(`${field}.category`, options.category ?? DEFAULT_CATEGORY),
    mask: requireBits(`${field}.mask`, options.mask ?? DEFAULT_MASK),
    group: requireGroup(`${field}.group`, options.group ?? 0),
  };
}

function requireBits(field: string, value: number): number {
  if (typeof value !== 'number' || !Number.isInteger(value) || value < 0 || value > 0xffffffff) {
    throw new PhysicalError(
      field,
      `must be a whole number from 0 to 0xFFFFFFFF (32 bits), got ${describeValue(value)}.`,
    );
  }
  return value;
}

function requireGroup(field: string, value: number): number {
  if (
    typeof value !== 'number' ||
    !Number.isInteger(value) ||
    value < -0x80000000 ||
    value > 0x7fffffff
  ) {
    throw new PhysicalError(
      field,
      `must be a whole number from -2147483648 to 2147483647, got ${describeValue(value)}.`,
    );
  }
  return value;
}

/** Filter fields a shape carries (numbers, read in the broad phase's pair callback). */
export interface Filtered {
  readonly categoryBits: number;
  readonly maskBits: number;
  readonly groupIndex: number;
}

/** Whether two filters let their shapes collide (Box2D's rule: group first, then the bits). */
export function filtersCollide(a: Filtered, b: Filtered): boolean {
  if (a.groupIndex === b.groupIndex && a.groupIndex !== 0) return a.groupIndex > 0;
  return (a.categoryBits & b.maskBits) !== 0 && (b.categoryBits & a.maskBits) !== 0;
}
