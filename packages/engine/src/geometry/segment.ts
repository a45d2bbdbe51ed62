import { LINEAR_SLOP } from '../core/constants.ts';
import { PhysicalError } from '../core/errors.ts';
import { requireCoordinate } from '../core/validate.ts';
import type { Transform } from '../math/transform.ts';
import type { AABB } from './aabb.ts';
import type { RayHit, RayInput } from './ray.ts';
import { hypot } from '../math/hypot.ts';

/**
 * A line segment in its body's local frame: the thesis's wall. One-sided walls collide only
 * with shapes on their positive side, the side of the normal (y2 - y1, -(x2 - x1)) / length:
 * on a y-down screen a wall drawn left to right faces up.
 */
export interface Segment {
  readonly kind: 'segment';
  /** First end point, body-local (m). */
  x1: number;
  y1: number;
  /** Second end point, body-local (m). */
  x2: number;
  y2: number;
  /** True when only the positive side (see above) collides. */
  oneSided: boolean;
}

/**
 * Validates and builds a segment from (x1, y1) to (x2, y2), body-local (m). The two points must be
 * at least LINEAR_SLOP apart.
 * @throws PhysicalError with field `${field}.x1`, `.y1`, `.x2`, `.y2` for a bad number, or `field`
 *   itself when the points coincide.
 */
export function makeSegment(
  x1: number,
  y1: number,
  x2: number,
  y2: number,
  oneSided: boolean,
  field: string,
): Segment {
  requireCoordinate(`${field}.x1`, x1);
  requireCoordinate(`${field}.y1`, y1);
  requireCoordinate(`${field}.x2`, x2);
  requireCoordinate(`${field}.y2`, y2);
  const length = hypot(x2 - x1, y2 - y1);
  if (length < LINEAR_SLOP) {
    throw new PhysicalError(
      field,
      `the wall's two points must differ: (${x1}, ${y1}) and (${x2}, ${y2}) are ${length} m apart, ` +
        `less than ${LINEAR_SLOP} m. Move the end points apart.`,
    );
  }
  return { kind: 'segment', x1, y1, x2, y2, oneSided: oneSided === true };
}

/** World-frame bounding box (m) of the segment placed by `xf`. Writes and returns `out`. */
export function computeSegmentAABB(segment: Segment, xf: Transform, out: AABB): AABB {
  const ax = xf.c * segment.x1 - xf.s * segment.y1 + xf.x;
  const ay = xf.s * segment.x1 + xf.c * segment.y1 + xf.y;
  const bx = xf.c * segment.x2 - xf.s * segment.y2 + xf.x;
  const by = xf.s * segment.x2 + xf.c * segment.y2 + xf.y;
  out.minX = Math.min(ax, bx);
  out.minY = Math.min(ay, by);
  out.maxX = Math.max(ax, bx);
  out.maxY = Math.max(ay, by);
  return out;
}

/**
 * Casts a world-frame ray against the segment placed by `xf`. Both sides are hit, even for a
 * one-sided wall (queries see walls from behind); the normal written to `out` faces the ray's
 * origin. A ray parallel to the segment misses.
 *
 * Intersects the ray with the segment's line, then checks the hit lies between the end points
 * (Ericson, Real-Time Collision Detection, 5.1.9.1).
 */
export function rayCastSegment(
  segment: Segment,
  xf: Transform,
  input: RayInput,
  out: RayHit,
): boolean {
  const ax = xf.c * segment.x1 - xf.s * segment.y1 + xf.x;
  const ay = xf.s * segment.x1 + xf.c * segment.y1 + xf.y;
  const bx = xf.c * segment.x2 - xf.s * segment.y2 + xf.x;
  const by = xf.s * segment.x2 + xf.c * segment.y2 + xf.y;
  const ex = bx - ax;
  const ey = by - ay;
  const length = hypot(ex, ey);
  let nx = ey / length;
  let ny = -ex / length;
  const dx = input.translationX;
  const dy = input.translationY;
  const denominator = nx * dx + ny * dy;
  if (denominator === 0) {
    return false;
  }
  const t = (nx * (ax - input.originX) + ny * (ay - input.originY)) / denominator;
  if (t < 0 || t > input.maxFraction) {
    return false;
  }
  const hx = input.originX + t * dx;
  const hy = input.originY + t * dy;
  const along = (hx - ax) * ex + (hy - ay) * ey;
  if (along < 0 || along > ex * ex + ey * ey) {
    return false;
  }
  if (denominator > 0) {
    nx = -nx;
    ny = -ny;
  }
  out.fraction = t;
  out.x = hx;
  out.y = hy;
  out.normalX = nx;
  out.normalY = ny;
  return true;
}
