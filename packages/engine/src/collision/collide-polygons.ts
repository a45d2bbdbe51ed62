import { LINEAR_SLOP, MAX_POLYGON_VERTICES } from '../core/constants.ts';
import type { Polygon } from '../geometry/polygon.ts';
import type { Transform } from '../math/transform.ts';
import { closestSegmentFractions, segmentFractions } from './closest-segment-fractions.ts';
import { makeFeatureId, type Manifold } from './manifold.ts';

// Scratch for one call, in frame F = A's local frame shifted to A's first vertex: coordinates
// stay small there however far the bodies are from the world origin.
const verticesA = new Float64Array(2 * MAX_POLYGON_VERTICES);
const verticesB = new Float64Array(2 * MAX_POLYGON_VERTICES);
const normalsB = new Float64Array(2 * MAX_POLYGON_VERTICES);

/** Edge index found by the last findMaxSeparation call (a second return value without allocation). */
let maxSeparationEdge = 0;
/**
 * Fractional values passed to the helpers below and back (findMaxSeparation's result at 0, a
 * point's x, y and separation or a normal's x, y at 1-3): V8 boxes (allocates) the numbers
 * passed to or returned from a call it does not inline, once per pair per step here.
 */
const carry = new Float64Array(4);

/** Feature-id flag: the point comes from two vertices, not a face. */
const VERTEX_PAIR = 0x10;

/**
 * Reference faces are kept on A unless B's face separates by this much more (m): the bias keeps
 * the choice, and with it the feature ids, from flickering between nearly equal faces.
 */
const FLIP_BIAS = 0.1 * LINEAR_SLOP;

/**
 * Contact manifold between two convex polygons, sharp or rounded: up to two points. Polygons with
 * count 2 are accepted as well (a segment: normals n and -n), which is how walls reuse this kernel.
 *
 * Algorithm (Ericson, Real-Time Collision Detection, 5.2.1 and 8.x; D. Gregorius, "Robust Contact
 * Creation for Physics Simulations", GDC 2015; the structure of Box2D v3's b2CollidePolygons):
 * 1. Separating-axis test over the face normals of both polygons, in A's frame through the
 *    relative transform: the face of maximum separation on each side.
 * 2. Reference face on A unless B's separates by more than FLIP_BIAS; incident edge = the edge of
 *    the other polygon whose normal is most anti-parallel to the reference normal.
 * 3. When the cores are apart (separation > 0.1 LINEAR_SLOP) and their nearest features are two
 *    vertices lying outside each other's face slabs, the contact is the single vertex pair with
 *    the normal along it: only then does rounding see the true distance at a corner.
 * 4. Otherwise Sutherland-Hodgman clipping of the incident edge against the reference face's two
 *    side planes; each clipped point is measured along the reference normal and kept while its
 *    separation (radii included) is below the speculative distance.
 * Points lie midway between the two rounded surfaces. Ids pair the reference edge with the incident
 * vertex, so they persist while the same faces touch. Writes only the geometric fields of `out`;
 * the normal points from A to B (world frame).
 */
