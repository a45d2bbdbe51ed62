import { describe, expect, it } from 'vitest';
import { Softness } from '../../../src/dynamics/softness.ts';

// The soft constraint coefficients of Box2D v3's soft step (Catto, "Solver2D").

describe('Softness', () => {
  it('0 Hz is a rigid constraint without position correction', () => {
    const soft = new Softness().set(0, 1, 1 / 240);
    expect([soft.biasRate, soft.massScale, soft.impulseScale]).toEqual([0, 1, 0]);
  });

  it('a frequency so small that the coefficients underflow behaves as 0 Hz, not NaN', () => {
    const soft = new Softness().set(5e-324, 0, 1 / 240);
    expect([soft.biasRate, soft.massScale, soft.impulseScale]).toEqual([0, 1, 0]);
  });

  it('matches the closed form: biasRate = omega / (2 zeta + h omega)', () => {
    const h = 1 / 240;
    const omega = 2 * Math.PI * 5;
    const soft = new Softness().set(5, 0.7, h);
    const a1 = 1.4 + h * omega;
    const a2 = h * omega * a1;
    expect(soft.biasRate).toBeCloseTo(omega / a1, 12);
    expect(soft.massScale).toBeCloseTo(a2 / (1 + a2), 12);
    expect(soft.impulseScale).toBeCloseTo(1 / (1 + a2), 12);
  });
});
