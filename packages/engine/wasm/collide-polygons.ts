// Ported from src/collision/collide-polygons.ts (issue #30): the one source of this narrow phase.
import {
  B_C,
  B_S,
  B_X,
  B_Y,
  G_COUNT,
  G_NORMALS,
  G_RADIUS,
  G_VERTICES,
  LINEAR_SLOP,
  S_FRACTIONS,
  S_NORMALS_B,
  S_VERTICES_A,
  S_VERTICES_B,
} from './contact-layout';
import { closestSegmentFractions } from './closest-segment-fractions';
import { ld, st } from './load-store';
import {
  makeFeatureId,
  setPointCount,
  speculativeDistanceOf,
  writeNormal,
  writePoint,
} from './manifold';

/** Feature-id flag: the point comes from two vertices, not a face. */
const VERTEX_PAIR: i32 = 0x10;

/**
 * Reference faces are kept on A unless B's face separates by this much more (m): the bias keeps
 * the choice, and with it the feature ids, from flickering between nearly equal faces.
 */
const FLIP_BIAS: f64 = 0.1 * LINEAR_SLOP;

/** Edge index found by the last findMaxSeparation call. */
let maxSeparationEdge: i32 = 0;

/** Where double k of the list at `p` (a geometry row's, or the scratch's) is. */
function at(p: usize, k: i32): f64 {
  return ld(p, k);
}

/**
 * Contact manifold between two convex polygons (geometry rows `a` and `b`), sharp or rounded: up
 * to two points. Polygons with count 2 are accepted as well (a segment: normals n and -n), which
 * is how walls and capsules reuse this kernel.
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
 * Works in frame F = A's local frame shifted to A's first vertex (scratch at `m`): coordinates
 * stay small there however far the bodies are from the world origin. Points lie midway between
 * the two rounded surfaces. Ids pair the reference edge with the incident vertex, so they persist
 * while the same faces touch. Writes the manifold at `m`; the normal points from A to B (world
 * frame).
 */
