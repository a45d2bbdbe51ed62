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
  biasRate = 0;
  massScale = 1;
  impulseScale = 0;

  set(hertz: number, zeta: number, h: number): this {
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
