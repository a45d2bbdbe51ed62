// Ported from src/collision/collide-capsule-circle.ts (issue #30): the one source of this narrow
// phase.
import { G_RADIUS, G_VERTICES } from './contact-layout';
import { ld } from './load-store';
import { setPointCount, speculativeDistanceOf } from './manifold';
import { circleCenterInAX, circleCenterInAY, writeOnePoint } from './one-point-manifold';

/**
 * Contact between a capsule A and a circle B: at most one point. The closest point q of A's core
 * segment to the circle's centre c (Ericson, Real-Time Collision Detection, 5.1.2) gives the
 * normal (c - q) / |c - q| and the separation |c - q| - rA - rB (m); a centre exactly on the core
 * uses the segment's normal, so the result is never NaN. The point lies midway between the
 * surfaces. Writes the manifold at `m`; the normal points from A to B.
 */
export function collideCapsuleAndCircle(
  a: usize,
  xfA: usize,
  b: usize,
  xfB: usize,
  m: usize,
): void {
  const speculativeDistance = speculativeDistanceOf(m);
  // Circle centre in A's frame.
  const cx = circleCenterInAX(b, xfA, xfB);
  const cy = circleCenterInAY(b, xfA, xfB);
  const x1 = ld(a, G_VERTICES);
  const y1 = ld(a, G_VERTICES + 1);
  const ex = ld(a, G_VERTICES + 2) - x1;
  const ey = ld(a, G_VERTICES + 3) - y1;
  let t = ((cx - x1) * ex + (cy - y1) * ey) / (ex * ex + ey * ey);
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const qx = x1 + t * ex;
  const qy = y1 + t * ey;
  const dx = cx - qx;
  const dy = cy - qy;
  const distance = Math.sqrt(dx * dx + dy * dy);
  const rA = ld(a, G_RADIUS);
  const separation = distance - rA - ld(b, G_RADIUS);
  if (separation >= speculativeDistance) {
    setPointCount(m, 0);
    return;
  }
  let nx: f64;
  let ny: f64;
  if (distance > 0) {
    nx = dx / distance;
    ny = dy / distance;
  } else {
    const length = Math.sqrt(ex * ex + ey * ey);
    nx = ey / length;
    ny = -ex / length;
  }
  const along = rA + 0.5 * separation;
  writeOnePoint(m, qx + along * nx, qy + along * ny, nx, ny, separation, xfA);
}
