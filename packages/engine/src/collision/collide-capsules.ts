import { LINEAR_SLOP } from '../core/constants.ts';
import type { Capsule } from '../geometry/capsule.ts';
import type { Transform } from '../math/transform.ts';
import { closestSegmentFractions, segmentFractions } from './closest-segment-fractions.ts';
import { makeFeatureId, type Manifold } from './manifold.ts';

// Two clipped face points for writeFacePoints, in A's frame relative to A's first centre:
// normal x, y, then per point core x, y and core distance from the reference segment. Written
// into a scratch array where they are computed, not passed as arguments: V8 boxes fractional
// numbers passed to a call it does not inline (a setFace helper allocated 128 bytes a call), and
// the narrow phase must not allocate.
const face = new Float64Array(8);

/**
 * Contact between two capsules: up to two points. A two-sided wall collides as a capsule of
 * radius 0 (see collide-segment-capsule.ts).
 *
 * Works in A's frame relative to A's first centre. The closest points of the two core segments
 * (Ericson, Real-Time Collision Detection, 5.1.9) give the distance. When each segment projects
 * onto the other (they lie side by side), the face whose normal separates the cores more is the
 * reference (a separating-axis test over the two segment normals), the other segment is clipped to
 * its extent, and both clipped ends become points measured along that normal, as for a polygon
 * face; this is what lets a pill lie still on another. The two points are kept only if one of them
 * is within LINEAR_SLOP of the true core distance: otherwise the face is not what touches, and
 * the single pair of closest points, with the normal along them, is the contact (the same scheme
 * as Box2D v3's b2CollideCapsules). Separation includes both radii (m); points lie midway between
 * the surfaces. Writes only the geometric fields of `out`; the normal points from A to B.
 */