export function collidePolygons(
  a: Polygon,
  xfA: Transform,
  b: Polygon,
  xfB: Transform,
  out: Manifold,
): void {
  const speculativeDistance = out.speculativeDistance;
  const countA = a.count;
  const countB = b.count;
  const originX = a.vertices[0]!;
  const originY = a.vertices[1]!;
  // B in frame F: v_F = R v_B + t, R = RA^T RB, t = RA^T (pB - pA) - origin.
  const cA = xfA.c;
  const sA = xfA.s;
  const c = cA * xfB.c + sA * xfB.s;
  const s = cA * xfB.s - sA * xfB.c;
  const dx = xfB.x - xfA.x;
  const dy = xfB.y - xfA.y;
  const tx = cA * dx + sA * dy - originX;
  const ty = -sA * dx + cA * dy - originY;
  for (let i = 0; i < 2 * countA; i += 2) {
    verticesA[i] = a.vertices[i]! - originX;
    verticesA[i + 1] = a.vertices[i + 1]! - originY;
  }
  for (let i = 0; i < 2 * countB; i += 2) {
    const x = b.vertices[i]!;
    const y = b.vertices[i + 1]!;
    verticesB[i] = c * x - s * y + tx;
    verticesB[i + 1] = s * x + c * y + ty;
    const nx = b.normals[i]!;
    const ny = b.normals[i + 1]!;
    normalsB[i] = c * nx - s * ny;
    normalsB[i + 1] = s * nx + c * ny;
  }

  findMaxSeparation(countA, verticesA, a.normals, countB, verticesB);
  const separationA = carry[0]!;
  const edgeA = maxSeparationEdge;
  findMaxSeparation(countB, verticesB, normalsB, countA, verticesA);
  const separationB = carry[0]!;
  const edgeB = maxSeparationEdge;
  const radius = a.radius + b.radius;
  if (separationA - radius >= speculativeDistance || separationB - radius >= speculativeDistance) {
    out.pointCount = 0;
    return;
  }

  // Polygon 1 owns the reference face, polygon 2 the incident edge.
  const isFlipped = separationB > FLIP_BIAS + separationA;
  const vertices1 = isFlipped ? verticesB : verticesA;
  const normals1 = isFlipped ? normalsB : a.normals;
  const count1 = isFlipped ? countB : countA;
  const edge1 = isFlipped ? edgeB : edgeA;
  const radius1 = isFlipped ? b.radius : a.radius;
  const vertices2 = isFlipped ? verticesA : verticesB;
  const normals2 = isFlipped ? a.normals : normalsB;
  const count2 = isFlipped ? countA : countB;
  const radius2 = isFlipped ? a.radius : b.radius;

  const nx = normals1[2 * edge1]!;
  const ny = normals1[2 * edge1 + 1]!;
  let edge2 = 0;
  let minDot = Infinity;
  for (let i = 0; i < count2; i++) {
    const d = nx * normals2[2 * i]! + ny * normals2[2 * i + 1]!;
    if (d < minDot) {
      minDot = d;
      edge2 = i;
    }
  }
  const i11 = edge1;
  const i12 = edge1 + 1 < count1 ? edge1 + 1 : 0;
  const i21 = edge2;
  const i22 = edge2 + 1 < count2 ? edge2 + 1 : 0;
  const v11x = vertices1[2 * i11]!;
  const v11y = vertices1[2 * i11 + 1]!;
  const v12x = vertices1[2 * i12]!;
  const v12y = vertices1[2 * i12 + 1]!;
  const v21x = vertices2[2 * i21]!;
  const v21y = vertices2[2 * i21 + 1]!;
  const v22x = vertices2[2 * i22]!;
  const v22y = vertices2[2 * i22 + 1]!;
  // Reference edge direction d1 and incident direction d2 (kernel names: Ericson 5.1.9).
  const d1x = v12x - v11x;
  const d1y = v12y - v11y;
  const d2x = v22x - v21x;
  const d2y = v22y - v21y;
  const length1Squared = d1x * d1x + d1y * d1y;

  if (Math.max(separationA, separationB) > 0.1 * LINEAR_SLOP) {
    // Closest points of the two edges, fractions f1 on the reference, f2 on the incident edge
    // (Ericson, 5.1.9, ClosestPtSegmentSegment; both edges have non-zero length).
    const length2Squared = d2x * d2x + d2y * d2y;
    const rx = v11x - v21x;
    const ry = v11y - v21y;
    const io = segmentFractions;
    io[0] = length1Squared;
    io[1] = length2Squared;
    io[2] = d1x * d2x + d1y * d2y;
    io[3] = d1x * rx + d1y * ry;
    io[4] = d2x * rx + d2y * ry;
    closestSegmentFractions();
    const f1 = io[5]!;
    const f2 = io[6]!;
    if ((f1 === 0 || f1 === 1) && (f2 === 0 || f2 === 1)) {
      const p2x = v21x + f2 * d2x;
      const p2y = v21y + f2 * d2y;
      // Where the incident vertex falls along the reference face, in units of its length.
      const slab = ((p2x - v11x) * d1x + (p2y - v11y) * d1y) / length1Squared;
      const margin = (0.1 * LINEAR_SLOP) / Math.sqrt(length1Squared);
      if (slab < -margin || slab > 1 + margin) {
        const p1x = v11x + f1 * d1x;
        const p1y = v11y + f1 * d1y;
        const gapX = p2x - p1x;
        const gapY = p2y - p1y;
        const distance = Math.sqrt(gapX * gapX + gapY * gapY);
        const separation = distance - radius;
        if (separation >= speculativeDistance) {
          out.pointCount = 0;
          return;
        }
        const ux = gapX / distance;
        const uy = gapY / distance;
        const along = radius1 + 0.5 * separation;
        const vertex1 = f1 === 0 ? i11 : i12;
        const vertex2 = f2 === 0 ? i21 : i22;
        carry[1] = isFlipped ? -ux : ux;
        carry[2] = isFlipped ? -uy : uy;
        writeNormal(out, xfA);
        carry[1] = p1x + along * ux + originX;
        carry[2] = p1y + along * uy + originY;
        carry[3] = separation;
        writePoint(
          out,
          0,
          isFlipped
            ? makeFeatureId(VERTEX_PAIR | vertex2, vertex1)
            : makeFeatureId(VERTEX_PAIR | vertex1, vertex2),
          xfA,
          xfB,
        );
        out.pointCount = 1;
        return;
      }
    }
  }

  // Sutherland-Hodgman: clip the incident edge to lower <= (p - v11).d1 <= upper.
  const upper = length1Squared;
  const lower = 0;
  let ax = v21x;
  let ay = v21y;
  let bx = v22x;
  let by = v22y;
  let ta = (ax - v11x) * d1x + (ay - v11y) * d1y;
  let tb = (bx - v11x) * d1x + (by - v11y) * d1y;
  let count = 2;
  let vertexA = i21;
  if ((ta < lower && tb < lower) || (ta > upper && tb > upper)) {
    // The edges do not overlap along the face (possible only within the slab margin above):
    // keep the incident vertex deeper along the normal.
    if (nx * (bx - ax) + ny * (by - ay) < 0) {
      ax = bx;
      ay = by;
      vertexA = i22;
    }
    count = 1;
  } else {
    if (ta < lower) {
      const f = (lower - ta) / (tb - ta);
      ax += f * (bx - ax);
      ay += f * (by - ay);
      ta = lower;
    } else if (tb < lower) {
      const f = (lower - tb) / (ta - tb);
      bx += f * (ax - bx);
      by += f * (ay - by);
      tb = lower;
    }
    if (ta > upper) {
      const f = (ta - upper) / (ta - tb);
      ax += f * (bx - ax);
      ay += f * (by - ay);
    } else if (tb > upper) {
      const f = (tb - upper) / (tb - ta);
      bx += f * (ax - bx);
      by += f * (ay - by);
    }
  }

  const outNormalX = isFlipped ? -nx : nx;
  const outNormalY = isFlipped ? -ny : ny;
  let pointCount = 0;
  const coreA = nx * (ax - v11x) + ny * (ay - v11y);
  if (coreA - radius < speculativeDistance) {
    // Midway between the reference surface (plane + radius1) and the incident one (p - radius2 n).
    const shift = 0.5 * (radius1 - radius2 - coreA);
    carry[1] = ax + shift * nx + originX;
    carry[2] = ay + shift * ny + originY;
    carry[3] = coreA - radius;
    writePoint(out, pointCount, pointId(isFlipped, vertexA === i21 ? i12 : i11, vertexA), xfA, xfB);
    pointCount++;
  }
  if (count === 2) {
    const coreB = nx * (bx - v11x) + ny * (by - v11y);
    if (coreB - radius < speculativeDistance) {
      const shift = 0.5 * (radius1 - radius2 - coreB);
      carry[1] = bx + shift * nx + originX;
      carry[2] = by + shift * ny + originY;
      carry[3] = coreB - radius;
      writePoint(out, pointCount, pointId(isFlipped, i11, i22), xfA, xfB);
      pointCount++;
    }
  }
  carry[1] = outNormalX;
  carry[2] = outNormalY;
  writeNormal(out, xfA);
  out.pointCount = pointCount;
}

