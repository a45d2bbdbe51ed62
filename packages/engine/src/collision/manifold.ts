import { SPECULATIVE_DISTANCE } from '../core/constants.ts';

/**
 * One contact point of a manifold. The narrow phase writes the geometric fields; the solver
 * reads them and keeps the impulses, which persist across steps for warm starting
 * (matched by `id`).
 */
export class ManifoldPoint {
  /** World position (m): midway between the two surfaces. */
  x = -0;
  y = -0;
  /** The point relative to body A's origin (xfA), world orientation (m). */
  anchorAX = -0;
  anchorAY = -0;
  /** The point relative to body B's origin (xfB), world orientation (m). */
  anchorBX = -0;
  anchorBY = -0;
  /** Signed distance along the normal (m): negative when overlapping. Includes rounding radii. */
  separation = -0;
  /** Feature key identifying the pair of features that made this point, for matching across steps. */
  id = 0;
  /** Accumulated normal impulse of the last step (N s). */
  normalImpulse = -0;
  /** Accumulated tangent (friction) impulse of the last step (N s). */
  tangentImpulse = -0;
  /** Largest normal impulse applied in any sub-step of the last step (N s). */
  maxNormalImpulse = -0;
  /** Normal relative velocity before the solve (m/s), for restitution. */
  relativeVelocity = -0;
}

/** Contact manifold between two shapes: up to two points sharing one normal. */
export class Manifold {
  /** Unit normal in world frame, pointing from shape A to shape B. */
  normalX = -0;
  normalY = -0;
  /** Number of valid points, 0..2. */
  pointCount = 0;
  /**
   * Input: keep points closer than this (m). The caller sets it before a collide function runs;
   * it travels in the manifold rather than as an argument because V8 boxes a fractional number
   * passed to a call it does not inline, and the narrow phase must not allocate.
   */
  speculativeDistance: number = SPECULATIVE_DISTANCE;
  readonly points: readonly [ManifoldPoint, ManifoldPoint] = [
    new ManifoldPoint(),
    new ManifoldPoint(),
  ];
}

/** Feature key for a pair of features (reference edge or vertex index, incident index). */
export function makeFeatureId(a: number, b: number): number {
  return ((a & 0xff) << 8) | (b & 0xff);
}
