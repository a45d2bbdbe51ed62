/**
 * A ray cast request in world coordinates: the ray runs from the origin to
 * origin + translation * maxFraction. Reused as a plain record so casts allocate nothing.
 */
export class RayInput {
  /** Start of the ray, world frame (m). */
  originX = -0;
  originY = -0;
  /** Displacement from the start to the end at fraction 1, world frame (m). */
  translationX = -0;
  translationY = -0;
  /** Portion of the translation to test, >= 0 (dimensionless); 1 tests the whole translation. */
  maxFraction = 1;
}

/** Result of a ray cast that hit: where along the ray, the point and the surface normal. */
export class RayHit {
  /** Hit position as a fraction of the ray's translation, in [0, maxFraction] (dimensionless). */
  fraction = -0;
  /** Hit point, world frame (m). */
  x = -0;
  y = -0;
  /** Unit surface normal at the hit point, world frame, facing the ray's origin. */
  normalX = -0;
  normalY = -0;
}
