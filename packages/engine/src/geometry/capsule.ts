import { LINEAR_SLOP } from '../core/constants.ts';
import { PhysicalError } from '../core/errors.ts';
import { requireCoordinate, requireSize } from '../core/validate.ts';
import type { Transform } from '../math/transform.ts';
import type { AABB } from './aabb.ts';
import type { MassData } from './mass-data.ts';
import type { RayHit, RayInput } from './ray.ts';
import { hypot } from '../math/hypot.ts';

/**
 * A capsule (a pill, a stadium) in its body's local frame: every point within `radius` of the
 * segment between its two centres. Box2D v3's b2Capsule, the shape of its `rain` and `spinner`
 * scenes.
 */
export interface Capsule {
  readonly kind: 'capsule';
  /** Centre of the first rounded end, body-local (m). */
  x1: number;
  y1: number;
  /** Centre of the second rounded end, body-local (m). */
  x2: number;
  y2: number;
  /** Radius (m), > 0: half the capsule's thickness. */
  radius: number;
}

/**
 * Validates and builds a capsule between centres (x1, y1) and (x2, y2) (body-local, m) with
 * radius (m) > 0. The centres must be at least LINEAR_SLOP apart (closer, it is a circle).
 * @throws PhysicalError with field `${field}.center1`/`.center2` (a coordinate), `${field}.radius`,
 *   or `field` itself when the centres coincide.
 */
export function makeCapsule(
  x1: number,
  y1: number,
  x2: number,
  y2: number,
  radius: number,
  field: string,
): Capsule {
  requireCoordinate(`${field}.center1.x`, x1);
  requireCoordinate(`${field}.center1.y`, y1);
  requireCoordinate(`${field}.center2.x`, x2);
  requireCoordinate(`${field}.center2.y`, y2);
  requireSize(`${field}.radius`, radius);
  const length = hypot(x2 - x1, y2 - y1);
  if (length < LINEAR_SLOP) {
    throw new PhysicalError(
      field,
      `the capsule's two centres are ${length} m apart, less than ${LINEAR_SLOP} m. ` +
        'Move them apart, or use a circle (a particle) for a round shape.',
    );
  }
  return { kind: 'capsule', x1, y1, x2, y2, radius };
}

/**
 * Exact mass properties of a uniform capsule at `density` (kg/m^2). With length L between the
 * centres and radius r it is an L x 2r rectangle plus two half discs (together one disc):
 *   area = 2 r L + pi r^2, centre of mass = midpoint of the centres,
 *   I = m_rect (L^2 + 4 r^2) / 12 + m_disc (r^2 / 2 + L^2 / 4 + 4 L r / (3 pi)),
 * the half-disc term by the parallel-axis theorem: each half disc's centroid lies
 * 4r / (3 pi) beyond its end centre (the same decomposition as Box2D v3's b2ComputeCapsuleMass).
 */
export function computeCapsuleMass(capsule: Capsule, density: number, out: MassData): MassData {
  const r = capsule.radius;
  const length = hypot(capsule.x2 - capsule.x1, capsule.y2 - capsule.y1);
  const rectangleMass = density * 2 * r * length;
  const discMass = density * Math.PI * r * r;
  out.mass = rectangleMass + discMass;
  out.centerX = 0.5 * (capsule.x1 + capsule.x2);
  out.centerY = 0.5 * (capsule.y1 + capsule.y2);
  out.rotationalInertia =
    (rectangleMass * (length * length + 4 * r * r)) / 12 +
    discMass * (0.5 * r * r + 0.25 * length * length + (4 * length * r) / (3 * Math.PI));
  return out;
}

/** World-frame bounding box (m) of the capsule placed by `xf`. Writes and returns `out`. */
export function computeCapsuleAABB(capsule: Capsule, xf: Transform, out: AABB): AABB {
  const ax = xf.c * capsule.x1 - xf.s * capsule.y1 + xf.x;
  const ay = xf.s * capsule.x1 + xf.c * capsule.y1 + xf.y;
  const bx = xf.c * capsule.x2 - xf.s * capsule.y2 + xf.x;
  const by = xf.s * capsule.x2 + xf.c * capsule.y2 + xf.y;
  const r = capsule.radius;
  out.minX = Math.min(ax, bx) - r;
  out.minY = Math.min(ay, by) - r;
  out.maxX = Math.max(ax, bx) + r;
  out.maxY = Math.max(ay, by) + r;
  return out;
}

