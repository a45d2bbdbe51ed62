import type { Capsule } from '../geometry/capsule.ts';
import type { Circle } from '../geometry/circle.ts';
import type { Transform } from '../math/transform.ts';
import { makeFeatureId, type Manifold } from './manifold.ts';

/**
 * Contact between a capsule A and a circle B: at most one point. The closest point q of A's core
 * segment to the circle's centre c (Ericson, Real-Time Collision Detection, 5.1.2) gives the
 * normal (c - q) / |c - q| and the separation |c - q| - rA - rB (m); a centre exactly on the core
 * uses the segment's normal, so the result is never NaN. The point lies midway between the
 * surfaces. Writes only the geometric fields of `out`; the normal points from A to B.
 */
export function collideCapsuleAndCircle(
  a: Capsule,
  xfA: Transform,
  b: Circle,
  xfB: Transform,
  out: Manifold,
): void {
  const speculativeDistance = out.speculativeDistance;
  // Circle centre in A's frame.
  const wx = xfB.c * b.centerX - xfB.s * b.centerY + xfB.x - xfA.x;
  const wy = xfB.s * b.centerX + xfB.c * b.centerY + xfB.y - xfA.y;
  const cx = xfA.c * wx + xfA.s * wy;
  const cy = -xfA.s * wx + xfA.c * wy;
  const ex = a.x2 - a.x1;
  const ey = a.y2 - a.y1;
  let t = ((cx - a.x1) * ex + (cy - a.y1) * ey) / (ex * ex + ey * ey);
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const qx = a.x1 + t * ex;
  const qy = a.y1 + t * ey;
  const dx = cx - qx;
  const dy = cy - qy;
  const distance = Math.sqrt(dx * dx + dy * dy);
  const separation = distance - a.radius - b.radius;
  if (separation >= speculativeDistance) {
    out.pointCount = 0;
    return;
  }
  let nx: number;
  let ny: number;
  if (distance > 0) {
    nx = dx / distance;
    ny = dy / distance;
  } else {
    const length = Math.sqrt(ex * ex + ey * ey);
    nx = ey / length;
    ny = -ex / length;
  }
  const along = a.radius + 0.5 * separation;
  const px = qx + along * nx;
  const py = qy + along * ny;
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
  point.separation = separation;
  point.id = makeFeatureId(0, 0);
}
