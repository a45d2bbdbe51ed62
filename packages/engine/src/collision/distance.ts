import { MAX_POLYGON_VERTICES } from '../core/constants.ts';
import type { Capsule } from '../geometry/capsule.ts';
import type { Circle } from '../geometry/circle.ts';
import type { Polygon } from '../geometry/polygon.ts';
import type { Segment } from '../geometry/segment.ts';
import type { Transform } from '../math/transform.ts';

// Distance between convex shapes by the Gilbert-Johnson-Keerthi algorithm (Gilbert, Johnson and
// Keerthi 1988, "A fast procedure for computing the distance between complex objects in
// three-dimensional space"), with the simplex solved by Voronoi regions and barycentric
// coordinates as in Erin Catto, "Computing Distance" (GDC 2010).
//
// Each shape is a convex core (a point, a segment or a polygon) swollen by a radius. GJK works on
// the cores: it searches the Minkowski difference B - A for the point closest to the origin with
// a simplex of at most three support points w = b - a. The radii are applied at the end, which
// keeps the core iteration exact for polytopes (it ends when a support point repeats).

/** Most GJK iterations; a polytope pair of up to 8 + 8 vertices needs far fewer. */
const MAX_ITERATIONS = 20;

/**
 * A convex shape for distance queries: `count` vertices of the core (x0, y0, x1, y1, ... in the
 * shape's body frame, m) and a radius (m) around it. A circle is one vertex plus its radius, a
 * segment two vertices, a polygon its vertices plus its rounding radius.
 */
export class DistanceProxy {
  /** Core vertices x0, y0, x1, y1, ... in the body frame (m); only the first 2 * count are used. */
  readonly vertices: Float64Array = new Float64Array(2 * MAX_POLYGON_VERTICES);
  /** Number of core vertices, 1..MAX_POLYGON_VERTICES. */
  count = 0;
  /** Radius around the core (m), >= 0. */
  radius = -0;
}

/** Result of shapeDistance. Points and normal are in the world frame. */
export class DistanceOutput {
  /** Distance between the shapes' surfaces, radii included (m); 0 when they overlap. */
  distance = -0;
  /** Closest point on shape A's surface (m); when overlapping, a point in the overlap. */
  pointAX = -0;
  pointAY = -0;
  /** Closest point on shape B's surface (m); equals point A when overlapping. */
  pointBX = -0;
  pointBY = -0;
  /** Unit vector from A's core towards B's core; 0, 0 when the cores overlap. */
  normalX = -0;
  normalY = -0;
  /** Number of GJK iterations used. */
  iterations = 0;
}

/** Fills `proxy` from a polygon: its vertices and rounding radius. Returns `proxy`. */
export function setProxyFromPolygon(proxy: DistanceProxy, polygon: Polygon): DistanceProxy {
  const n = 2 * polygon.count;
  for (let i = 0; i < n; i++) {
    proxy.vertices[i] = polygon.vertices[i]!;
  }
  proxy.count = polygon.count;
  proxy.radius = polygon.radius;
  return proxy;
}

/** Fills `proxy` from a circle: one vertex at the centre and the circle's radius. Returns `proxy`. */
export function setProxyFromCircle(proxy: DistanceProxy, circle: Circle): DistanceProxy {
  proxy.vertices[0] = circle.centerX;
  proxy.vertices[1] = circle.centerY;
  proxy.count = 1;
  proxy.radius = circle.radius;
  return proxy;
}

/** Fills `proxy` from a capsule: its two centres and its radius. Returns `proxy`. */
export function setProxyFromCapsule(proxy: DistanceProxy, capsule: Capsule): DistanceProxy {
  proxy.vertices[0] = capsule.x1;
  proxy.vertices[1] = capsule.y1;
  proxy.vertices[2] = capsule.x2;
  proxy.vertices[3] = capsule.y2;
  proxy.count = 2;
  proxy.radius = capsule.radius;
  return proxy;
}

/** Fills `proxy` from a segment: its two end points, radius 0. Returns `proxy`. */
export function setProxyFromSegment(proxy: DistanceProxy, segment: Segment): DistanceProxy {
  proxy.vertices[0] = segment.x1;
  proxy.vertices[1] = segment.y1;
  proxy.vertices[2] = segment.x2;
  proxy.vertices[3] = segment.y2;
  proxy.count = 2;
  proxy.radius = 0;
  return proxy;
}

