import type { Circle } from '../geometry/circle.ts';
import type { Segment } from '../geometry/segment.ts';
import type { Transform } from '../math/transform.ts';
import type { Manifold } from './manifold.ts';
import { circleCenterInA, onePoint, writeOnePoint } from './one-point-manifold.ts';

/**
 * Contact between a segment A (a wall) and a circle B: at most one point.
 *
 * Two-sided: the closest point q of the segment to the centre c (Ericson, Real-Time Collision
 * Detection, 5.1.2) gives the normal (c - q) / |c - q|; a centre exactly on the segment uses the
 * segment's positive normal. One-sided: a centre behind the wall (negative side of its positive
 * normal) gives no contact; otherwise the normal is always the positive normal, so a circle is
 * never pushed sideways over the wall's end or pulled through from behind, while the separation
 * stays the true distance |c - q| - r so a circle beside the end is not reported as touching.
 * Separation in m. Writes only the geometric fields of `out`; the normal points from A to B.
 */
export function collideSegmentAndCircle(
  a: Segment,
  xfA: Transform,
  b: Circle,
  xfB: Transform,
  out: Manifold,
): void {
  const speculativeDistance = out.speculativeDistance;
  // Everything in A's frame.
  circleCenterInA(b, xfA, xfB);
  const cx = onePoint[0]!;
  const cy = onePoint[1]!;
  const ex = a.x2 - a.x1;
  const ey = a.y2 - a.y1;
  const length = Math.sqrt(ex * ex + ey * ey);
  // Positive normal (e.y, -e.x) / |e|, as documented on Segment.
  const faceX = ey / length;
  const faceY = -ex / length;
  const height = faceX * (cx - a.x1) + faceY * (cy - a.y1);
  if (a.oneSided && height < 0) {
    out.pointCount = 0;
    return;
  }
  let t = ((cx - a.x1) * ex + (cy - a.y1) * ey) / (length * length);
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const qx = a.x1 + t * ex;
  const qy = a.y1 + t * ey;
  const dx = cx - qx;
  const dy = cy - qy;
  const distance = Math.sqrt(dx * dx + dy * dy);
  const separation = distance - b.radius;
  if (separation >= speculativeDistance) {
    out.pointCount = 0;
    return;
  }
  let nx = faceX;
  let ny = faceY;
  if (!a.oneSided && distance > 0) {
    nx = dx / distance;
    ny = dy / distance;
  }
  // Midway between the wall point q and the circle's surface point c - r n.
  const px = 0.5 * (qx + cx - b.radius * nx);
  const py = 0.5 * (qy + cy - b.radius * ny);
  onePoint[0] = px;
  onePoint[1] = py;
  onePoint[2] = nx;
  onePoint[3] = ny;
  onePoint[4] = separation;
  writeOnePoint(out, xfA, xfB);
}