export function collidePolygons(a: usize, xfA: usize, b: usize, xfB: usize, m: usize): void {
  const speculativeDistance = speculativeDistanceOf(m);
  const verticesA = m + ((<usize>S_VERTICES_A) << 3);
  const verticesB = m + ((<usize>S_VERTICES_B) << 3);
  const normalsB = m + ((<usize>S_NORMALS_B) << 3);
  const normalsA = a + ((<usize>G_NORMALS) << 3);
  const rowVerticesA = a + ((<usize>G_VERTICES) << 3);
  const rowVerticesB = b + ((<usize>G_VERTICES) << 3);
  const rowNormalsB = b + ((<usize>G_NORMALS) << 3);
  const countA = <i32>ld(a, G_COUNT);
  const countB = <i32>ld(b, G_COUNT);
  const originX = at(rowVerticesA, 0);
  const originY = at(rowVerticesA, 1);
  // B in frame F: v_F = R v_B + t, R = RA^T RB, t = RA^T (pB - pA) - origin.
  const cA = ld(xfA, B_C);
  const sA = ld(xfA, B_S);
  const c = cA * ld(xfB, B_C) + sA * ld(xfB, B_S);
  const s = cA * ld(xfB, B_S) - sA * ld(xfB, B_C);
  const dx = ld(xfB, B_X) - ld(xfA, B_X);
  const dy = ld(xfB, B_Y) - ld(xfA, B_Y);
  const tx = cA * dx + sA * dy - originX;
  const ty = -sA * dx + cA * dy - originY;
  for (let i: i32 = 0; i < 2 * countA; i += 2) {
    st(verticesA, i, at(rowVerticesA, i) - originX);
    st(verticesA, i + 1, at(rowVerticesA, i + 1) - originY);
  }
  for (let i: i32 = 0; i < 2 * countB; i += 2) {
    const x = at(rowVerticesB, i);
    const y = at(rowVerticesB, i + 1);
    st(verticesB, i, c * x - s * y + tx);
    st(verticesB, i + 1, s * x + c * y + ty);
    const nx = at(rowNormalsB, i);
    const ny = at(rowNormalsB, i + 1);
    st(normalsB, i, c * nx - s * ny);
    st(normalsB, i + 1, s * nx + c * ny);
  }

  const separationA = findMaxSeparation(countA, verticesA, normalsA, countB, verticesB);
  const edgeA = maxSeparationEdge;
  const separationB = findMaxSeparation(countB, verticesB, normalsB, countA, verticesA);
  const edgeB = maxSeparationEdge;
  const radiusA = ld(a, G_RADIUS);
  const radiusB = ld(b, G_RADIUS);
  const radius = radiusA + radiusB;
  if (separationA - radius >= speculativeDistance || separationB - radius >= speculativeDistance) {
    setPointCount(m, 0);
    return;
  }

  // Polygon 1 owns the reference face, polygon 2 the incident edge.
  const isFlipped = separationB > FLIP_BIAS + separationA;
  const vertices1 = isFlipped ? verticesB : verticesA;
  const normals1 = isFlipped ? normalsB : normalsA;
  const count1 = isFlipped ? countB : countA;
  const edge1 = isFlipped ? edgeB : edgeA;
  const radius1 = isFlipped ? radiusB : radiusA;
  const vertices2 = isFlipped ? verticesA : verticesB;
  const normals2 = isFlipped ? normalsA : normalsB;
  const count2 = isFlipped ? countA : countB;
  const radius2 = isFlipped ? radiusA : radiusB;

  const nx = at(normals1, 2 * edge1);
  const ny = at(normals1, 2 * edge1 + 1);
  let edge2: i32 = 0;
  let minDot: f64 = Infinity;
  for (let i: i32 = 0; i < count2; i++) {
    const d = nx * at(normals2, 2 * i) + ny * at(normals2, 2 * i + 1);
    if (d < minDot) {
      minDot = d;
      edge2 = i;
    }
  }
  const i11 = edge1;
  const i12 = edge1 + 1 < count1 ? edge1 + 1 : 0;
  const i21 = edge2;
  const i22 = edge2 + 1 < count2 ? edge2 + 1 : 0;
  const v11x = at(vertices1, 2 * i11);
  const v11y = at(vertices1, 2 * i11 + 1);
  const v12x = at(vertices1, 2 * i12);
  const v12y = at(vertices1, 2 * i12 + 1);
  const v21x = at(vertices2, 2 * i21);
  const v21y = at(vertices2, 2 * i21 + 1);
  const v22x = at(vertices2, 2 * i22);
  const v22y = at(vertices2, 2 * i22 + 1);
  // Reference edge direction d1 and incident direction d2 (kernel names: Ericson 5.1.9).
  const d1x = v12x - v11x;
  const d1y = v12y - v11y;
  const d2x = v22x - v21x;
  const d2y = v22y - v21y;
  const length1Squared = d1x * d1x + d1y * d1y;

  if (max<f64>(separationA, separationB) > 0.1 * LINEAR_SLOP) {
    // Closest points of the two edges, fractions f1 on the reference, f2 on the incident edge
    // (Ericson, 5.1.9, ClosestPtSegmentSegment; both edges have non-zero length).
    const length2Squared = d2x * d2x + d2y * d2y;
    const rx = v11x - v21x;
    const ry = v11y - v21y;
    closestSegmentFractions(
      m,
      length1Squared,
      length2Squared,
      d1x * d2x + d1y * d2y,
      d1x * rx + d1y * ry,
      d2x * rx + d2y * ry,
    );
    const f1 = ld(m, S_FRACTIONS);
    const f2 = ld(m, S_FRACTIONS + 1);
    if ((f1 == 0 || f1 == 1) && (f2 == 0 || f2 == 1)) {
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
          setPointCount(m, 0);
          return;
        }
        const ux = gapX / distance;
        const uy = gapY / distance;
        const along = radius1 + 0.5 * separation;
        const vertex1 = f1 == 0 ? i11 : i12;
        const vertex2 = f2 == 0 ? i21 : i22;
        writeNormal(m, isFlipped ? -ux : ux, isFlipped ? -uy : uy, xfA);
        writePoint(
          m,
          0,
          p1x + along * ux + originX,
          p1y + along * uy + originY,
          separation,
          isFlipped
            ? makeFeatureId(VERTEX_PAIR | vertex2, vertex1)
            : makeFeatureId(VERTEX_PAIR | vertex1, vertex2),
          xfA,
        );
        setPointCount(m, 1);
        return;
      }
    }
  }

  // Sutherland-Hodgman: clip the incident edge to lower <= (p - v11).d1 <= upper.
  const upper = length1Squared;
  const lower: f64 = 0;
  let ax = v21x;
  let ay = v21y;
  let bx = v22x;
  let by = v22y;
  let ta = (ax - v11x) * d1x + (ay - v11y) * d1y;
  let tb = (bx - v11x) * d1x + (by - v11y) * d1y;
  let count: i32 = 2;
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
  let pointCount: i32 = 0;
  const coreA = nx * (ax - v11x) + ny * (ay - v11y);
  if (coreA - radius < speculativeDistance) {
    // Midway between the reference surface (plane + radius1) and the incident one (p - radius2 n).
    const shift = 0.5 * (radius1 - radius2 - coreA);
    writePoint(
      m,
      pointCount,
      ax + shift * nx + originX,
      ay + shift * ny + originY,
      coreA - radius,
      pointId(isFlipped, vertexA == i21 ? i12 : i11, vertexA),
      xfA,
    );
    pointCount++;
  }
  if (count == 2) {
    const coreB = nx * (bx - v11x) + ny * (by - v11y);
    if (coreB - radius < speculativeDistance) {
      const shift = 0.5 * (radius1 - radius2 - coreB);
      writePoint(
        m,
        pointCount,
        bx + shift * nx + originX,
        by + shift * ny + originY,
        coreB - radius,
        pointId(isFlipped, i11, i22),
        xfA,
      );
      pointCount++;
    }
  }
  writeNormal(m, outNormalX, outNormalY, xfA);
  setPointCount(m, pointCount);
}

