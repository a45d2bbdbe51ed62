import type { Circle } from '../geometry/circle.ts';
import type { Transform } from '../math/transform.ts';
import { makeFeatureId, type Manifold } from './manifold.ts';

/**
 * Contact between two circles: at most one point, on the line of centres, midway between the
 * surfaces, with separation |cB - cA| - rA - rB (m). Coincident centres use the fixed normal
 * (1, 0) so the result is never NaN. Writes only the geometric fields of `out`; the normal points
 * from A to B (world frame).
 */
export function collideCircles(
  a: Circle,
  xfA: Transform,
  b: Circle,
  xfB: Transform,
  out: Manifold,
): void {
  const speculativeDistance = out.speculativeDistance;
  // Centres relative to A's origin, world orientation.
  const ax = xfA.c * a.centerX - xfA.s * a.centerY;
  const ay = xfA.s * a.centerX + xfA.c * a.centerY;
  const bx = xfB.c * b.centerX - xfB.s * b.centerY + xfB.x - xfA.x;
  const by = xfB.s * b.centerX + xfB.c * b.centerY + xfB.y - xfA.y;
  const dx = bx - ax;
  const dy = by - ay;
  const distance = Math.sqrt(dx * dx + dy * dy);
  const separation = distance - a.radius - b.radius;
  if (separation >= speculativeDistance) {
    out.pointCount = 0;
    return;
  }
  let nx = 1;
  let ny = 0;
  if (distance > 0) {
    nx = dx / distance;
    ny = dy / distance;
  }
  // Midway between A's surface point a + rA n and B's surface point b - rB n.
  const along = 0.5 * (a.radius - b.radius + distance);
  const pointX = ax + along * nx;
  const pointY = ay + along * ny;
  out.normalX = nx;
  out.normalY = ny;
  out.pointCount = 1;
  const point = out.points[0];
  point.anchorAX = pointX;
  point.anchorAY = pointY;
  point.anchorBX = pointX + xfA.x - xfB.x;
  point.anchorBY = pointY + xfA.y - xfB.y;
  point.x = pointX + xfA.x;
  point.y = pointY + xfA.y;
  point.separation = separation;
  point.id = makeFeatureId(0, 0);
}