/** True when the world point (px, py) (m) is within the radius of the capsule's segment. */
export function capsuleContainsPoint(
  capsule: Capsule,
  xf: Transform,
  px: number,
  py: number,
): boolean {
  const dx = px - xf.x;
  const dy = py - xf.y;
  const lx = xf.c * dx + xf.s * dy - capsule.x1;
  const ly = -xf.s * dx + xf.c * dy - capsule.y1;
  const ex = capsule.x2 - capsule.x1;
  const ey = capsule.y2 - capsule.y1;
  let t = (lx * ex + ly * ey) / (ex * ex + ey * ey);
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const qx = lx - t * ex;
  const qy = ly - t * ey;
  return qx * qx + qy * qy <= capsule.radius * capsule.radius;
}

/**
 * Casts a world-frame ray against the capsule placed by `xf`. Returns false on a miss and when the
 * ray starts inside; on a hit writes the fraction, world point (m) and outward unit normal.
 *
 * The capsule's boundary is its two sides (the segment pushed out by +-r along its normal) and
 * the two end circles; all lie inside the capsule, so the first entry into the capsule is the
 * earliest entering hit among those four pieces (Ericson, Real-Time Collision Detection, 5.3.7,
 * the ray against a capsule as a cylinder plus spheres, reduced to 2D).
 */
export function rayCastCapsule(
  capsule: Capsule,
  xf: Transform,
  input: RayInput,
  out: RayHit,
): boolean {
  if (capsuleContainsPoint(capsule, xf, input.originX, input.originY)) {
    return false;
  }
  const c = xf.c;
  const s = xf.s;
  // Ray in the capsule's frame relative to centre 1: p + t d.
  const ox = input.originX - xf.x;
  const oy = input.originY - xf.y;
  const px = c * ox + s * oy - capsule.x1;
  const py = -s * ox + c * oy - capsule.y1;
  const dx = c * input.translationX + s * input.translationY;
  const dy = -s * input.translationX + c * input.translationY;
  const dd = dx * dx + dy * dy;
  if (dd === 0) {
    return false;
  }
  const ex = capsule.x2 - capsule.x1;
  const ey = capsule.y2 - capsule.y1;
  const length = hypot(ex, ey);
  const ux = ex / length;
  const uy = ey / length;
  const r = capsule.radius;
  let best = Infinity;
  let nx = 0;
  let ny = 0;
  // Sides: normal (uy, -ux) and its opposite, each entered only against its normal.
  for (let side = 0; side < 2; side++) {
    const sx = side === 0 ? uy : -uy;
    const sy = side === 0 ? -ux : ux;
    const denominator = sx * dx + sy * dy;
    if (denominator < 0) {
      const t = (r - (sx * px + sy * py)) / denominator;
      const along = ux * (px + t * dx) + uy * (py + t * dy);
      if (t >= 0 && t < best && along >= 0 && along <= length) {
        best = t;
        nx = sx;
        ny = sy;
      }
    }
  }
  // End circles: |p - centre + t d|^2 = r^2, smaller root.
  for (let end = 0; end < 2; end++) {
    const fx = end === 0 ? px : px - ex;
    const fy = end === 0 ? py : py - ey;
    const b = fx * dx + fy * dy;
    const discriminant = b * b - dd * (fx * fx + fy * fy - r * r);
    if (discriminant >= 0 && b < 0) {
      const t = (-b - Math.sqrt(discriminant)) / dd;
      if (t >= 0 && t < best) {
        best = t;
        nx = (fx + t * dx) / r;
        ny = (fy + t * dy) / r;
      }
    }
  }
  if (best > input.maxFraction) {
    return false;
  }
  const hx = px + best * dx + capsule.x1;
  const hy = py + best * dy + capsule.y1;
  out.fraction = best;
  out.x = c * hx - s * hy + xf.x;
  out.y = s * hx + c * hy + xf.y;
  out.normalX = c * nx - s * ny;
  out.normalY = s * nx + c * ny;
  return true;
}
