// Ported from src/collision/collide-polygon-capsule.ts (issue #30): the one source of this narrow
// phase.
import {
  G_CENTROID_X,
  G_CENTROID_Y,
  G_COUNT,
  G_NORMALS,
  G_RADIUS,
  G_VERTICES,
  S_POLYGON,
} from './contact-layout';
import { collidePolygons } from './collide-polygons';
import { ld, st } from './load-store';

/**
 * Writes capsule `capsule` (a geometry row) as a two-vertex polygon with the capsule's radius
 * into the scratch's polygon row (S_POLYGON of `m`), which it returns: vertices at the two
 * centres, face normals n and -n, centroid at the midpoint. Box2D v3 collides capsules with
 * polygons the same way (b2MakeCapsule): a capsule is a segment swollen by a radius, and the
 * polygon kernel handles rounding and count-2 polygons.
 */
export function capsuleAsPolygon(capsule: usize, m: usize): usize {
  const out = m + ((<usize>S_POLYGON) << 3);
  const x1 = ld(capsule, G_VERTICES);
  const y1 = ld(capsule, G_VERTICES + 1);
  const x2 = ld(capsule, G_VERTICES + 2);
  const y2 = ld(capsule, G_VERTICES + 3);
  const ex = x2 - x1;
  const ey = y2 - y1;
  const length = Math.sqrt(ex * ex + ey * ey);
  const nx = ey / length;
  const ny = -ex / length;
  st(out, G_COUNT, 2);
  st(out, G_RADIUS, ld(capsule, G_RADIUS));
  st(out, G_VERTICES, x1);
  st(out, G_VERTICES + 1, y1);
  st(out, G_VERTICES + 2, x2);
  st(out, G_VERTICES + 3, y2);
  st(out, G_NORMALS, nx);
  st(out, G_NORMALS + 1, ny);
  st(out, G_NORMALS + 2, -nx);
  st(out, G_NORMALS + 3, -ny);
  st(out, G_CENTROID_X, 0.5 * (x1 + x2));
  st(out, G_CENTROID_Y, 0.5 * (y1 + y2));
  return out;
}

/**
 * Contact between a convex polygon A (sharp or rounded) and a capsule B: up to two points, by the
 * polygon kernel with B as a rounded two-vertex polygon. The separating-axis test there is
 * complete for this pair: the Minkowski difference of a polygon with area and a segment has only
 * the polygon's edge normals and the segment's normal as face normals, and a corner-to-end
 * contact is found by its vertex-pair step. Writes the manifold at `m`; the normal points from A
 * to B.
 */
export function collidePolygonAndCapsule(
  a: usize,
  xfA: usize,
  b: usize,
  xfB: usize,
  m: usize,
): void {
  collidePolygons(a, xfA, capsuleAsPolygon(b, m), xfB, m);
}