/**
 * Largest over the faces of polygon 1 of the smallest signed distance of polygon 2's vertices to
 * that face (m, cores only), in carry[0]: positive means a separating axis. Stores the face in
 * maxSeparationEdge.
 */
function findMaxSeparation(
  count1: number,
  vertices1: Float64Array,
  normals1: Float64Array,
  count2: number,
  vertices2: Float64Array,
): void {
  let bestEdge = 0;
  let maxSeparation = -Infinity;
  for (let i = 0; i < count1; i++) {
    const nx = normals1[2 * i]!;
    const ny = normals1[2 * i + 1]!;
    const vx = vertices1[2 * i]!;
    const vy = vertices1[2 * i + 1]!;
    let minSeparation = Infinity;
    for (let j = 0; j < count2; j++) {
      const separation = nx * (vertices2[2 * j]! - vx) + ny * (vertices2[2 * j + 1]! - vy);
      if (separation < minSeparation) {
        minSeparation = separation;
      }
    }
    if (minSeparation > maxSeparation) {
      maxSeparation = minSeparation;
      bestEdge = i;
    }
  }
  maxSeparationEdge = bestEdge;
  carry[0] = maxSeparation;
}

/** Rotates a normal from A's frame to world and stores it. */
function writeNormal(out: Manifold, xfA: Transform): void {
  const nx = carry[1]!;
  const ny = carry[2]!;
  out.normalX = xfA.c * nx - xfA.s * ny;
  out.normalY = xfA.s * nx + xfA.c * ny;
}

