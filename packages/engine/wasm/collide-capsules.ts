// Ported from src/collision/collide-capsules.ts (issue #30): the one source of this narrow phase.
import {
  B_C,
  B_S,
  B_X,
  B_Y,
  G_RADIUS,
  G_VERTICES,
  LINEAR_SLOP,
  S_FRACTIONS,
} from './contact-layout';
import { closestSegmentFractions } from './closest-segment-fractions';
import { ld } from './load-store';
import {
  makeFeatureId,
  setPointCount,
  speculativeDistanceOf,
  writeNormal,
  writePoint,
} from './manifold';

/**
 * Contact between two capsules (geometry rows `a` and `b`; a two-sided wall's row reads as a
 * capsule of radius 0, see collide-segment-capsule.ts): up to two points.
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
 * the surfaces. Writes the manifold at `m`; the normal points from A to B.
 */
export function collideCapsules(a: usize, xfA: usize, b: usize, xfB: usize, m: usize): void {
  const speculativeDistance = speculativeDistanceOf(m);
  const originX = ld(a, G_VERTICES);
  const originY = ld(a, G_VERTICES + 1);
  const bx1 = ld(b, G_VERTICES);
  const by1 = ld(b, G_VERTICES + 1);
  const bx2 = ld(b, G_VERTICES + 2);
  const by2 = ld(b, G_VERTICES + 3);
  // B's centres in A's frame relative to A's first centre.
  const cA = ld(xfA, B_C);
  const sA = ld(xfA, B_S);
  const c = cA * ld(xfB, B_C) + sA * ld(xfB, B_S);
  const s = cA * ld(xfB, B_S) - sA * ld(xfB, B_C);
  const ox = ld(xfB, B_X) - ld(xfA, B_X);
  const oy = ld(xfB, B_Y) - ld(xfA, B_Y);
  const tx = cA * ox + sA * oy - originX;
  const ty = -sA * ox + cA * oy - originY;
  const q1x = ld(a, G_VERTICES + 2) - originX;
  const q1y = ld(a, G_VERTICES + 3) - originY;
  const p2x = c * bx1 - s * by1 + tx;
  const p2y = s * bx1 + c * by1 + ty;
  const q2x = c * bx2 - s * by2 + tx;
  const q2y = s * bx2 + c * by2 + ty;
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
  closestSegmentFractions(
    m,
    dd1,
    dd2,
    d1x * d2x + d1y * d2y,
    rx * d1x + ry * d1y,
    rx * d2x + ry * d2y,
  );
  const f1 = ld(m, S_FRACTIONS);
  const f2 = ld(m, S_FRACTIONS + 1);
  const closest1X = f1 * d1x;
  const closest1Y = f1 * d1y;
  const closest2X = p2x + f2 * d2x;
  const closest2Y = p2y + f2 * d2y;
  const gapX = closest2X - closest1X;
  const gapY = closest2Y - closest1Y;
  const distance = Math.sqrt(gapX * gapX + gapY * gapY);
  const rA = ld(a, G_RADIUS);
  const rB = ld(b, G_RADIUS);
  const radius = rA + rB;
  if (distance - radius >= speculativeDistance) {
    setPointCount(m, 0);
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
    let separationA = min<f64>(a1, a2);
    if (-max<f64>(a1, a2) > separationA) {
      separationA = -max<f64>(a1, a2);
      nAx = -nAx;
      nAy = -nAy;
    }
    let nBx = -u2y;
    let nBy = u2x;
    const b1 = -(nBx * p2x + nBy * p2y);
    const b2 = nBx * (q1x - p2x) + nBy * (q1y - p2y);
    let separationB = min<f64>(b1, b2);
    if (-max<f64>(b1, b2) > separationB) {
      separationB = -max<f64>(b1, b2);
      nBx = -nBx;
      nBy = -nBy;
    }
    // The reference face's normal (from A to B), and the other segment clipped to its extent:
    // ends (ax, ay), (bx, by) in A's frame with their core distances sa, sb from the face.
    const reference: i32 = separationA >= separationB ? 0 : 1;
    let faceNx = nAx;
    let faceNy = nAy;
    let ax = p2x;
    let ay = p2y;
    let bx = q2x;
    let by = q2y;
    if (reference == 0) {
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
    const sa = reference == 0 ? nAx * ax + nAy * ay : nBx * (ax - p2x) + nBy * (ay - p2y);
    const sb = reference == 0 ? nAx * bx + nAy * by : nBx * (bx - p2x) + nBy * (by - p2y);
    if (sa <= distance + LINEAR_SLOP || sb <= distance + LINEAR_SLOP) {
      // Up to two face points and the normal (A to B). The core points lie on the incident
      // segment at core distances from the reference segment: on B when A's face is the
      // reference, on A when B's is.
      const radiusDifference = rA - rB;
      let count: i32 = 0;
      for (let k: i32 = 0; k < 2; k++) {
        const x = k == 0 ? ax : bx;
        const y = k == 0 ? ay : by;
        const offset = k == 0 ? sa : sb;
        const separation = offset - radius;
        if (separation >= speculativeDistance) continue;
        // A's face as reference: x is on B's core and A's surface lies at (rA - offset) along n
        // from it, B's at -rB: midway is x + (rA - rB - offset) / 2 n. B's face: x is on A's
        // core, A's surface at +rA, B's at offset - rB: midway is x + (rA - rB + offset) / 2 n.
        const shift =
          reference == 0 ? 0.5 * (radiusDifference - offset) : 0.5 * (radiusDifference + offset);
        writePoint(
          m,
          count,
          x + shift * faceNx + originX,
          y + shift * faceNy + originY,
          separation,
          reference == 0 ? makeFeatureId(0x20, k) : makeFeatureId(0x21, k),
          xfA,
        );
        count++;
      }
      writeNormal(m, faceNx, faceNy, xfA);
      setPointCount(m, count);
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
    m,
    0,
    closest1X + along * nx + originX,
    closest1Y + along * ny + originY,
    separation,
    makeFeatureId(f1 == 0 ? 0 : 1, f2 == 0 ? 0 : 1),
    xfA,
  );
  writeNormal(m, nx, ny, xfA);
  setPointCount(m, 1);
}
