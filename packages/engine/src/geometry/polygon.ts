import { LINEAR_SLOP, MAX_POLYGON_VERTICES } from '../core/constants.ts';
import { PhysicalError } from '../core/errors.ts';
import {
  describeValue,
  MAX_SIZE,
  requireAngle,
  requireCoordinate,
  requireNonNegative,
  requireSize,
  requireVector,
} from '../core/validate.ts';
import type { Transform } from '../math/transform.ts';
import type { Vec2Like } from '../math/vec2.ts';
import type { AABB } from './aabb.ts';
import type { MassData } from './mass-data.ts';
import type { RayHit, RayInput } from './ray.ts';
import { hypot } from '../math/hypot.ts';
import { atan2, cosSin } from '../math/trigonometry.ts';

// Where cosSin writes makeBox's rotation.
const rotation = new Float64Array(2);

/**
 * A convex polygon in its body's local frame, vertices in counter-clockwise order in the
 * mathematical sense (positive signed area in x, y; on a y-down screen that looks clockwise).
 * `radius` > 0 rounds it (a rounded box); 0 is a sharp polygon.
 */
export interface Polygon {
  readonly kind: 'polygon';
  /** Number of vertices, 3..MAX_POLYGON_VERTICES. */
  count: number;
  /** x0, y0, x1, y1, ... (m), length 2 * MAX_POLYGON_VERTICES; only the first 2 * count are used. */
  readonly vertices: Float64Array;
  /** Outward unit normal of edge i (from vertex i to vertex i + 1), same layout as vertices. */
  readonly normals: Float64Array;
  /** Centroid of the area (m). */
  centroidX: number;
  centroidY: number;
  /** Rounding radius (m), >= 0. */
  radius: number;
}

const SLAB_POLYGONS = 256;
let slab = new ArrayBuffer(0);
let slabUsed = 0;

/** Vertices and normals of one polygon, cut from a shared slab (see createEmptyPolygon). */
function polygonStorage(): Float64Array {
  const bytes = 4 * MAX_POLYGON_VERTICES * 8;
  if (slabUsed + bytes > slab.byteLength) {
    slab = new ArrayBuffer(SLAB_POLYGONS * bytes);
    slabUsed = 0;
  }
  const storage = new Float64Array(slab, slabUsed, 4 * MAX_POLYGON_VERTICES);
  slabUsed += bytes;
  return storage;
}

/** A polygon with no vertices and zeroed storage, to be filled by `makePolygon` or `makeBox`. */
export function createEmptyPolygon(): Polygon {
  const storage = polygonStorage();
  return {
    kind: 'polygon',
    count: 0,
    vertices: storage.subarray(0, 2 * MAX_POLYGON_VERTICES),
    normals: storage.subarray(2 * MAX_POLYGON_VERTICES),
    centroidX: 0,
    centroidY: 0,
    radius: 0,
  };
}

/** Points closer than this (m) are one point: below what the solver can resolve anyway. */
const DUPLICATE_TOLERANCE = 0.5 * LINEAR_SLOP;

/**
 * A vertex closer than this (m) to the line through its neighbours is treated as straight and
 * dropped, whichever way it bends: it would give an edge too short for a stable normal, and
 * rounding in user data must not turn a convex outline into a "concave" one.
 */
const STRAIGHT_TOLERANCE = 0.5 * LINEAR_SLOP;

const MIN_POLYGON_VERTICES = 3;

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

/**
 * Validates a point list and builds a convex polygon from it (body-local, m). Accepts clockwise or
 * counter-clockwise input and stores it counter-clockwise; merges points closer than
 * 0.5 * LINEAR_SLOP and drops vertices that are straight within that tolerance. It never computes a
 * hull: a concave or self-intersecting outline is an error, so the shape is always what was drawn
 * (the polygon shape splits concave outlines into convex parts: see polygon-decomposition.ts).
 * `radius` (m) >= 0 rounds the corners. Fills `out` when given (reusing its storage).
 * @throws PhysicalError with field `${field}.vertices`, `${field}.vertices[i]`,
 *   `${field}.vertices[i].x`/`.y` or `${field}.radius`.
 */