/**
 * Stores point `index` given in A's local frame (carry[1..3]: x, y, separation; m): world
 * position, anchors, separation, id.
 */
function writePoint(
  out: Manifold,
  index: number,
  id: number,
  xfA: Transform,
  xfB: Transform,
): void {
  const localX = carry[1]!;
  const localY = carry[2]!;
  const separation = carry[3]!;
  const point = out.points[index === 0 ? 0 : 1];
  const anchorX = xfA.c * localX - xfA.s * localY;
  const anchorY = xfA.s * localX + xfA.c * localY;
  point.anchorAX = anchorX;
  point.anchorAY = anchorY;
  point.anchorBX = anchorX + xfA.x - xfB.x;
  point.anchorBY = anchorY + xfA.y - xfB.y;
  point.x = anchorX + xfA.x;
  point.y = anchorY + xfA.y;
  point.separation = separation;
  point.id = id;
}

/**
 * A point's id names the pair of vertices it lies between, A's then B's: a clipped point lies
 * between an incident vertex and the reference vertex it faces (the edges run opposite ways, so
 * the incident edge's first vertex faces the reference edge's second). Because the pair does not
 * depend on which polygon owns the reference face, ids survive the reference face flipping between
 * two nearly parallel faces, and warm starting with them (Box2D v3 names its points the same way).
 */
function pointId(isFlipped: boolean, referenceVertex: number, incidentVertex: number): number {
  return isFlipped
    ? makeFeatureId(incidentVertex, referenceVertex)
    : makeFeatureId(referenceVertex, incidentVertex);
}
