import { MAX_POLYGON_VERTICES } from '../core/constants.ts';
import { PhysicalError } from '../core/errors.ts';
import { MAX_SIZE, requireNonNegative } from '../core/validate.ts';
import type { Vec2Like } from '../math/vec2.ts';
import { makePolygonFromOutline, type Polygon } from './polygon.ts';
import { findConcaveVertex, prepareOutline, type Outline } from './polygon-outline.ts';

/**
 * Builds the convex parts of any simple polygon outline (body-local, m; either winding, up to
 * MAX_OUTLINE_POINTS points). A convex outline of at most MAX_POLYGON_VERTICES corners is one
 * part; anything else is split into convex parts of at most MAX_POLYGON_VERTICES corners that
 * tile it exactly (they meet along shared diagonals and do not overlap), so the sum of the
 * parts' mass properties is the outline's.
 *
 * Algorithm: ear clipping into triangles (Meisters' two-ears theorem; Eberly, "Triangulation by
 * Ear Clipping", 2002), then Hertel and Mehlhorn's merge (1983): drop every diagonal whose two
 * sides still form a convex polygon, here also of at most MAX_POLYGON_VERTICES corners. The
 * result has at most four times the fewest possible convex parts.
 *
 * `radius` > 0 rounds only a single convex part: rounded parts of a split outline would overlap
 * along their diagonals, and their mass would count the overlap twice.
 * @throws PhysicalError naming `${field}.vertices` (self-intersecting, repeated or collinear
 *   points, no area, too many points) or `${field}.radius`.
 */
export function makePolygonParts(
  points: ArrayLike<Vec2Like>,
  radius: number,
  field: string,
): Polygon[] {
  const outline = prepareOutline(points, field);
  requireNonNegative(`${field}.radius`, radius, MAX_SIZE);
  if (findConcaveVertex(outline) < 0 && outline.count <= MAX_POLYGON_VERTICES) {
    return [makePolygonFromOutline(outline.xs, outline.ys, outline.count, radius)];
  }
  if (radius > 0) {
    throw new PhysicalError(
      `${field}.radius`,
      `only a convex polygon of at most ${MAX_POLYGON_VERTICES} corners can be rounded; this ` +
        `outline (${outline.count} corners${findConcaveVertex(outline) >= 0 ? ', concave' : ''}) ` +
        'is split into convex parts, whose rounding would overlap. Use radius 0, or round ' +
        'convex pieces added as separate shapes.',
    );
  }
  const parts = mergeConvex(outline, triangulate(outline, field));
  const xs: number[] = [];
  const ys: number[] = [];
  const polygons: Polygon[] = [];
  for (const part of parts) {
    xs.length = 0;
    ys.length = 0;
    for (const index of part) {
      xs.push(outline.xs[index]!);
      ys.push(outline.ys[index]!);
    }
    polygons.push(makePolygonFromOutline(xs, ys, part.length, 0));
  }
  return polygons;
}

/**
 * Ear clipping of a counter-clockwise simple outline: repeatedly cuts off a convex vertex whose
 * triangle holds no other remaining vertex (inside or on its edges). Returns the triangles as
 * vertex-index triples, counter-clockwise.
 */
function triangulate(outline: Outline, field: string): number[][] {
  const { xs, ys, count } = outline;
  const next = new Int32Array(count);
  const previous = new Int32Array(count);
  for (let i = 0; i < count; i++) {
    next[i] = i === count - 1 ? 0 : i + 1;
    previous[i] = i === 0 ? count - 1 : i - 1;
  }
  const scale = outlineScale(outline);
  // Twice a triangle's area below this is no area at all (round-off of the cross product).
  const flat = 1e-12 * scale * scale;
  const triangles: number[][] = [];
  let remaining = count;
  let vertex = 0;
  let sinceLastEar = 0;
  while (remaining > 3) {
    const a = previous[vertex]!;
    const c = next[vertex]!;
    const area = cross(xs, ys, a, vertex, c);
    let isEar = false;
    if (Math.abs(area) <= flat) {
      // A straight vertex left by earlier cuts: drop it, it adds no area.
      next[a] = c;
      previous[c] = a;
      remaining--;
      vertex = c;
      sinceLastEar = 0;
      continue;
    }
    if (area > 0) {
      isEar = true;
      for (let w = next[c]!; w !== a; w = next[w]!) {
        if (isInTriangle(xs, ys, a, vertex, c, w, flat)) {
          isEar = false;
          break;
        }
      }
    }
    if (isEar) {
      triangles.push([a, vertex, c]);
      next[a] = c;
      previous[c] = a;
      remaining--;
      vertex = c;
      sinceLastEar = 0;
    } else {
      vertex = c;
      sinceLastEar++;
      if (sinceLastEar > remaining) {
        // A simple outline always has an ear; only round-off in a nearly degenerate outline
        // gets here.
        throw new PhysicalError(
          `${field}.vertices`,
          'could not be split into convex parts: the outline is too close to touching itself. ' +
            'Move nearly touching corners apart.',
        );
      }
    }
  }
  const a = previous[vertex]!;
  const c = next[vertex]!;
  if (cross(xs, ys, a, vertex, c) > flat) {
    triangles.push([a, vertex, c]);
  }
  return triangles;
}