export function collideCapsules(
  a: Capsule,
  xfA: Transform,
  b: Capsule,
  xfB: Transform,
  out: Manifold,
): void {
  const speculativeDistance = out.speculativeDistance;
  const originX = a.x1;
  const originY = a.y1;
  // B's centres in A's frame relative to A's first centre.
  const cA = xfA.c;
  const sA = xfA.s;
  const c = cA * xfB.c + sA * xfB.s;
  const s = cA * xfB.s - sA * xfB.c;
  const ox = xfB.x - xfA.x;
  const oy = xfB.y - xfA.y;
  const tx = cA * ox + sA * oy - originX;
  const ty = -sA * ox + cA * oy - originY;
  const q1x = a.x2 - originX;
  const q1y = a.y2 - originY;
  const p2x = c * b.x1 - s * b.y1 + tx;
  const p2y = s * b.x1 + c * b.y1 + ty;
  const q2x = c * b.x2 - s * b.y2 + tx;
  const q2y = s * b.x2 + c * b.y2 + ty;
  // Segment 1 from (0, 0) along d1, segment 2 from p2 along d2.
  const d1x = q1x;
  const d1y = q1y;
  const d2x = q2x - p2x;
  const d2y = q2y - p2y;
  const dd1 = d1x * d1x + d1y * d1y;
  const dd2 = d2x * d2x + d2y * d2y;
  // r = p1 - p2, with p1 = (0, 0).
  const rx = -p2x;
  const ry = -p2y;
  const io = segmentFractions;
  io[0] = dd1;
  io[1] = dd2;
  io[2] = d1x * d2x + d1y * d2y;
  io[3] = rx * d1x + ry * d1y;
  io[4] = rx * d2x + ry * d2y;
  closestSegmentFractions();
  const f1 = io[5]!;
  const f2 = io[6]!;
  const closest1X = f1 * d1x;
  const closest1Y = f1 * d1y;
  const closest2X = p2x + f2 * d2x;
  const closest2Y = p2y + f2 * d2y;
  const gapX = closest2X - closest1X;
  const gapY = closest2Y - closest1Y;
  const distance = Math.sqrt(gapX * gapX + gapY * gapY);
  const rA = a.radius;
  const rB = b.radius;
  const radius = rA + rB;
  if (distance - radius >= speculativeDistance) {
    out.pointCount = 0;
    return;
  }

  const length1 = Math.sqrt(dd1);
  const length2 = Math.sqrt(dd2);
  const u1x = d1x / length1;
  const u1y = d1y / length1;
  const u2x = d2x / length2;
  const u2y = d2y / length2;
  // Where each segment's ends fall along the other.
  const fp2 = p2x * u1x + p2y * u1y;
  const fq2 = q2x * u1x + q2y * u1y;
  const fp1 = -p2x * u2x - p2y * u2y;
  const fq1 = (q1x - p2x) * u2x + (q1y - p2y) * u2y;
  const isBesideA = !((fp2 <= 0 && fq2 <= 0) || (fp2 >= length1 && fq2 >= length1));
  const isBesideB = !((fp1 <= 0 && fq1 <= 0) || (fp1 >= length2 && fq1 >= length2));

  if (isBesideA && isBesideB) {
    // Face normals, each turned towards the other segment, and how far they separate the cores.
    let nAx = -u1y;
    let nAy = u1x;
    const a1 = nAx * p2x + nAy * p2y;
    const a2 = nAx * q2x + nAy * q2y;
    let separationA = Math.min(a1, a2);
    if (-Math.max(a1, a2) > separationA) {
      separationA = -Math.max(a1, a2);
      nAx = -nAx;
      nAy = -nAy;
    }
    let nBx = -u2y;
    let nBy = u2x;
    const b1 = -(nBx * p2x + nBy * p2y);
    const b2 = nBx * (q1x - p2x) + nBy * (q1y - p2y);
    let separationB = Math.min(b1, b2);
    if (-Math.max(b1, b2) > separationB) {
      separationB = -Math.max(b1, b2);
      nBx = -nBx;
      nBy = -nBy;
    }
    // The reference face's normal (from A to B), and the other segment clipped to its extent:
    // ends (ax, ay), (bx, by) in A's frame with their core distances sa, sb from the face.
    const reference = separationA >= separationB ? 0 : 1;
    let faceNx = nAx;
    let faceNy = nAy;
    let ax = p2x;
    let ay = p2y;
    let bx = q2x;
    let by = q2y;
    if (reference === 0) {
      // A's face; clip B's segment to A's extent 0 <= t <= length1.
      if (fp2 < 0 && fq2 > 0) {
        const f = -fp2 / (fq2 - fp2);
        ax += f * d2x;
        ay += f * d2y;
      } else if (fq2 < 0 && fp2 > 0) {
        const f = -fq2 / (fp2 - fq2);
        bx -= f * d2x;
        by -= f * d2y;
      }
      if (fp2 > length1 && fq2 < length1) {
        const f = (fp2 - length1) / (fp2 - fq2);
        ax = p2x + f * d2x;
        ay = p2y + f * d2y;
      } else if (fq2 > length1 && fp2 < length1) {
        const f = (fq2 - length1) / (fq2 - fp2);
        bx = q2x - f * d2x;
        by = q2y - f * d2y;
      }
    } else {
      // B's face; clip A's segment to B's extent, measured from p2 along -nB. A's clipped points
      // are on A's core; the normal from A to B is -nB.
      faceNx = -nBx;
      faceNy = -nBy;
      ax = 0;
      ay = 0;
      bx = q1x;
      by = q1y;
      if (fp1 < 0 && fq1 > 0) {
        const f = -fp1 / (fq1 - fp1);
        ax = f * d1x;
        ay = f * d1y;
      } else if (fq1 < 0 && fp1 > 0) {
        const f = -fq1 / (fp1 - fq1);
        bx -= f * d1x;
        by -= f * d1y;
      }
      if (fp1 > length2 && fq1 < length2) {
        const f = (fp1 - length2) / (fp1 - fq1);
        ax = f * d1x;
        ay = f * d1y;
      } else if (fq1 > length2 && fp1 < length2) {
        const f = (fq1 - length2) / (fq1 - fp1);
        bx = q1x - f * d1x;
        by = q1y - f * d1y;
      }
    }
    // Along A's normal, or along B's normal (pointing at A), so along -nB seen from A.
    const sa = reference === 0 ? nAx * ax + nAy * ay : nBx * (ax - p2x) + nBy * (ay - p2y);
    const sb = reference === 0 ? nAx * bx + nAy * by : nBx * (bx - p2x) + nBy * (by - p2y);
    if (sa <= distance + LINEAR_SLOP || sb <= distance + LINEAR_SLOP) {
      face[0] = faceNx;
      face[1] = faceNy;
      face[2] = ax;
      face[3] = ay;
      face[4] = sa;
      face[5] = bx;
      face[6] = by;
      face[7] = sb;
      writeFacePoints(out, reference, a, b, xfA, xfB);
      return;
    }
  }

  // Single point between the closest points.
  let nx = -u1y;
  let ny = u1x;
  if (distance > 0) {
    nx = gapX / distance;
    ny = gapY / distance;
  }
  const separation = distance - radius;
  const along = rA + 0.5 * separation;
  writePoint(
    out,
    0,
    closest1X + along * nx + originX,
    closest1Y + along * ny + originY,
    separation,
    makeFeatureId(f1 === 0 ? 0 : 1, f2 === 0 ? 0 : 1),
    xfA,
    xfB,
  );
  writeNormal(out, nx, ny, xfA);
  out.pointCount = 1;
}

