// What the one-point narrow phases (a circle against a capsule, a segment or a polygon) share:
// the circle's centre in A's frame, and the manifold written from A's frame.
import type { Circle } from '../geometry/circle.ts';
import type { Transform } from '../math/transform.ts';
import { makeFeatureId, type Manifold } from './manifold.ts';

/**
 * In and out for the functions below, in place of arguments and results: V8 boxes (allocates)
 * fractional numbers passed to or returned from a call it does not inline, and the narrow phase
 * must not allocate. {@link circleCenterInA} writes the centre at 0, 1; {@link writeOnePoint}
 * reads the point at 0, 1, the unit normal at 2, 3 and the separation at 4, all in A's frame.
 */
export const onePoint: Float64Array = new Float64Array(5);

/** Writes circle B's centre in A's frame, c = RA^T (RB cb + pB - pA), to onePoint[0], [1]. */
export function circleCenterInA(b: Circle, xfA: Transform, xfB: Transform): void {
  const wx = xfB.c * b.centerX - xfB.s * b.centerY + xfB.x - xfA.x;
  const wy = xfB.s * b.centerX + xfB.c * b.centerY + xfB.y - xfA.y;
  onePoint[0] = xfA.c * wx + xfA.s * wy;
  onePoint[1] = -xfA.s * wx + xfA.c * wy;
}

/**
 * Writes the one-point manifold whose point, normal (from A to B) and separation (m) are in
 * {@link onePoint} in A's frame: the normal and the point's place turned into the world frame,
 * its anchors from each body's origin, feature id 0.
 */
export function writeOnePoint(out: Manifold, xfA: Transform, xfB: Transform): void {
  const px = onePoint[0]!;
  const py = onePoint[1]!;
  const nx = onePoint[2]!;
  const ny = onePoint[3]!;
  const c = xfA.c;
  const s = xfA.s;
  const anchorX = c * px - s * py;
  const anchorY = s * px + c * py;
  out.normalX = c * nx - s * ny;
  out.normalY = s * nx + c * ny;
  out.pointCount = 1;
  const point = out.points[0];
  point.anchorAX = anchorX;
  point.anchorAY = anchorY;
  point.anchorBX = anchorX + xfA.x - xfB.x;
  point.anchorBY = anchorY + xfA.y - xfB.y;
  point.x = anchorX + xfA.x;
  point.y = anchorY + xfA.y;
  point.separation = onePoint[4]!;
  point.id = makeFeatureId(0, 0);
}
