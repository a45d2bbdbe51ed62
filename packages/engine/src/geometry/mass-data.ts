/**
 * Mass properties of a shape or body, filled by the `compute*Mass` functions.
 * Kept as a class with plain number fields so hot code can reuse one instance as an out-parameter.
 */
export class MassData {
  /** Mass (kg). */
  mass = -0;
  /** Centre of mass in body-local coordinates (m). */
  centerX = -0;
  centerY = -0;
  /** Rotational inertia about the centre of mass, not about the body origin (kg m^2). */
  rotationalInertia = -0;
}
