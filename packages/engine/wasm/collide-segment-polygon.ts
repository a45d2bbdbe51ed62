// Ported from src/collision/collide-segment-polygon.ts (issue #30): the one source of this narrow
// phase.
import {
  B_C,
  B_S,
  B_X,
  B_Y,
  G_CENTROID_X,
  G_CENTROID_Y,
  G_COUNT,
  G_NORMALS,
  G_ONE_SIDED,
  G_RADIUS,
  G_VERTICES,
  S_POLYGON,
} from './contact-layout';
import { collidePolygons } from './collide-polygons';
import { ld, st } from './load-store';
import {
  makeFeatureId,
  setPointCount,
  speculativeDistanceOf,
  writeWorldNormal,
  writeWorldPoint,
} from './manifold';

/**
 * Contact between a segment A (a wall) and a convex polygon B (a geometry row, or a capsule as a
 * polygon): up to two points.
 *
 * Two-sided: the segment is a two-vertex polygon whose two faces have normals n and -n, and the
 * polygon kernel runs unchanged (SAT over both sets of face normals, then clipping; Box2D v3
 * treats segments as degenerate polygons the same way). One-sided: a polygon whose centroid is
 * behind the wall gives no contact. Otherwise the reference face is forced to be the wall's
 * positive face, so the normal is always the positive normal: B's edge most anti-parallel to it is
 * clipped to the wall's extent (Ericson, Real-Time Collision Detection, 8.x) and measured along
 * it; nothing beside the wall's ends is pushed sideways across it. Separation in m, including B's
 * radius. Writes the manifold at `m`; the normal points from A to B.
 */
export function collideSegmentAndPolygon(
  a: usize,
  xfA: usize,
  b: usize,
  xfB: usize,
  m: usize,
): void {
  const speculativeDistance = speculativeDistanceOf(m);
  const x1 = ld(a, G_VERTICES);
  const y1 = ld(a, G_VERTICES + 1);
  const x2 = ld(a, G_VERTICES + 2);
  const y2 = ld(a, G_VERTICES + 3);
  const ex = x2 - x1;
  const ey = y2 - y1;
  const length = Math.sqrt(ex * ex + ey * ey);
  const nx = ey / length;
  const ny = -ex / length;
  if (ld(a, G_ONE_SIDED) == 0) {
    // The wall as a two-vertex polygon in the scratch's polygon row (B is then a real polygon:
    // a two-sided wall meets a capsule in collide-segment-capsule.ts).
    const polygon = m + ((<usize>S_POLYGON) << 3);
    st(polygon, G_COUNT, 2);
    st(polygon, G_RADIUS, 0);
    st(polygon, G_VERTICES, x1);
    st(polygon, G_VERTICES + 1, y1);
    st(polygon, G_VERTICES + 2, x2);
    st(polygon, G_VERTICES + 3, y2);
    st(polygon, G_NORMALS, nx);
    st(polygon, G_NORMALS + 1, ny);
    st(polygon, G_NORMALS + 2, -nx);
    st(polygon, G_NORMALS + 3, -ny);
    st(polygon, G_CENTROID_X, 0.5 * (x1 + x2));
    st(polygon, G_CENTROID_Y, 0.5 * (y1 + y2));
    collidePolygons(polygon, xfA, b, xfB, m);
    return;
  }

  // One-sided, in A's frame relative to the first end point: B's local v maps to R v + t.
  const cA = ld(xfA, B_C);
  const sA = ld(xfA, B_S);
  const c = cA * ld(xfB, B_C) + sA * ld(xfB, B_S);
  const s = cA * ld(xfB, B_S) - sA * ld(xfB, B_C);
  const dx = ld(xfB, B_X) - ld(xfA, B_X);
  const dy = ld(xfB, B_Y) - ld(xfA, B_Y);
  const tx = cA * dx + sA * dy - x1;
  const ty = -sA * dx + cA * dy - y1;
  const centroidX = ld(b, G_CENTROID_X);
  const centroidY = ld(b, G_CENTROID_Y);
  const centroidHeight =
    nx * (c * centroidX - s * centroidY + tx) + ny * (s * centroidX + c * centroidY + ty);
  if (centroidHeight < 0) {
    setPointCount(m, 0);
    return;
  }
  const count = <i32>ld(b, G_COUNT);
  let incident: i32 = 0;
  let minDot: f64 = Infinity;
  for (let i: i32 = 0; i < count; i++) {
    const bx = ld(b, G_NORMALS + 2 * i);
    const by = ld(b, G_NORMALS + 2 * i + 1);
    const d = nx * (c * bx - s * by) + ny * (s * bx + c * by);
    if (d < minDot) {
      minDot = d;
      incident = i;
    }
  }
  const next = incident + 1 < count ? incident + 1 : 0;
  const ix = ld(b, G_VERTICES + 2 * incident);
  const iy = ld(b, G_VERTICES + 2 * incident + 1);
  const jx = ld(b, G_VERTICES + 2 * next);
  const jy = ld(b, G_VERTICES + 2 * next + 1);
  // Incident edge from p to q, in A's frame relative to the wall's first end point.
  let px = c * ix - s * iy + tx;
  let py = s * ix + c * iy + ty;
  let qx = c * jx - s * jy + tx;
  let qy = s * jx + c * jy + ty;
  // Clip to 0 <= (point . e) <= |e|^2, the wall's extent.
  const upper = length * length;
  let tp = px * ex + py * ey;
  let tq = qx * ex + qy * ey;
  if ((tp < 0 && tq < 0) || (tp > upper && tq > upper)) {
    setPointCount(m, 0);
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
  const radius = ld(b, G_RADIUS);
  const ax = ld(xfA, B_X);
  const ay = ld(xfA, B_Y);
  let pointCount: i32 = 0;
  for (let k: i32 = 0; k < 2; k++) {
    const x = k == 0 ? px : qx;
    const y = k == 0 ? py : qy;
    const core = nx * x + ny * y;
    const separation = core - radius;
    if (separation >= speculativeDistance) {
      continue;
    }
    // Midway between the wall (height 0) and B's surface (height core - radius).
    const shift = -0.5 * (core + radius);
    const localX = x + shift * nx + x1;
    const localY = y + shift * ny + y1;
    const anchorX = cA * localX - sA * localY;
    const anchorY = sA * localX + cA * localY;
    writeWorldPoint(
      m,
      pointCount,
      anchorX + ax,
      anchorY + ay,
      separation,
      makeFeatureId(0, k == 0 ? incident : next),
    );
    pointCount++;
  }
  writeWorldNormal(m, cA * nx - sA * ny, sA * nx + cA * ny);
  setPointCount(m, pointCount);
}
