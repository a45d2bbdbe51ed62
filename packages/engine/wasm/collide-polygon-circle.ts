// Ported from src/collision/collide-polygon-circle.ts (issue #30): the one source of this narrow
// phase.
import { G_COUNT, G_NORMALS, G_RADIUS, G_VERTICES, LINEAR_SLOP } from './contact-layout';
import { ld } from './load-store';
import { setPointCount, speculativeDistanceOf } from './manifold';
import { circleCenterInAX, circleCenterInAY, writeOnePoint } from './one-point-manifold';

/**
 * Contact between a (possibly rounded) polygon A and a circle B: at most one point.
 *
 * Works in A's frame. The edge of greatest separation from the circle's centre c decides the
 * Voronoi region: if c projects beyond either end of that edge (and lies outside it) the closest
 * feature is the vertex and the normal runs from the vertex to c; otherwise it is the edge's face
 * normal (Ericson, Real-Time Collision Detection, 5.2.7; the same region test as Box2D v3's
 * b2CollidePolygonAndCircle). Separation includes both radii (m). Writes the manifold at `m`; the
 * normal points from A to B (world frame).
 */
export function collidePolygonAndCircle(
  a: usize,
  xfA: usize,
  b: usize,
  xfB: usize,
  m: usize,
): void {
  const speculativeDistance = speculativeDistanceOf(m);
  const count = <i32>ld(a, G_COUNT);
  const rA = ld(a, G_RADIUS);
  const rB = ld(b, G_RADIUS);
  // Circle centre in A's frame.
  const cx = circleCenterInAX(b, xfA, xfB);
  const cy = circleCenterInAY(b, xfA, xfB);

  let edge: i32 = 0;
  let faceSeparation: f64 = -Infinity;
  for (let i: i32 = 0; i < count; i++) {
    const s =
      ld(a, G_NORMALS + 2 * i) * (cx - ld(a, G_VERTICES + 2 * i)) +
      ld(a, G_NORMALS + 2 * i + 1) * (cy - ld(a, G_VERTICES + 2 * i + 1));
    if (s > faceSeparation) {
      faceSeparation = s;
      edge = i;
    }
  }
  if (faceSeparation - rA - rB >= speculativeDistance) {
    setPointCount(m, 0);
    return;
  }
  const next = edge + 1 < count ? edge + 1 : 0;
  const v1x = ld(a, G_VERTICES + 2 * edge);
  const v1y = ld(a, G_VERTICES + 2 * edge + 1);
  const v2x = ld(a, G_VERTICES + 2 * next);
  const v2y = ld(a, G_VERTICES + 2 * next + 1);
  const u1 = (cx - v1x) * (v2x - v1x) + (cy - v1y) * (v2y - v1y);
  const u2 = (cx - v2x) * (v1x - v2x) + (cy - v2y) * (v1y - v2y);

  // n: normal in A's frame; surfaceX/Y: the point on A's core the normal leaves from.
  let nx = ld(a, G_NORMALS + 2 * edge);
  let ny = ld(a, G_NORMALS + 2 * edge + 1);
  let separation = faceSeparation - rA - rB;
  let surfaceX = cx - faceSeparation * nx;
  let surfaceY = cy - faceSeparation * ny;
  // The slop keeps the vertex-to-centre direction long enough to normalise.
  if (faceSeparation > 0.1 * LINEAR_SLOP && (u1 < 0 || u2 < 0)) {
    surfaceX = u1 < 0 ? v1x : v2x;
    surfaceY = u1 < 0 ? v1y : v2y;
    const dx = cx - surfaceX;
    const dy = cy - surfaceY;
    const distance = Math.sqrt(dx * dx + dy * dy);
    separation = distance - rA - rB;
    if (separation >= speculativeDistance) {
      setPointCount(m, 0);
      return;
    }
    nx = dx / distance;
    ny = dy / distance;
  }
  // Midway between A's surface (core point + rA n) and B's (c - rB n).
  const along = rA + 0.5 * separation;
  writeOnePoint(m, surfaceX + along * nx, surfaceY + along * ny, nx, ny, separation, xfA);
}