// Simplex storage, shared by all calls: JavaScript runs one call at a time per realm and
// nothing below calls back into user code, so a module-level scratch is safe and keeps the
// query free of allocation. Per vertex v (stride 7): wA (x, y), wB (x, y), w = wB - wA (x, y),
// barycentric weight a; vertex indices on A and B in `simplexIndices` (stride 2).
const STRIDE = 7;
const simplex = new Float64Array(3 * STRIDE);
const simplexIndices = new Int32Array(6);
const savedIndexA = new Int32Array(3);
const savedIndexB = new Int32Array(3);
let simplexCount = 0;

/**
 * Core result of the last gjkCores call, world frame: witness points on the cores, their
 * distance (m), and the iteration count.
 */
export const coreResult = {
  pointAX: 0,
  pointAY: 0,
  pointBX: 0,
  pointBY: 0,
  distance: 0,
  iterations: 0,
};

function copyVertex(to: number, from: number): void {
  const t = to * STRIDE;
  const f = from * STRIDE;
  for (let k = 0; k < STRIDE; k++) {
    simplex[t + k] = simplex[f + k]!;
  }
  simplexIndices[2 * to] = simplexIndices[2 * from]!;
  simplexIndices[2 * to + 1] = simplexIndices[2 * from + 1]!;
}

/** Index of the vertex of `proxy` furthest along the body-frame direction (dx, dy). */
function support(proxy: DistanceProxy, dx: number, dy: number): number {
  const v = proxy.vertices;
  let best = 0;
  let bestValue = v[0]! * dx + v[1]! * dy;
  for (let i = 1; i < proxy.count; i++) {
    const value = v[2 * i]! * dx + v[2 * i + 1]! * dy;
    if (value > bestValue) {
      best = i;
      bestValue = value;
    }
  }
  return best;
}

/** Writes support vertex `slot` from vertex indexA of A and indexB of B, placed by xfA, xfB. */
function setVertex(
  slot: number,
  proxyA: DistanceProxy,
  xfA: Transform,
  indexA: number,
  proxyB: DistanceProxy,
  xfB: Transform,
  indexB: number,
): void {
  const va = proxyA.vertices;
  const vb = proxyB.vertices;
  const ax = va[2 * indexA]!;
  const ay = va[2 * indexA + 1]!;
  const bx = vb[2 * indexB]!;
  const by = vb[2 * indexB + 1]!;
  const wAx = xfA.c * ax - xfA.s * ay + xfA.x;
  const wAy = xfA.s * ax + xfA.c * ay + xfA.y;
  const wBx = xfB.c * bx - xfB.s * by + xfB.x;
  const wBy = xfB.s * bx + xfB.c * by + xfB.y;
  const o = slot * STRIDE;
  simplex[o] = wAx;
  simplex[o + 1] = wAy;
  simplex[o + 2] = wBx;
  simplex[o + 3] = wBy;
  simplex[o + 4] = wBx - wAx;
  simplex[o + 5] = wBy - wAy;
  simplex[o + 6] = 1;
  simplexIndices[2 * slot] = indexA;
  simplexIndices[2 * slot + 1] = indexB;
}

/**
 * Reduces a 2-simplex {w1, w2} to the feature whose Voronoi region holds the origin and sets
 * the barycentric weights of the closest point (Catto 2010):
 *   region w1 when -w1 . e12 <= 0, region w2 when w2 . e12 <= 0, otherwise the edge with
 *   a1 = w2 . e12 / |e12|^2 and a2 = -w1 . e12 / |e12|^2, where e12 = w2 - w1.
 */
function solve2(): void {
  const w1x = simplex[4]!;
  const w1y = simplex[5]!;
  const w2x = simplex[STRIDE + 4]!;
  const w2y = simplex[STRIDE + 5]!;
  const ex = w2x - w1x;
  const ey = w2y - w1y;
  const d12n2 = -(w1x * ex + w1y * ey);
  if (d12n2 <= 0) {
    simplex[6] = 1;
    simplexCount = 1;
    return;
  }
  const d12n1 = w2x * ex + w2y * ey;
  if (d12n1 <= 0) {
    copyVertex(0, 1);
    simplex[6] = 1;
    simplexCount = 1;
    return;
  }
  const inv = 1 / (d12n1 + d12n2);
  simplex[6] = d12n1 * inv;
  simplex[STRIDE + 6] = d12n2 * inv;
  simplexCount = 2;
}

/**
 * Reduces a 3-simplex {w1, w2, w3} to the feature whose Voronoi region holds the origin
 * (Catto 2010). Edge weights are the unnormalised barycentric pairs d_ij (as in solve2);
 * triangle weights are the signed areas d123_k = n123 * cross(w_i, w_j) of the sub-triangles
 * opposite each vertex, with n123 = cross(e12, e13) fixing the orientation. All three triangle
 * weights positive means the origin is inside: the cores overlap.
 */
