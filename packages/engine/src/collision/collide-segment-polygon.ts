import { createEmptyPolygon } from '../geometry/polygon.ts';
import type { Polygon } from '../geometry/polygon.ts';
import type { Segment } from '../geometry/segment.ts';
import type { Transform } from '../math/transform.ts';
import { collidePolygons } from './collide-polygons.ts';
import { makeFeatureId, type Manifold } from './manifold.ts';

/** The segment being collided, as a two-vertex polygon (normals n and -n); rebuilt every call. */
const segmentPolygon = createEmptyPolygon();

/**
 * Contact between a segment A (a wall) and a convex polygon B: up to two points.
 *
 * Two-sided: the segment is a two-vertex polygon whose two faces have normals n and -n, and the
 * polygon kernel runs unchanged (SAT over both sets of face normals, then clipping; Box2D v3
 * treats segments as degenerate polygons the same way). One-sided: a polygon whose centroid is
 * behind the wall gives no contact. Otherwise the reference face is forced to be the wall's
 * positive face, so the normal is always the positive normal: B's edge most anti-parallel to it is
 * clipped to the wall's extent (Ericson, Real-Time Collision Detection, 8.x) and measured along
 * it; nothing beside the wall's ends is pushed sideways across it. Separation in m, including B's
 * radius. Writes only the geometric fields of `out`; the normal points from A to B.
 */
export function collideSegmentAndPolygon(
  a: Segment,
  xfA: Transform,
  b: Polygon,
  xfB: Transform,
  out: Manifold,
): void {
  const speculativeDistance = out.speculativeDistance;
  const ex = a.x2 - a.x1;
  const ey = a.y2 - a.y1;
  const length = Math.sqrt(ex * ex + ey * ey);
  const nx = ey / length;
  const ny = -ex / length;
  if (!a.oneSided) {
    const polygon = segmentPolygon;
    polygon.count = 2;
    polygon.radius = 0;
    polygon.vertices[0] = a.x1;
    polygon.vertices[1] = a.y1;
    polygon.vertices[2] = a.x2;
    polygon.vertices[3] = a.y2;
    polygon.normals[0] = nx;
    polygon.normals[1] = ny;
    polygon.normals[2] = -nx;
    polygon.normals[3] = -ny;
    polygon.centroidX = 0.5 * (a.x1 + a.x2);
    polygon.centroidY = 0.5 * (a.y1 + a.y2);
    collidePolygons(polygon, xfA, b, xfB, out);
    return;
  }

  // One-sided, in A's frame relative to the first end point: B's local v maps to R v + t.
  const cA = xfA.c;
  const sA = xfA.s;
  const c = cA * xfB.c + sA * xfB.s;
  const s = cA * xfB.s - sA * xfB.c;
  const dx = xfB.x - xfA.x;
  const dy = xfB.y - xfA.y;
  const tx = cA * dx + sA * dy - a.x1;
  const ty = -sA * dx + cA * dy - a.y1;
  const centroidHeight =
    nx * (c * b.centroidX - s * b.centroidY + tx) + ny * (s * b.centroidX + c * b.centroidY + ty);
  if (centroidHeight < 0) {
    out.pointCount = 0;
    return;
  }
  const count = b.count;
  const vertices = b.vertices;
  const normals = b.normals;
  let incident = 0;
  let minDot = Infinity;
  for (let i = 0; i < count; i++) {
    const bx = normals[2 * i]!;
    const by = normals[2 * i + 1]!;
    const d = nx * (c * bx - s * by) + ny * (s * bx + c * by);
    if (d < minDot) {
      minDot = d;
      incident = i;
    }
  }
  const next = incident + 1 < count ? incident + 1 : 0;
  // Incident edge from p to q, in A's frame relative to the wall's first end point.
  let px = c * vertices[2 * incident]! - s * vertices[2 * incident + 1]! + tx;
  let py = s * vertices[2 * incident]! + c * vertices[2 * incident + 1]! + ty;
  let qx = c * vertices[2 * next]! - s * vertices[2 * next + 1]! + tx;
  let qy = s * vertices[2 * next]! + c * vertices[2 * next + 1]! + ty;
  // Clip to 0 <= (point . e) <= |e|^2, the wall's extent.
  const upper = length * length;
  let tp = px * ex + py * ey;
  let tq = qx * ex + qy * ey;
  if ((tp < 0 && tq < 0) || (tp > upper && tq > upper)) {
    out.pointCount = 0;
    return;
  }
  if (tp < 0) {
    const f = -tp / (tq - tp);
    px += f * (qx - px);
    py += f * (qy - py);
    tp = 0;
  } else if (tq < 0) {
    const f = -tq / (tp - tq);
    qx += f * (px - qx);
    qy += f * (py - qy);
    tq = 0;
  }
  if (tp > upper) {
    const f = (tp - upper) / (tp - tq);
    px += f * (qx - px);
    py += f * (qy - py);
  } else if (tq > upper) {
    const f = (tq - upper) / (tq - tp);
    qx += f * (px - qx);
    qy += f * (py - qy);
  }
  const radius = b.radius;
  let pointCount = 0;
  for (let k = 0; k < 2; k++) {
    const x = k === 0 ? px : qx;
    const y = k === 0 ? py : qy;
    const core = nx * x + ny * y;
    const separation = core - radius;
    if (separation >= speculativeDistance) {
      continue;
    }
    // Midway between the wall (height 0) and B's surface (height core - radius).
    const shift = -0.5 * (core + radius);
    const localX = x + shift * nx + a.x1;
    const localY = y + shift * ny + a.y1;
    const anchorX = cA * localX - sA * localY;
    const anchorY = sA * localX + cA * localY;
    const point = out.points[pointCount === 0 ? 0 : 1];
    point.anchorAX = anchorX;
    point.anchorAY = anchorY;
    point.anchorBX = anchorX + xfA.x - xfB.x;
    point.anchorBY = anchorY + xfA.y - xfB.y;
    point.x = anchorX + xfA.x;
    point.y = anchorY + xfA.y;
    point.separation = separation;
    point.id = makeFeatureId(0, k === 0 ? incident : next);
    pointCount++;
  }
  out.normalX = cA * nx - sA * ny;
  out.normalY = sA * nx + cA * ny;
  out.pointCount = pointCount;
}