/**
 * Largest over the faces of polygon 1 of the smallest signed distance of polygon 2's vertices to
 * that face (m, cores only): positive means a separating axis. Stores the face in
 * maxSeparationEdge.
 */
function findMaxSeparation(
  count1: i32,
  vertices1: usize,
  normals1: usize,
  count2: i32,
  vertices2: usize,
): f64 {
  let bestEdge: i32 = 0;
  let maxSeparation: f64 = -Infinity;
  for (let i: i32 = 0; i < count1; i++) {
    const nx = at(normals1, 2 * i);
    const ny = at(normals1, 2 * i + 1);
    const vx = at(vertices1, 2 * i);
    const vy = at(vertices1, 2 * i + 1);
    let minSeparation: f64 = Infinity;
    for (let j: i32 = 0; j < count2; j++) {
      const separation = nx * (at(vertices2, 2 * j) - vx) + ny * (at(vertices2, 2 * j + 1) - vy);
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
  return maxSeparation;
}

/**
 * A point's id names the pair of vertices it lies between, A's then B's: a clipped point lies
 * between an incident vertex and the reference vertex it faces (the edges run opposite ways, so
 * the incident edge's first vertex faces the reference edge's second). Because the pair does not
 * depend on which polygon owns the reference face, ids survive the reference face flipping between
 * two nearly parallel faces, and warm starting with them (Box2D v3 names its points the same way).
 */
function pointId(isFlipped: bool, referenceVertex: i32, incidentVertex: i32): i32 {
  return isFlipped
    ? makeFeatureId(incidentVertex, referenceVertex)
    : makeFeatureId(referenceVertex, incidentVertex);
}