export function makePolygon(
  points: ArrayLike<Vec2Like>,
  radius: number,
  field: string,
  out?: Polygon,
): Polygon {
  const verticesField = `${field}.vertices`;
  const outline = prepareOutline(points, field);
  requireNonNegative(`${field}.radius`, radius, MAX_SIZE);
  const { xs, ys, count } = outline;
  const concave = findConcaveVertex(outline);
  if (concave >= 0) {
    throw new PhysicalError(
      verticesField,
      `is concave at (${xs[concave]}, ${ys[concave]}), but one convex part must be convex. ` +
        'A polygon shape or body splits concave outlines into convex parts by itself.',
    );
  }

  if (count > MAX_POLYGON_VERTICES) {
    throw new PhysicalError(
      verticesField,
      `has ${count} corners but a polygon may have at most ${MAX_POLYGON_VERTICES}. ` +
        'Use fewer corners, or split the shape into several polygons on one body.',
    );
  }
  return makePolygonFromOutline(xs, ys, count, radius, out);
}

/**
 * Validates and builds one convex part exactly as given (body-local, m), without cleaning: 3 to
 * MAX_POLYGON_VERTICES finite points, counter-clockwise, every vertex turning left and every
 * vertex on the inner side of every edge (so convex and simple), no zero-length edge. This is
 * how a snapshot restores the parts a concave outline was split into: a part may hold a vertex
 * that outline cleaning would call straight (its neighbours came from the split), and it must
 * come back as it was saved.
 * @throws PhysicalError with field `${field}.vertices` or `${field}.radius`.
 */
export function makeConvexPart(
  points: ArrayLike<Vec2Like>,
  radius: number,
  field: string,
): Polygon {
  const verticesField = `${field}.vertices`;
  const count = points.length;
  if (count < MIN_POLYGON_VERTICES || count > MAX_POLYGON_VERTICES) {
    throw new PhysicalError(
      verticesField,
      `must hold ${MIN_POLYGON_VERTICES} to ${MAX_POLYGON_VERTICES} points, got ${count}.`,
    );
  }
  const xs = new Float64Array(count);
  const ys = new Float64Array(count);
  for (let i = 0; i < count; i++) {
    requireVector(`${verticesField}[${i}]`, points[i]!);
    xs[i] = points[i]!.x;
    ys[i] = points[i]!.y;
  }
  requireNonNegative(`${field}.radius`, radius, MAX_SIZE);
  for (let i = 0; i < count; i++) {
    const next = i === count - 1 ? 0 : i + 1;
    if (!(distance(xs[i]!, ys[i]!, xs[next]!, ys[next]!) > 0)) {
      throw new PhysicalError(verticesField, `edge ${i} has no length.`);
    }
    for (let j = 0; j < count; j++) {
      if (j === i || j === next) continue;
      if (!(orientation(xs[i]!, ys[i]!, xs[next]!, ys[next]!, xs[j]!, ys[j]!) > 0)) {
        throw new PhysicalError(
          verticesField,
          `is not a convex counter-clockwise part: point ${j} is not inside edge ${i}.`,
        );
      }
    }
  }
  return makePolygonFromOutline(xs, ys, count, radius);
}

/**
 * Builds a polygon from `count` counter-clockwise, convex, cleaned points (no validation: callers
 * have done it). Fills `out` when given.
 */
export function makePolygonFromOutline(
  xs: ArrayLike<number>,
  ys: ArrayLike<number>,
  count: number,
  radius: number,
  out?: Polygon,
): Polygon {
  const polygon = out ?? createEmptyPolygon();
  polygon.count = count;
  polygon.radius = radius;
  for (let i = 0; i < count; i++) {
    polygon.vertices[2 * i] = xs[i]!;
    polygon.vertices[2 * i + 1] = ys[i]!;
  }
  finishPolygon(polygon);
  return polygon;
}

