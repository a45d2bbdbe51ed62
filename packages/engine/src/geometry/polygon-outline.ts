import { LINEAR_SLOP } from '../core/constants.ts';
import { PhysicalError } from '../core/errors.ts';
import { describeValue, requireVector } from '../core/validate.ts';
import type { Vec2Like } from '../math/vec2.ts';
import { hypot } from '../math/hypot.ts';

/** Points closer than this (m) are one point: below what the solver can resolve anyway. */
const DUPLICATE_TOLERANCE = 0.5 * LINEAR_SLOP;

/**
 * A vertex closer than this (m) to the line through its neighbours is treated as straight and
 * dropped, whichever way it bends: it would give an edge too short for a stable normal, and
 * rounding in user data must not turn a convex outline into a "concave" one.
 */
const STRAIGHT_TOLERANCE = 0.5 * LINEAR_SLOP;

/** Fewest corners a polygon may have. */
export const MIN_POLYGON_VERTICES = 3;

/** Most points a polygon outline may list (a concave outline is split into convex parts). */
export const MAX_OUTLINE_POINTS = 256;

/**
 * A validated simple outline: `count` distinct points, counter-clockwise, no straight vertices.
 * Scratch arrays may be longer than `count`.
 */
export interface Outline {
  readonly xs: Float64Array;
  readonly ys: Float64Array;
  readonly count: number;
}

/**
 * Validates a point list (body-local, m) as a simple polygon outline and cleans it: accepts
 * clockwise or counter-clockwise input and returns it counter-clockwise; merges points closer
 * than 0.5 * LINEAR_SLOP and drops vertices that are straight within that tolerance. Concave
 * outlines pass; self-intersecting, collinear and too-long ones do not.
 * @throws PhysicalError with field `${field}.vertices`, `${field}.vertices[i]`,
 *   `${field}.vertices[i].x`/`.y`.
 */
export function prepareOutline(points: ArrayLike<Vec2Like>, field: string): Outline {
  const verticesField = `${field}.vertices`;
  if (points === null || typeof points !== 'object' || typeof points.length !== 'number') {
    throw new PhysicalError(
      verticesField,
      `must be a list of points { x, y } in metres, got ${describeValue(points)}.`,
    );
  }
  const inputCount = points.length;
  if (inputCount > MAX_OUTLINE_POINTS) {
    throw new PhysicalError(
      verticesField,
      `has ${inputCount} points but an outline may have at most ${MAX_OUTLINE_POINTS}. ` +
        'Simplify the outline, or build the body from several shapes.',
    );
  }
  for (let i = 0; i < inputCount; i++) {
    requireVector(`${verticesField}[${i}]`, points[i]!);
  }

  // Merge consecutive near-duplicates, including the last point against the first (a closed
  // outline often repeats its first point at the end).
  const xs = new Float64Array(inputCount);
  const ys = new Float64Array(inputCount);
  let count = 0;
  for (let i = 0; i < inputCount; i++) {
    const p = points[i]!;
    if (count > 0 && distance(p.x, p.y, xs[count - 1]!, ys[count - 1]!) < DUPLICATE_TOLERANCE) {
      continue;
    }
    xs[count] = p.x;
    ys[count] = p.y;
    count++;
  }
  while (
    count > 1 &&
    distance(xs[0]!, ys[0]!, xs[count - 1]!, ys[count - 1]!) < DUPLICATE_TOLERANCE
  ) {
    count--;
  }
  if (count < MIN_POLYGON_VERTICES) {
    throw new PhysicalError(
      verticesField,
      `needs at least ${MIN_POLYGON_VERTICES} distinct points, got ${count} ` +
        `(points closer than ${DUPLICATE_TOLERANCE} m count as one). ` +
        'Give three or more corners, or use a circle or a wall for smaller shapes.',
    );
  }

  if (isCollinear(xs, ys, count)) {
    throw new PhysicalError(
      verticesField,
      `all ${count} points lie on one line, so the polygon has no area. ` +
        'Spread the corners out, or use a wall (segment) for a line.',
    );
  }

  const duplicate = findRepeatedPoint(xs, ys, count);
  if (duplicate >= 0) {
    throw new PhysicalError(
      verticesField,
      `point ${duplicate >> 8} and point ${duplicate & 0xff} are the same point, so the outline ` +
        'touches itself. List each corner once, in order around the shape.',
    );
  }

  const crossing = findSelfIntersection(xs, ys, count);
  if (crossing >= 0) {
    throw new PhysicalError(
      verticesField,
      `the outline is self-intersecting: edge ${crossing >> 8} (from point ${crossing >> 8}) ` +
        `crosses or touches edge ${crossing & 0xff}. ` +
        'List the corners in order around the shape (clockwise or counter-clockwise) without crossing.',
    );
  }

  if (signedDoubleArea(xs, ys, count) < 0) {
    xs.subarray(0, count).reverse();
    ys.subarray(0, count).reverse();
  }

  count = removeStraightVertices(xs, ys, count);
  if (count < MIN_POLYGON_VERTICES) {
    throw new PhysicalError(
      verticesField,
      `all points lie within ${STRAIGHT_TOLERANCE} m of one line, so the polygon has no area. ` +
        'Spread the corners out, or use a wall (segment) for a line.',
    );
  }
  return { xs, ys, count };
}