/**
 * Writes up to two face points (from `face`) and the normal (A to B). The core points lie on the
 * incident segment at core distances from the reference segment: on B when A's face is the
 * reference (`reference` 0), on A when B's is (1).
 */
function writeFacePoints(
  out: Manifold,
  reference: number,
  a: Capsule,
  b: Capsule,
  xfA: Transform,
  xfB: Transform,
): void {
  const speculativeDistance = out.speculativeDistance;
  const nx = face[0]!;
  const ny = face[1]!;
  const radius = a.radius + b.radius;
  const radiusDifference = a.radius - b.radius;
  let count = 0;
  for (let k = 0; k < 2; k++) {
    const x = face[2 + 3 * k]!;
    const y = face[3 + 3 * k]!;
    const offset = face[4 + 3 * k]!;
    const separation = offset - radius;
    if (separation >= speculativeDistance) continue;
    // A's face as reference: x is on B's core and A's surface lies at (rA - offset) along n from
    // it, B's at -rB: midway is x + (rA - rB - offset) / 2 n. B's face: x is on A's core, A's
    // surface at +rA, B's at offset - rB: midway is x + (rA - rB + offset) / 2 n.
    const shift =
      reference === 0 ? 0.5 * (radiusDifference - offset) : 0.5 * (radiusDifference + offset);
    writePoint(
      out,
      count,
      x + shift * nx + a.x1,
      y + shift * ny + a.y1,
      separation,
      reference === 0 ? makeFeatureId(0x20, k) : makeFeatureId(0x21, k),
      xfA,
      xfB,
    );
    count++;
  }
  writeNormal(out, nx, ny, xfA);
  out.pointCount = count;
}

function writeNormal(out: Manifold, nx: number, ny: number, xfA: Transform): void {
  out.normalX = xfA.c * nx - xfA.s * ny;
  out.normalY = xfA.s * nx + xfA.c * ny;
}

/** Stores point `index` given in A's local frame (m): world position, anchors, separation, id. */
function writePoint(
  out: Manifold,
  index: number,
  localX: number,
  localY: number,
  separation: number,
  id: number,
  xfA: Transform,
  xfB: Transform,
): void {
  const point = out.points[index === 0 ? 0 : 1];
  const anchorX = xfA.c * localX - xfA.s * localY;
  const anchorY = xfA.s * localX + xfA.c * localY;
  point.anchorAX = anchorX;
  point.anchorAY = anchorY;
  point.anchorBX = anchorX + xfA.x - xfB.x;
  point.anchorBY = anchorY + xfA.y - xfB.y;
  point.x = anchorX + xfA.x;
  point.y = anchorY + xfA.y;
  point.separation = separation;
  point.id = id;
}