/**
 * Validates and builds a rectangle with half extents (m) > 0, centred at (centerX, centerY)
 * (body-local, m) and rotated by `angle` (rad), with rounding `radius` (m) >= 0.
 * Fills `out` when given.
 * @throws PhysicalError with field `${field}.halfWidth`, `.halfHeight`, `.centerX`, `.centerY`,
 *   `.angle` or `.radius`.
 */
export function makeBox(
  halfWidth: number,
  halfHeight: number,
  centerX: number,
  centerY: number,
  angle: number,
  radius: number,
  field: string,
  out?: Polygon,
): Polygon {
  requireSize(`${field}.halfWidth`, halfWidth);
  requireSize(`${field}.halfHeight`, halfHeight);
  requireCoordinate(`${field}.centerX`, centerX);
  requireCoordinate(`${field}.centerY`, centerY);
  requireAngle(`${field}.angle`, angle);
  requireNonNegative(`${field}.radius`, radius, MAX_SIZE);
  const polygon = out ?? createEmptyPolygon();
  cosSin(angle, rotation);
  const c = rotation[0]!;
  const s = rotation[1]!;
  polygon.count = 4;
  polygon.radius = radius;
  const vertices = polygon.vertices;
  const normals = polygon.normals;
  for (let i = 0; i < 4; i++) {
    // Corners (-w,-h), (w,-h), (w,h), (-w,h): counter-clockwise; edge i has normal (0,-1), (1,0), ...
    const lx = i === 1 || i === 2 ? halfWidth : -halfWidth;
    const ly = i >= 2 ? halfHeight : -halfHeight;
    vertices[2 * i] = c * lx - s * ly + centerX;
    vertices[2 * i + 1] = s * lx + c * ly + centerY;
    const nx = i === 1 ? 1 : i === 3 ? -1 : 0;
    const ny = i === 0 ? -1 : i === 2 ? 1 : 0;
    normals[2 * i] = c * nx - s * ny;
    normals[2 * i + 1] = s * nx + c * ny;
  }
  polygon.centroidX = centerX;
  polygon.centroidY = centerY;
  return polygon;
}

/**
 * Mass properties of the polygon at `density` (kg/m^2): mass (kg), centre of mass (body-local, m)
 * and rotational inertia about the centre of mass (kg m^2). Writes and returns `out`.
 *
 * Sharp core: a fan of triangles from a reference point inside the polygon (its first vertex),
 * each contributing area |e1 x e2| / 2, first moment area (e1 + e2) / 3 and polar second moment
 * (|e1 x e2| / 12)(e1.e1 + e1.e2 + e2.e2); working relative to a vertex keeps precision for shapes
 * far from the body origin (the formula Box2D's b2ComputePolygonMass uses).
 *
 * Rounded (radius r > 0), exact rather than Box2D's pushed-out-edges approximation: the shape is
 * the Minkowski sum of the core with a disc, which splits without overlap into the core, one
 * r-thick rectangle on each edge and one circular sector at each vertex (their angles sum to 2 pi),
 * so area = A + P r + pi r^2. For the sector at vertex v between edge normals n0 and n1 (angles
 * alpha, beta), with q measured from v:
 *   area = (beta - alpha) r^2 / 2,   integral of q = (r^3 / 3)(n1.y - n0.y, n0.x - n1.x),
 *   integral of |q|^2 = (beta - alpha) r^4 / 4,
 * and moving to another origin o uses integral |v - o + q|^2 = J_v + 2 (v - o).Q_v + area |v - o|^2.
 * An edge rectangle of length L has area L r, centroid at the edge midpoint + (r/2) n and polar
 * moment about its centroid L r (L^2 + r^2) / 12.
 */