/** Index of the first vertex of a counter-clockwise outline that turns right (concave), or -1. */
export function findConcaveVertex(outline: Outline): number {
  const { xs, ys, count } = outline;
  for (let i = 0; i < count; i++) {
    const previous = i === 0 ? count - 1 : i - 1;
    const next = i === count - 1 ? 0 : i + 1;
    if (turn(xs, ys, previous, i, next) < 0) {
      return i;
    }
  }
  return -1;
}

/** Distance (m) between two points. */
export function distance(ax: number, ay: number, bx: number, by: number): number {
  return hypot(bx - ax, by - ay);
}

/** Twice the signed area (shoelace), relative to point 0 for precision. */
function signedDoubleArea(xs: Float64Array, ys: Float64Array, count: number): number {
  let sum = 0;
  for (let i = 1; i < count - 1; i++) {
    sum += (xs[i]! - xs[0]!) * (ys[i + 1]! - ys[0]!) - (ys[i]! - ys[0]!) * (xs[i + 1]! - xs[0]!);
  }
  return sum;
}

/** True when every point lies within STRAIGHT_TOLERANCE of the line through the farthest pair. */
function isCollinear(xs: Float64Array, ys: Float64Array, count: number): boolean {
  let first = 0;
  let second = 0;
  let widest = -1;
  for (let i = 0; i < count; i++) {
    for (let j = i + 1; j < count; j++) {
      const d = distance(xs[i]!, ys[i]!, xs[j]!, ys[j]!);
      if (d > widest) {
        widest = d;
        first = i;
        second = j;
      }
    }
  }
  const ux = (xs[second]! - xs[first]!) / widest;
  const uy = (ys[second]! - ys[first]!) / widest;
  for (let i = 0; i < count; i++) {
    const offset = ux * (ys[i]! - ys[first]!) - uy * (xs[i]! - xs[first]!);
    if (Math.abs(offset) >= STRAIGHT_TOLERANCE) {
      return false;
    }
  }
  return true;
}

/** Cross product (b - a) x (c - b): > 0 turns left (convex for counter-clockwise), < 0 right. */
function turn(xs: Float64Array, ys: Float64Array, a: number, b: number, c: number): number {
  return (xs[b]! - xs[a]!) * (ys[c]! - ys[b]!) - (ys[b]! - ys[a]!) * (xs[c]! - xs[b]!);
}

