import type { Capsule } from '../geometry/capsule.ts';
import { createEmptyPolygon, type Polygon } from '../geometry/polygon.ts';
import type { Transform } from '../math/transform.ts';
import { collidePolygons } from './collide-polygons.ts';
import type { Manifold } from './manifold.ts';

/** The capsule being collided, as a rounded two-vertex polygon; rebuilt every call. */
const capsulePolygon = createEmptyPolygon();

/**
 * Writes `capsule` into `out` as a two-vertex polygon with the capsule's radius: vertices at the
 * two centres, face normals n and -n, centroid at the midpoint. Box2D v3 collides capsules with
 * polygons the same way (b2MakeCapsule): a capsule is a segment swollen by a radius, and the
 * polygon kernel handles rounding and count-2 polygons. Returns `out`.
 */
export function capsuleAsPolygon(capsule: Capsule, out: Polygon): Polygon {
  const ex = capsule.x2 - capsule.x1;
  const ey = capsule.y2 - capsule.y1;
  const length = Math.sqrt(ex * ex + ey * ey);
  const nx = ey / length;
  const ny = -ex / length;
  out.count = 2;
  out.radius = capsule.radius;
  out.vertices[0] = capsule.x1;
  out.vertices[1] = capsule.y1;
  out.vertices[2] = capsule.x2;
  out.vertices[3] = capsule.y2;
  out.normals[0] = nx;
  out.normals[1] = ny;
  out.normals[2] = -nx;
  out.normals[3] = -ny;
  out.centroidX = 0.5 * (capsule.x1 + capsule.x2);
  out.centroidY = 0.5 * (capsule.y1 + capsule.y2);
  return out;
}

/**
 * Contact between a convex polygon A (sharp or rounded) and a capsule B: up to two points, by the
 * polygon kernel with B as a rounded two-vertex polygon. The separating-axis test there is
 * complete for this pair: the Minkowski difference of a polygon with area and a segment has only
 * the polygon's edge normals and the segment's normal as face normals, and a corner-to-end
 * contact is found by its vertex-pair step. Writes only the geometric fields of `out`; the normal
 * points from A to B.
 */
export function collidePolygonAndCapsule(
  a: Polygon,
  xfA: Transform,
  b: Capsule,
  xfB: Transform,
  out: Manifold,
): void {
  collidePolygons(a, xfA, capsuleAsPolygon(b, capsulePolygon), xfB, out);
}
