import type { Capsule } from '../geometry/capsule.ts';
import type { Circle } from '../geometry/circle.ts';
import type { Transform } from '../math/transform.ts';
import type { Manifold } from './manifold.ts';
import { circleCenterInA, onePoint, writeOnePoint } from './one-point-manifold.ts';

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
  circleCenterInA(b, xfA, xfB);
  const cx = onePoint[0]!;
  const cy = onePoint[1]!;
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
  onePoint[0] = px;
  onePoint[1] = py;
  onePoint[2] = nx;
  onePoint[3] = ny;
  onePoint[4] = separation;
  writeOnePoint(out, xfA, xfB);
}