/**
 * Hertel-Mehlhorn: merges parts across shared diagonals while the union stays convex (no right
 * turn at the diagonal's two ends; an exactly straight end is dropped) and has at most
 * MAX_POLYGON_VERTICES corners.
 */
function mergeConvex(outline: Outline, triangles: number[][]): number[][] {
  const { xs, ys, count } = outline;
  const scale = outlineScale(outline);
  const flat = 1e-12 * scale * scale;
  const parts: (number[] | null)[] = triangles;
  // owner[a * count + b]: the part holding directed edge a -> b.
  const owner = new Int32Array(count * count).fill(-1);
  for (let p = 0; p < parts.length; p++) setOwner(owner, count, parts[p]!, p);
  let isChanged = true;
  while (isChanged) {
    isChanged = false;
    for (let p = 0; p < parts.length; p++) {
      const part = parts[p];
      if (part === null || part === undefined) continue;
      for (let e = 0; e < part.length; e++) {
        const a = part[e]!;
        const b = part[e + 1 === part.length ? 0 : e + 1]!;
        const q = owner[b * count + a]!;
        const other = q < 0 || q === p ? null : parts[q];
        if (other === null || other === undefined) continue;
        const merged = mergeAcross(xs, ys, part, other, a, b, flat);
        if (merged === null) continue;
        setOwner(owner, count, part, -1);
        setOwner(owner, count, other, -1);
        parts[p] = merged;
        parts[q] = null;
        setOwner(owner, count, merged, p);
        isChanged = true;
        break;
      }
    }
  }
  return parts.filter((part): part is number[] => part !== null);
}

/**
 * The union of part 1 (holding edge a -> b) and part 2 (holding b -> a), counter-clockwise, or
 * null when it would be concave or have too many corners.
 */
function mergeAcross(
  xs: Float64Array,
  ys: Float64Array,
  part1: readonly number[],
  part2: readonly number[],
  a: number,
  b: number,
  flat: number,
): number[] | null {
  // Walk part 1 from b round to a, then part 2 from a round to just before b.
  const merged: number[] = [];
  const start1 = part1.indexOf(b);
  for (let k = 0; k < part1.length; k++) merged.push(part1[(start1 + k) % part1.length]!);
  const start2 = part2.indexOf(a);
  for (let k = 1; k < part2.length - 1; k++) merged.push(part2[(start2 + k) % part2.length]!);
  // Check the turn at a and at b, dropping them when exactly straight.
  for (const junction of [a, b]) {
    const i = merged.indexOf(junction);
    const before = merged[i === 0 ? merged.length - 1 : i - 1]!;
    const after = merged[i === merged.length - 1 ? 0 : i + 1]!;
    const area = cross(xs, ys, before, junction, after);
    if (area < -flat) return null;
    if (area <= flat) merged.splice(i, 1);
  }
  return merged.length <= MAX_POLYGON_VERTICES ? merged : null;
}

function setOwner(owner: Int32Array, count: number, part: readonly number[], p: number): void {
  for (let e = 0; e < part.length; e++) {
    owner[part[e]! * count + part[e + 1 === part.length ? 0 : e + 1]!] = p;
  }
}

/** (b - a) x (c - b): twice the signed area of triangle a, b, c. */
function cross(xs: Float64Array, ys: Float64Array, a: number, b: number, c: number): number {
  return (xs[b]! - xs[a]!) * (ys[c]! - ys[b]!) - (ys[b]! - ys[a]!) * (xs[c]! - xs[b]!);
}

/** True when point p lies inside or on the counter-clockwise triangle a, b, c. */
function isInTriangle(
  xs: Float64Array,
  ys: Float64Array,
  a: number,
  b: number,
  c: number,
  p: number,
  flat: number,
): boolean {
  return (
    cross(xs, ys, a, b, p) >= -flat &&
    cross(xs, ys, b, c, p) >= -flat &&
    cross(xs, ys, c, a, p) >= -flat
  );
}

/** Largest coordinate extent of the outline (m), the scale of its round-off. */
function outlineScale(outline: Outline): number {
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (let i = 0; i < outline.count; i++) {
    minX = Math.min(minX, outline.xs[i]!);
    maxX = Math.max(maxX, outline.xs[i]!);
    minY = Math.min(minY, outline.ys[i]!);
    maxY = Math.max(maxY, outline.ys[i]!);
  }
  return Math.max(maxX - minX, maxY - minY);
}