function solve3(): void {
  const w1x = simplex[4]!;
  const w1y = simplex[5]!;
  const w2x = simplex[STRIDE + 4]!;
  const w2y = simplex[STRIDE + 5]!;
  const w3x = simplex[2 * STRIDE + 4]!;
  const w3y = simplex[2 * STRIDE + 5]!;

  const e12x = w2x - w1x;
  const e12y = w2y - w1y;
  const d12n1 = w2x * e12x + w2y * e12y;
  const d12n2 = -(w1x * e12x + w1y * e12y);

  const e13x = w3x - w1x;
  const e13y = w3y - w1y;
  const d13n1 = w3x * e13x + w3y * e13y;
  const d13n2 = -(w1x * e13x + w1y * e13y);

  const e23x = w3x - w2x;
  const e23y = w3y - w2y;
  const d23n1 = w3x * e23x + w3y * e23y;
  const d23n2 = -(w2x * e23x + w2y * e23y);

  const n123 = e12x * e13y - e12y * e13x;
  const d123n1 = n123 * (w2x * w3y - w2y * w3x);
  const d123n2 = n123 * (w3x * w1y - w3y * w1x);
  const d123n3 = n123 * (w1x * w2y - w1y * w2x);

  if (d12n2 <= 0 && d13n2 <= 0) {
    simplex[6] = 1;
    simplexCount = 1;
    return;
  }
  if (d12n1 > 0 && d12n2 > 0 && d123n3 <= 0) {
    const inv = 1 / (d12n1 + d12n2);
    simplex[6] = d12n1 * inv;
    simplex[STRIDE + 6] = d12n2 * inv;
    simplexCount = 2;
    return;
  }
  if (d13n1 > 0 && d13n2 > 0 && d123n2 <= 0) {
    const inv = 1 / (d13n1 + d13n2);
    copyVertex(1, 2);
    simplex[6] = d13n1 * inv;
    simplex[STRIDE + 6] = d13n2 * inv;
    simplexCount = 2;
    return;
  }
  if (d12n1 <= 0 && d23n2 <= 0) {
    copyVertex(0, 1);
    simplex[6] = 1;
    simplexCount = 1;
    return;
  }
  if (d13n1 <= 0 && d23n1 <= 0) {
    copyVertex(0, 2);
    simplex[6] = 1;
    simplexCount = 1;
    return;
  }
  if (d23n1 > 0 && d23n2 > 0 && d123n1 <= 0) {
    const inv = 1 / (d23n1 + d23n2);
    copyVertex(0, 2);
    simplex[6] = d23n2 * inv;
    simplex[STRIDE + 6] = d23n1 * inv;
    simplexCount = 2;
    return;
  }
  const inv = 1 / (d123n1 + d123n2 + d123n3);
  simplex[6] = d123n1 * inv;
  simplex[STRIDE + 6] = d123n2 * inv;
  simplex[2 * STRIDE + 6] = d123n3 * inv;
  simplexCount = 3;
}

/**
 * Runs GJK on the cores of two proxies placed by xfA and xfB and writes the witness points,
 * core distance (m) and iteration count to `coreResult`. Returns the core distance; 0 when the
 * cores overlap. Internal to the collision layer (time of impact uses it directly).
 */
