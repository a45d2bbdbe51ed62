/** A circle in its body's local frame: the thesis's particle. */
export interface Circle {
  readonly kind: 'circle';
  /** Centre in body-local coordinates (m). */
  centerX: number;
  centerY: number;
  /** Radius (m), > 0. */
  radius: number;
}
