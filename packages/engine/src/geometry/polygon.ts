import { MAX_POLYGON_VERTICES } from '../core/constants.ts';
import { PhysicalError } from '../core/errors.ts';
import {
  MAX_SIZE,
  requireAngle,
  requireCoordinate,
  requireNonNegative,
  requireSize,
  requireVector,
} from '../core/validate.ts';
import type { Vec2Like } from '../math/vec2.ts';
import { hypot } from '../math/hypot.ts';
import { cosSin } from '../math/trigonometry.ts';
import {
  distance,
  findConcaveVertex,
  MIN_POLYGON_VERTICES,
  orientation,
  prepareOutline,
} from './polygon-outline.ts';

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