/** Signed orientation of c against the directed line a -> b (twice the triangle's area). */
export function orientation(
  ax: number,
  ay: number,
  bx: number,
  by: number,
  cx: number,
  cy: number,
): number {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

/** True when closed segments ab and cd share a point (crossing, touching or overlapping). */
function segmentsIntersect(
  ax: number,
  ay: number,
  bx: number,
  by: number,
  cx: number,
  cy: number,
  dx: number,
  dy: number,
): boolean {
  const o1 = orientation(ax, ay, bx, by, cx, cy);
  const o2 = orientation(ax, ay, bx, by, dx, dy);
  const o3 = orientation(cx, cy, dx, dy, ax, ay);
  const o4 = orientation(cx, cy, dx, dy, bx, by);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) {
    return true;
  }
  return (
    (o1 === 0 && isWithinBox(ax, ay, bx, by, cx, cy)) ||
    (o2 === 0 && isWithinBox(ax, ay, bx, by, dx, dy)) ||
    (o3 === 0 && isWithinBox(cx, cy, dx, dy, ax, ay)) ||
    (o4 === 0 && isWithinBox(cx, cy, dx, dy, bx, by))
  );
}

function isWithinBox(
  ax: number,
  ay: number,
  bx: number,
  by: number,
  px: number,
  py: number,
): boolean {
  return (
    Math.min(ax, bx) <= px &&
    px <= Math.max(ax, bx) &&
    Math.min(ay, by) <= py &&
    py <= Math.max(ay, by)
  );
}

/**
 * Returns (i << 8) | j for the first two non-consecutive points closer than DUPLICATE_TOLERANCE
 * (an outline that pinches itself at one point), or -1.
 */
function findRepeatedPoint(xs: Float64Array, ys: Float64Array, count: number): number {
  for (let i = 0; i < count; i++) {
    for (let j = i + 1; j < count; j++) {
      if (distance(xs[i]!, ys[i]!, xs[j]!, ys[j]!) < DUPLICATE_TOLERANCE) {
        return (i << 8) | j;
      }
    }
  }
  return -1;
}

/**
 * Returns (i << 8) | j for the first pair of edges that intersect, or -1 for a simple outline.
 * Non-adjacent edges may not meet at all; adjacent edges may not fold back onto each other
 * (a spike: the outline reverses direction at their shared vertex).
 */
function findSelfIntersection(xs: Float64Array, ys: Float64Array, count: number): number {
  for (let i = 0; i < count; i++) {
    const i1 = i === count - 1 ? 0 : i + 1;
    const i2 = i1 === count - 1 ? 0 : i1 + 1;
    const ex = xs[i1]! - xs[i]!;
    const ey = ys[i1]! - ys[i]!;
    const fx = xs[i2]! - xs[i1]!;
    const fy = ys[i2]! - ys[i1]!;
    const cross = ex * fy - ey * fx;
    const lengths = hypot(ex, ey) * hypot(fx, fy);
    if (ex * fx + ey * fy < 0 && Math.abs(cross) <= 1e-12 * lengths) {
      return (i << 8) | i1;
    }
    for (let j = i + 2; j < count; j++) {
      if (i === 0 && j === count - 1) {
        continue;
      }
      const j1 = j === count - 1 ? 0 : j + 1;
      if (segmentsIntersect(xs[i]!, ys[i]!, xs[i1]!, ys[i1]!, xs[j]!, ys[j]!, xs[j1]!, ys[j1]!)) {
        return (i << 8) | j;
      }
    }
  }
  return -1;
}

/**
 * Drops vertices within STRAIGHT_TOLERANCE of the line through their neighbours, repeating until
 * none is left, and returns the new count. Expects a counter-clockwise, simple outline.
 */
function removeStraightVertices(xs: Float64Array, ys: Float64Array, count: number): number {
  let isChanged = true;
  while (isChanged && count >= MIN_POLYGON_VERTICES) {
    isChanged = false;
    for (let i = 0; i < count; i++) {
      const previous = i === 0 ? count - 1 : i - 1;
      const next = i === count - 1 ? 0 : i + 1;
      const baseLength = distance(xs[previous]!, ys[previous]!, xs[next]!, ys[next]!);
      const offset =
        orientation(xs[previous]!, ys[previous]!, xs[next]!, ys[next]!, xs[i]!, ys[i]!) /
        baseLength;
      if (Math.abs(offset) < STRAIGHT_TOLERANCE) {
        xs.copyWithin(i, i + 1, count);
        ys.copyWithin(i, i + 1, count);
        count--;
        isChanged = true;
        break;
      }
    }
  }
  return count;
}