export function computePolygonMass(polygon: Polygon, density: number, out: MassData): MassData {
  const count = polygon.count;
  const vertices = polygon.vertices;
  const normals = polygon.normals;
  const r = polygon.radius;
  // All moments relative to vertex 0 (ox, oy).
  const ox = vertices[0]!;
  const oy = vertices[1]!;
  let area = 0;
  let firstX = 0;
  let firstY = 0;
  let second = 0;
  for (let i = 1; i < count - 1; i++) {
    const e1x = vertices[2 * i]! - ox;
    const e1y = vertices[2 * i + 1]! - oy;
    const e2x = vertices[2 * i + 2]! - ox;
    const e2y = vertices[2 * i + 3]! - oy;
    const cross = e1x * e2y - e1y * e2x;
    const triangleArea = 0.5 * cross;
    area += triangleArea;
    firstX += (triangleArea * (e1x + e2x)) / 3;
    firstY += (triangleArea * (e1y + e2y)) / 3;
    second +=
      (cross / 12) * (e1x * e1x + e1x * e2x + e2x * e2x + e1y * e1y + e1y * e2y + e2y * e2y);
  }
  if (r > 0) {
    for (let i = 0; i < count; i++) {
      const next = i === count - 1 ? 0 : i + 1;
      const previous = i === 0 ? count - 1 : i - 1;
      const vx = vertices[2 * i]! - ox;
      const vy = vertices[2 * i + 1]! - oy;
      const wx = vertices[2 * next]! - ox;
      const wy = vertices[2 * next + 1]! - oy;
      const nx = normals[2 * i]!;
      const ny = normals[2 * i + 1]!;
      // Edge rectangle.
      const length = hypot(wx - vx, wy - vy);
      const rectangleArea = length * r;
      const rectangleX = 0.5 * (vx + wx) + 0.5 * r * nx;
      const rectangleY = 0.5 * (vy + wy) + 0.5 * r * ny;
      area += rectangleArea;
      firstX += rectangleArea * rectangleX;
      firstY += rectangleArea * rectangleY;
      second +=
        (rectangleArea * (length * length + r * r)) / 12 +
        rectangleArea * (rectangleX * rectangleX + rectangleY * rectangleY);
      // Vertex sector between the previous edge's normal and this edge's normal.
      const n0x = normals[2 * previous]!;
      const n0y = normals[2 * previous + 1]!;
      const sweep = atan2(n0x * ny - n0y * nx, n0x * nx + n0y * ny);
      const sectorArea = 0.5 * sweep * r * r;
      const sectorFirstX = ((r * r * r) / 3) * (ny - n0y);
      const sectorFirstY = ((r * r * r) / 3) * (n0x - nx);
      area += sectorArea;
      firstX += sectorFirstX + sectorArea * vx;
      firstY += sectorFirstY + sectorArea * vy;
      second +=
        0.25 * sweep * r * r * r * r +
        2 * (vx * sectorFirstX + vy * sectorFirstY) +
        sectorArea * (vx * vx + vy * vy);
    }
  }
  const mass = density * area;
  const cx = firstX / area;
  const cy = firstY / area;
  out.mass = mass;
  out.centerX = ox + cx;
  out.centerY = oy + cy;
  // Parallel axis theorem, from the reference vertex to the centre of mass.
  out.rotationalInertia = density * (second - area * (cx * cx + cy * cy));
  return out;
}

/** World-frame bounding box (m) of the polygon placed by `xf`, including its radius. */
export function computePolygonAABB(polygon: Polygon, xf: Transform, out: AABB): AABB {
  const vertices = polygon.vertices;
  const c = xf.c;
  const s = xf.s;
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (let i = 0; i < polygon.count; i++) {
    const lx = vertices[2 * i]!;
    const ly = vertices[2 * i + 1]!;
    const x = c * lx - s * ly + xf.x;
    const y = s * lx + c * ly + xf.y;
    if (x < minX) minX = x;
    if (y < minY) minY = y;
    if (x > maxX) maxX = x;
    if (y > maxY) maxY = y;
  }
  const r = polygon.radius;
  out.minX = minX - r;
  out.minY = minY - r;
  out.maxX = maxX + r;
  out.maxY = maxY + r;
  return out;
}

/**
 * True when the world point (px, py) (m) lies inside or on the polygon placed by `xf`, rounding
 * included: for radius r > 0 a point outside the core counts when its distance to the core is <= r.
 */