export function gjkCores(
  proxyA: DistanceProxy,
  xfA: Transform,
  proxyB: DistanceProxy,
  xfB: Transform,
): number {
  setVertex(0, proxyA, xfA, 0, proxyB, xfB, 0);
  simplexCount = 1;
  let iteration = 0;
  while (iteration < MAX_ITERATIONS) {
    const saveCount = simplexCount;
    for (let i = 0; i < saveCount; i++) {
      savedIndexA[i] = simplexIndices[2 * i]!;
      savedIndexB[i] = simplexIndices[2 * i + 1]!;
    }
    if (simplexCount === 2) {
      solve2();
    } else if (simplexCount === 3) {
      solve3();
    }
    if (simplexCount === 3) {
      break;
    }

    // Search direction towards the origin from the simplex's closest feature. For an edge the
    // direction is the edge's normal on the origin's side, which is exact even when the closest
    // point itself would be computed with cancellation (Catto 2010).
    let dx: number;
    let dy: number;
    if (simplexCount === 1) {
      dx = -simplex[4]!;
      dy = -simplex[5]!;
    } else {
      const ex = simplex[STRIDE + 4]! - simplex[4]!;
      const ey = simplex[STRIDE + 5]! - simplex[5]!;
      const side = ex * -simplex[5]! - ey * -simplex[4]!;
      if (side > 0) {
        dx = -ey;
        dy = ex;
      } else {
        dx = ey;
        dy = -ex;
      }
    }
    if (dx * dx + dy * dy < 1e-30) {
      // The origin lies on the simplex: the cores touch.
      break;
    }

    // Support of B - A along d: furthest vertex of B along d and of A along -d, found in each
    // body's frame by rotating d with the transposed rotation.
    const indexA = support(proxyA, -(xfA.c * dx + xfA.s * dy), -(-xfA.s * dx + xfA.c * dy));
    const indexB = support(proxyB, xfB.c * dx + xfB.s * dy, -xfB.s * dx + xfB.c * dy);
    iteration++;

    // A repeated support point means no progress: the closest feature has been found.
    let duplicate = false;
    for (let i = 0; i < saveCount; i++) {
      if (indexA === savedIndexA[i] && indexB === savedIndexB[i]) {
        duplicate = true;
        break;
      }
    }
    if (duplicate) {
      break;
    }
    setVertex(simplexCount, proxyA, xfA, indexA, proxyB, xfB, indexB);
    simplexCount++;
  }

  let ax: number;
  let ay: number;
  let bx: number;
  let by: number;
  if (simplexCount === 1) {
    ax = simplex[0]!;
    ay = simplex[1]!;
    bx = simplex[2]!;
    by = simplex[3]!;
  } else if (simplexCount === 2) {
    const a1 = simplex[6]!;
    const a2 = simplex[STRIDE + 6]!;
    ax = a1 * simplex[0]! + a2 * simplex[STRIDE]!;
    ay = a1 * simplex[1]! + a2 * simplex[STRIDE + 1]!;
    bx = a1 * simplex[2]! + a2 * simplex[STRIDE + 2]!;
    by = a1 * simplex[3]! + a2 * simplex[STRIDE + 3]!;
  } else {
    const a1 = simplex[6]!;
    const a2 = simplex[STRIDE + 6]!;
    const a3 = simplex[2 * STRIDE + 6]!;
    ax = a1 * simplex[0]! + a2 * simplex[STRIDE]! + a3 * simplex[2 * STRIDE]!;
    ay = a1 * simplex[1]! + a2 * simplex[STRIDE + 1]! + a3 * simplex[2 * STRIDE + 1]!;
    bx = ax;
    by = ay;
  }
  const distance = Math.sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay));
  coreResult.pointAX = ax;
  coreResult.pointAY = ay;
  coreResult.pointBX = bx;
  coreResult.pointBY = by;
  coreResult.distance = distance;
  coreResult.iterations = iteration;
  return distance;
}

/**
 * Distance between two convex shapes placed in the world by xfA and xfB, radii included (m):
 * 0 when they touch or overlap. Fills `out` with the distance, closest points, normal (A to B)
 * and iteration count, all in the world frame. Allocates nothing.
 */
export function shapeDistance(
  proxyA: DistanceProxy,
  xfA: Transform,
  proxyB: DistanceProxy,
  xfB: Transform,
  out: DistanceOutput,
): number {
  const coreDistance = gjkCores(proxyA, xfA, proxyB, xfB);
  let ax = coreResult.pointAX;
  let ay = coreResult.pointAY;
  let bx = coreResult.pointBX;
  let by = coreResult.pointBY;
  let nx = 0;
  let ny = 0;
  if (coreDistance > 1e-12) {
    nx = (bx - ax) / coreDistance;
    ny = (by - ay) / coreDistance;
  }
  const rA = proxyA.radius;
  const rB = proxyB.radius;
  let distance: number;
  if (coreDistance > rA + rB && coreDistance > 1e-12) {
    // Move the witness points from the cores onto the surfaces.
    distance = coreDistance - rA - rB;
    ax += rA * nx;
    ay += rA * ny;
    bx -= rB * nx;
    by -= rB * ny;
  } else {
    // The swollen shapes overlap: report the midpoint of the core witnesses for both.
    distance = 0;
    ax = 0.5 * (ax + bx);
    ay = 0.5 * (ay + by);
    bx = ax;
    by = ay;
  }
  out.distance = distance;
  out.pointAX = ax;
  out.pointAY = ay;
  out.pointBX = bx;
  out.pointBY = by;
  out.normalX = nx;
  out.normalY = ny;
  out.iterations = coreResult.iterations;
  return distance;
}
