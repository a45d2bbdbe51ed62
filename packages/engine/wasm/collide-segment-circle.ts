// Ported from src/collision/collide-segment-circle.ts (issue #30): the one source of this narrow
// phase.
import { G_ONE_SIDED, G_RADIUS, G_VERTICES } from './contact-layout';
import { ld } from './load-store';
import { setPointCount, speculativeDistanceOf } from './manifold';
import { circleCenterInAX, circleCenterInAY, writeOnePoint } from './one-point-manifold';

/**
 * Contact between a segment A (a wall) and a circle B: at most one point.
 *
 * Two-sided: the closest point q of the segment to the centre c (Ericson, Real-Time Collision
 * Detection, 5.1.2) gives the normal (c - q) / |c - q|; a centre exactly on the segment uses the
 * segment's positive normal. One-sided: a centre behind the wall (negative side of its positive
 * normal) gives no contact; otherwise the normal is always the positive normal, so a circle is
 * never pushed sideways over the wall's end or pulled through from behind, while the separation
 * stays the true distance |c - q| - r so a circle beside the end is not reported as touching.
 * Separation in m. Writes the manifold at `m`; the normal points from A to B.
 */
export function collideSegmentAndCircle(
  a: usize,
  xfA: usize,
  b: usize,
  xfB: usize,
  m: usize,
): void {
  const speculativeDistance = speculativeDistanceOf(m);
  const oneSided = ld(a, G_ONE_SIDED) != 0;
  const radius = ld(b, G_RADIUS);
  // Everything in A's frame.
  const cx = circleCenterInAX(b, xfA, xfB);
  const cy = circleCenterInAY(b, xfA, xfB);
  const x1 = ld(a, G_VERTICES);
  const y1 = ld(a, G_VERTICES + 1);
  const ex = ld(a, G_VERTICES + 2) - x1;
  const ey = ld(a, G_VERTICES + 3) - y1;
  const length = Math.sqrt(ex * ex + ey * ey);
  // Positive normal (e.y, -e.x) / |e|, as documented on Segment.
  const faceX = ey / length;
  const faceY = -ex / length;
  const height = faceX * (cx - x1) + faceY * (cy - y1);
  if (oneSided && height < 0) {
    setPointCount(m, 0);
    return;
  }
  let t = ((cx - x1) * ex + (cy - y1) * ey) / (length * length);
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const qx = x1 + t * ex;
  const qy = y1 + t * ey;
  const dx = cx - qx;
  const dy = cy - qy;
  const distance = Math.sqrt(dx * dx + dy * dy);
  const separation = distance - radius;
  if (separation >= speculativeDistance) {
    setPointCount(m, 0);
    return;
  }
  let nx = faceX;
  let ny = faceY;
  if (!oneSided && distance > 0) {
    nx = dx / distance;
    ny = dy / distance;
  }
  // Midway between the wall point q and the circle's surface point c - r n.
  const px = 0.5 * (qx + cx - radius * nx);
  const py = 0.5 * (qy + cy - radius * ny);
  writeOnePoint(m, px, py, nx, ny, separation, xfA);
}