export function polygonContainsPoint(
  polygon: Polygon,
  xf: Transform,
  px: number,
  py: number,
): boolean {
  const dx = px - xf.x;
  const dy = py - xf.y;
  const lx = xf.c * dx + xf.s * dy;
  const ly = -xf.s * dx + xf.c * dy;
  const count = polygon.count;
  const vertices = polygon.vertices;
  const normals = polygon.normals;
  let isInsideCore = true;
  for (let i = 0; i < count; i++) {
    const separation =
      normals[2 * i]! * (lx - vertices[2 * i]!) + normals[2 * i + 1]! * (ly - vertices[2 * i + 1]!);
    if (separation > 0) {
      isInsideCore = false;
      break;
    }
  }
  if (isInsideCore) {
    return true;
  }
  const r = polygon.radius;
  if (r === 0) {
    return false;
  }
  // Outside a convex core, the distance to it is the distance to the nearest edge.
  let best = Infinity;
  for (let i = 0; i < count; i++) {
    const next = i === count - 1 ? 0 : i + 1;
    const d = pointSegmentDistanceSquared(
      lx,
      ly,
      vertices[2 * i]!,
      vertices[2 * i + 1]!,
      vertices[2 * next]!,
      vertices[2 * next + 1]!,
    );
    if (d < best) best = d;
  }
  return best <= r * r;
}

/**
 * Casts a world-frame ray against the polygon placed by `xf`. Returns false on a miss and when
 * the ray starts inside; on a hit writes the fraction, world point (m) and outward unit normal.
 *
 * Sharp polygons: Cyrus-Beck clipping of the ray against the edge half-planes in the polygon's
 * frame (Ericson, Real-Time Collision Detection, 5.3.8). Rounded polygons (radius r > 0), exact:
 * the boundary of core + disc lies on the union of the edges pushed out by r n and the circles of
 * radius r around the vertices, all of which lie inside the shape, so the first entry into the
 * shape is the earliest entering hit among those pieces.
 */
export function rayCastPolygon(
  polygon: Polygon,
  xf: Transform,
  input: RayInput,
  out: RayHit,
): boolean {
  const c = xf.c;
  const s = xf.s;
  // Ray in the polygon's frame: p + t d, t in [0, maxFraction].
  const ox = input.originX - xf.x;
  const oy = input.originY - xf.y;
  const px = c * ox + s * oy;
  const py = -s * ox + c * oy;
  const dx = c * input.translationX + s * input.translationY;
  const dy = -s * input.translationX + c * input.translationY;
  const count = polygon.count;
  const vertices = polygon.vertices;
  const normals = polygon.normals;
  const r = polygon.radius;
  let hitFraction: number;
  let nx = 0;
  let ny = 0;

  if (r === 0) {
    let lower = 0;
    let upper = input.maxFraction;
    let index = -1;
    for (let i = 0; i < count; i++) {
      const ex = normals[2 * i]!;
      const ey = normals[2 * i + 1]!;
      // Inside half-plane i: e.(p + t d - v) <= 0, i.e. t * denominator <= numerator.
      const numerator = ex * (vertices[2 * i]! - px) + ey * (vertices[2 * i + 1]! - py);
      const denominator = ex * dx + ey * dy;
      if (denominator === 0) {
        if (numerator < 0) {
          return false;
        }
      } else if (denominator < 0 && numerator < lower * denominator) {
        lower = numerator / denominator;
        index = i;
      } else if (denominator > 0 && numerator < upper * denominator) {
        upper = numerator / denominator;
      }
      if (upper < lower) {
        return false;
      }
    }
    if (index < 0) {
      return false;
    }
    hitFraction = lower;
    nx = normals[2 * index]!;
    ny = normals[2 * index + 1]!;
  } else {
    if (polygonContainsPoint(polygon, xf, input.originX, input.originY)) {
      return false;
    }
    const dd = dx * dx + dy * dy;
    if (dd === 0) {
      return false;
    }
    let best = Infinity;
    for (let i = 0; i < count; i++) {
      const next = i === count - 1 ? 0 : i + 1;
      const vx = vertices[2 * i]!;
      const vy = vertices[2 * i + 1]!;
      const ex = normals[2 * i]!;
      const ey = normals[2 * i + 1]!;
      // Pushed-out edge, entered only when moving against its normal.
      const denominator = ex * dx + ey * dy;
      if (denominator < 0) {
        const t = (ex * (vx + r * ex - px) + ey * (vy + r * ey - py)) / denominator;
        if (t >= 0 && t < best) {
          const wx = vertices[2 * next]!;
          const wy = vertices[2 * next + 1]!;
          const qx = px + t * dx - vx;
          const qy = py + t * dy - vy;
          const along = qx * (wx - vx) + qy * (wy - vy);
          if (along >= 0 && along <= (wx - vx) * (wx - vx) + (wy - vy) * (wy - vy)) {
            best = t;
            nx = ex;
            ny = ey;
          }
        }
      }
      // Vertex circle: |p - v + t d|^2 = r^2, smaller root.
      const fx = px - vx;
      const fy = py - vy;
      const b = fx * dx + fy * dy;
      const discriminant = b * b - dd * (fx * fx + fy * fy - r * r);
      if (discriminant >= 0 && b < 0) {
        const t = (-b - Math.sqrt(discriminant)) / dd;
        if (t >= 0 && t < best) {
          best = t;
          nx = (fx + t * dx) / r;
          ny = (fy + t * dy) / r;
        }
      }
    }
    if (best > input.maxFraction) {
      return false;
    }
    hitFraction = best;
  }

  const hx = px + hitFraction * dx;
  const hy = py + hitFraction * dy;
  out.fraction = hitFraction;
  out.x = c * hx - s * hy + xf.x;
  out.y = s * hx + c * hy + xf.y;
  out.normalX = c * nx - s * ny;
  out.normalY = s * nx + c * ny;
  return true;
}

