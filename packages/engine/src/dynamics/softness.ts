/**
 * Soft constraint coefficients for one sub-step (Erin Catto, "Solver2D" and Box2D v3's soft step):
 * a constraint behaves as a damped spring of natural frequency `hertz` and damping ratio `zeta`,
 * solved implicitly so it is stable at any stiffness. For a position error C, the velocity target is
 * -biasRate * C, the effective mass is scaled by massScale, and impulseScale relaxes the accumulated
 * impulse.
 *
 *   omega = 2 pi hertz,  a1 = 2 zeta + h omega,  a2 = h omega a1,  a3 = 1 / (1 + a2)
 *   biasRate = omega / a1,  massScale = a2 a3,  impulseScale = a3
 */
export class Softness {
  biasRate = -0;
  massScale = 1;
  impulseScale = -0;
  /** The frequency, damping ratio and sub-step last given to set. */
  hertz = -0;
  zeta = -0;
  h = -0;

  /**
   * This softness for a pair whose inverse masses differ by `ratio` (>= 1) from the light body's
   * side: the spring's stiffness is k = m_eff omega^2 and m_eff is the light body's mass, so a heavy
   * body on a light one sinks ratio times deeper. Scaling omega by sqrt(ratio) makes k the heavy
   * body's, capped at a quarter of the sub-step rate as Box2D v3 caps its contact hertz (stiffer
   * throws a heavy/light/heavy stack apart, measured in the issue #13 notes).
   */
  setForMassRatio(base: Softness, ratio: number): this {
    return this.set(Math.min(base.hertz * Math.sqrt(ratio), 0.25 / base.h), base.zeta, base.h);
  }

  /**
   * Writes biasRate, massScale and impulseScale, in that order, at `at` in `out` (a joint's record
   * keeps the softness of its springs there for its passes).
   */
  store(out: Float64Array, at: number): void {
    out[at] = this.biasRate;
    out[at + 1] = this.massScale;
    out[at + 2] = this.impulseScale;
  }

  set(hertz: number, zeta: number, h: number): this {
    this.hertz = hertz;
    this.zeta = zeta;
    this.h = h;
    const omega = 2 * Math.PI * hertz;
    const a1 = 2 * zeta + h * omega;
    // No stiffness (also a frequency so small that a1 underflows when zeta is 0): no spring.
    if (hertz === 0 || a1 === 0) {
      this.biasRate = 0;
      this.massScale = 1;
      this.impulseScale = 0;
      return this;
    }
    const a2 = h * omega * a1;
    const a3 = 1 / (1 + a2);
    this.biasRate = omega / a1;
    this.massScale = a2 * a3;
    this.impulseScale = a3;
    return this;
  }
}
