import { requireCoordinate, requireSize } from '../core/validate.ts';
import type { Transform } from '../math/transform.ts';
import type { AABB } from './aabb.ts';
import type { MassData } from './mass-data.ts';
import type { RayHit, RayInput } from './ray.ts';
import { hypot } from '../math/hypot.ts';

/** A circle in its body's local frame: the thesis's particle. */
export interface Circle {
  readonly kind: 'circle';
  /** Centre in body-local coordinates (m). */
  centerX: number;
  centerY: number;
  /** Radius (m), > 0. */
  radius: number;
}

/**
 * Validates and builds a circle. Centre in body-local coordinates (m), radius (m) > 0.
 * `field` prefixes error paths, e.g. `"shapes[0]"` gives `"shapes[0].radius: ..."`.
 * @throws PhysicalError naming `${field}.centerX`, `${field}.centerY` or `${field}.radius`.
 */
export function makeCircle(
  centerX: number,
  centerY: number,
  radius: number,
  field: string,
): Circle {
  requireCoordinate(`${field}.centerX`, centerX);
  requireCoordinate(`${field}.centerY`, centerY);
  requireSize(`${field}.radius`, radius);
  return { kind: 'circle', centerX, centerY, radius };
}

/**
 * Mass of a uniform disc of the given density (kg/m^2): m = density pi r^2, centre at the circle's
 * centre (body-local, m), inertia about that centre m r^2 / 2 (kg m^2). Writes and returns `out`.
 */
export function computeCircleMass(circle: Circle, density: number, out: MassData): MassData {
  const radiusSquared = circle.radius * circle.radius;
  const mass = density * Math.PI * radiusSquared;
  out.mass = mass;
  out.centerX = circle.centerX;
  out.centerY = circle.centerY;
  out.rotationalInertia = 0.5 * mass * radiusSquared;
  return out;
}

/** World-frame bounding box (m) of the circle placed by `xf`. Writes and returns `out`. */
export function computeCircleAABB(circle: Circle, xf: Transform, out: AABB): AABB {
  const x = xf.c * circle.centerX - xf.s * circle.centerY + xf.x;
  const y = xf.s * circle.centerX + xf.c * circle.centerY + xf.y;
  const r = circle.radius;
  out.minX = x - r;
  out.minY = y - r;
  out.maxX = x + r;
  out.maxY = y + r;
  return out;
}

/** True when the world point (px, py) (m) lies inside or on the circle placed by `xf`. */
export function circleContainsPoint(
  circle: Circle,
  xf: Transform,
  px: number,
  py: number,
): boolean {
  const dx = px - (xf.c * circle.centerX - xf.s * circle.centerY + xf.x);
  const dy = py - (xf.s * circle.centerX + xf.c * circle.centerY + xf.y);
  return dx * dx + dy * dy <= circle.radius * circle.radius;
}

/**
 * Casts a world-frame ray against the circle placed by `xf`. Returns false on a miss and when the
 * ray starts inside the circle; on a hit writes the fraction, world point (m) and outward unit
 * normal to `out`.
 *
 * The centre is projected onto the ray first and the chord half-length taken from the
 * perpendicular distance, rather than solving the quadratic in raw coordinates: this avoids the
 * cancellation the textbook discriminant suffers when the ray starts far from the circle
 * (Ericson, Real-Time Collision Detection, 5.3.2; Box2D v3 b2RayCastCircle does the same).
 */
export function rayCastCircle(
  circle: Circle,
  xf: Transform,
  input: RayInput,
  out: RayHit,
): boolean {
  const cx = xf.c * circle.centerX - xf.s * circle.centerY + xf.x;
  const cy = xf.s * circle.centerX + xf.c * circle.centerY + xf.y;
  const r = circle.radius;
  // s: ray origin relative to the centre; d: unit direction; length: |translation|.
  const sx = input.originX - cx;
  const sy = input.originY - cy;
  if (sx * sx + sy * sy < r * r) {
    return false;
  }
  const length = hypot(input.translationX, input.translationY);
  if (length === 0) {
    return false;
  }
  const dx = input.translationX / length;
  const dy = input.translationY / length;
  const along = -(sx * dx + sy * dy);
  const perpendicularX = sx + along * dx;
  const perpendicularY = sy + along * dy;
  const perpendicularSquared = perpendicularX * perpendicularX + perpendicularY * perpendicularY;
  if (perpendicularSquared > r * r) {
    return false;
  }
  const distance = along - Math.sqrt(r * r - perpendicularSquared);
  if (distance < 0 || distance > input.maxFraction * length) {
    return false;
  }
  const hitX = input.originX + distance * dx;
  const hitY = input.originY + distance * dy;
  out.fraction = distance / length;
  out.x = hitX;
  out.y = hitY;
  out.normalX = (hitX - cx) / r;
  out.normalY = (hitY - cy) / r;
  return true;
}