/** Fills normals and centroid from the counter-clockwise vertices already stored in `polygon`. */
function finishPolygon(polygon: Polygon): void {
  const count = polygon.count;
  const vertices = polygon.vertices;
  const normals = polygon.normals;
  for (let i = 0; i < count; i++) {
    const next = i === count - 1 ? 0 : i + 1;
    const ex = vertices[2 * next]! - vertices[2 * i]!;
    const ey = vertices[2 * next + 1]! - vertices[2 * i + 1]!;
    const length = hypot(ex, ey);
    // Counter-clockwise winding: the outward normal is the edge turned clockwise.
    normals[2 * i] = ey / length;
    normals[2 * i + 1] = -ex / length;
  }
  // Area centroid by a triangle fan from vertex 0 (relative coordinates for precision).
  const ox = vertices[0]!;
  const oy = vertices[1]!;
  let area = 0;
  let cx = 0;
  let cy = 0;
  for (let i = 1; i < count - 1; i++) {
    const e1x = vertices[2 * i]! - ox;
    const e1y = vertices[2 * i + 1]! - oy;
    const e2x = vertices[2 * i + 2]! - ox;
    const e2y = vertices[2 * i + 3]! - oy;
    const triangleArea = 0.5 * (e1x * e2y - e1y * e2x);
    area += triangleArea;
    cx += (triangleArea * (e1x + e2x)) / 3;
    cy += (triangleArea * (e1y + e2y)) / 3;
  }
  polygon.centroidX = ox + cx / area;
  polygon.centroidY = oy + cy / area;
}

function distance(ax: number, ay: number, bx: number, by: number): number {
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
function orientation(
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

function pointSegmentDistanceSquared(
  px: number,
  py: number,
  ax: number,
  ay: number,
  bx: number,
  by: number,
): number {
  const ex = bx - ax;
  const ey = by - ay;
  const lengthSquared = ex * ex + ey * ey;
  let t = ((px - ax) * ex + (py - ay) * ey) / lengthSquared;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const dx = px - (ax + t * ex);
  const dy = py - (ay + t * ey);
  return dx * dx + dy * dy;
}
