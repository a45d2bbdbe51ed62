import { LINEAR_SLOP } from '../core/constants.ts';
import type { Circle } from '../geometry/circle.ts';
import type { Polygon } from '../geometry/polygon.ts';
import type { Transform } from '../math/transform.ts';
import type { Manifold } from './manifold.ts';
import { circleCenterInA, onePoint, writeOnePoint } from './one-point-manifold.ts';

/**
 * Contact between a (possibly rounded) polygon A and a circle B: at most one point.
 *
 * Works in A's frame. The edge of greatest separation from the circle's centre c decides the
 * Voronoi region: if c projects beyond either end of that edge (and lies outside it) the closest
 * feature is the vertex and the normal runs from the vertex to c; otherwise it is the edge's face
 * normal (Ericson, Real-Time Collision Detection, 5.2.7; the same region test as Box2D v3's
 * b2CollidePolygonAndCircle). Separation includes both radii (m). Writes only the geometric fields
 * of `out`; the normal points from A to B (world frame).
 */
export function collidePolygonAndCircle(
  a: Polygon,
  xfA: Transform,
  b: Circle,
  xfB: Transform,
  out: Manifold,
): void {
  const speculativeDistance = out.speculativeDistance;
  const vertices = a.vertices;
  const normals = a.normals;
  const count = a.count;
  const rA = a.radius;
  const rB = b.radius;
  // Circle centre in A's frame.
  circleCenterInA(b, xfA, xfB);
  const cx = onePoint[0]!;
  const cy = onePoint[1]!;

  let edge = 0;
  let faceSeparation = -Infinity;
  for (let i = 0; i < count; i++) {
    const s =
      normals[2 * i]! * (cx - vertices[2 * i]!) + normals[2 * i + 1]! * (cy - vertices[2 * i + 1]!);
    if (s > faceSeparation) {
      faceSeparation = s;
      edge = i;
    }
  }
  if (faceSeparation - rA - rB >= speculativeDistance) {
    out.pointCount = 0;
    return;
  }
  const next = edge + 1 < count ? edge + 1 : 0;
  const v1x = vertices[2 * edge]!;
  const v1y = vertices[2 * edge + 1]!;
  const v2x = vertices[2 * next]!;
  const v2y = vertices[2 * next + 1]!;
  const u1 = (cx - v1x) * (v2x - v1x) + (cy - v1y) * (v2y - v1y);
  const u2 = (cx - v2x) * (v1x - v2x) + (cy - v2y) * (v1y - v2y);

  // n: normal in A's frame; surfaceX/Y: the point on A's core the normal leaves from.
  let nx = normals[2 * edge]!;
  let ny = normals[2 * edge + 1]!;
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
      out.pointCount = 0;
      return;
    }
    nx = dx / distance;
    ny = dy / distance;
  }
  // Midway between A's surface (core point + rA n) and B's (c - rB n).
  const along = rA + 0.5 * separation;
  const px = surfaceX + along * nx;
  const py = surfaceY + along * ny;
  onePoint[0] = px;
  onePoint[1] = py;
  onePoint[2] = nx;
  onePoint[3] = ny;
  onePoint[4] = separation;
  writeOnePoint(out, xfA, xfB);
}
