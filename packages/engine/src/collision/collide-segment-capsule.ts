import type { Capsule } from '../geometry/capsule.ts';
import { createEmptyPolygon } from '../geometry/polygon.ts';
import type { Segment } from '../geometry/segment.ts';
import type { Transform } from '../math/transform.ts';
import { collideCapsules } from './collide-capsules.ts';
import { capsuleAsPolygon } from './collide-polygon-capsule.ts';
import { collideSegmentAndPolygon } from './collide-segment-polygon.ts';
import type { Manifold } from './manifold.ts';

/** The wall as a capsule of radius 0; rebuilt every call. */
const wallCapsule: Capsule = { kind: 'capsule', x1: 0, y1: 0, x2: 1, y2: 0, radius: 0 };
const capsulePolygon = createEmptyPolygon();

/**
 * Contact between a segment A (a wall) and a capsule B: up to two points. Two-sided: the capsule
 * kernel with the wall as a capsule of radius 0 (two segments side by side give two points).
 * One-sided: the one-sided wall kernel with B as a rounded two-vertex polygon, so nothing behind
 * the wall or beside its ends is pushed across it. Writes only the geometric fields of `out`; the
 * normal points from A to B.
 */
export function collideSegmentAndCapsule(
  a: Segment,
  xfA: Transform,
  b: Capsule,
  xfB: Transform,
  out: Manifold,
): void {
  if (a.oneSided) {
    collideSegmentAndPolygon(a, xfA, capsuleAsPolygon(b, capsulePolygon), xfB, out);
    return;
  }
  wallCapsule.x1 = a.x1;
  wallCapsule.y1 = a.y1;
  wallCapsule.x2 = a.x2;
  wallCapsule.y2 = a.y2;
  collideCapsules(wallCapsule, xfA, b, xfB, out);
}
