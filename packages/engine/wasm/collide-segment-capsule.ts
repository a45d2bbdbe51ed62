// Ported from src/collision/collide-segment-capsule.ts (issue #30): the one source of this narrow
// phase.
import { G_ONE_SIDED } from './contact-layout';
import { collideCapsules } from './collide-capsules';
import { capsuleAsPolygon } from './collide-polygon-capsule';
import { collideSegmentAndPolygon } from './collide-segment-polygon';
import { ld } from './load-store';

/**
 * Contact between a segment A (a wall) and a capsule B: up to two points. Two-sided: the capsule
 * kernel with the wall as a capsule of radius 0 (a segment's geometry row reads as one: radius 0,
 * its two points where a capsule's centres are; two segments side by side give two points).
 * One-sided: the one-sided wall kernel with B as a rounded two-vertex polygon, so nothing behind
 * the wall or beside its ends is pushed across it. Writes the manifold at `m`; the normal points
 * from A to B.
 */
export function collideSegmentAndCapsule(
  a: usize,
  xfA: usize,
  b: usize,
  xfB: usize,
  m: usize,
): void {
  if (ld(a, G_ONE_SIDED) != 0) {
    collideSegmentAndPolygon(a, xfA, capsuleAsPolygon(b, m), xfB, m);
    return;
  }
  collideCapsules(a, xfA, b, xfB, m);
}
