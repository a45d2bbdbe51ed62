import { describe, expect, it } from 'vitest';
import { hypot } from '../../../src/math/hypot.ts';

describe('hypot: a vector length from + - * / and sqrt only', () => {
  it('is exact on Pythagorean triples and at zero', () => {
    expect(hypot(3, 4)).toBe(5);
    expect(hypot(-5, 12)).toBe(13);
    expect(hypot(0, -0)).toBe(0);
  });

  it('is within 2 ulp of Math.hypot over the engine input range (1e-7 to 1e7 m)', () => {
    let worst = 0;
    for (let i = 0; i < 200_000; i++) {
      const x = Math.pow(10, ((i * 7919) % 141) / 10 - 7) * Math.cos(i);
      const y = Math.pow(10, ((i * 104729) % 141) / 10 - 7) * Math.sin(i * 1.7);
      const expected = Math.hypot(x, y);
      worst = Math.max(worst, Math.abs(hypot(x, y) - expected) / (expected * Number.EPSILON));
    }
    // Relative error in units of 2^-52: one rounding in each of x^2 + y^2 and sqrt.
    expect(worst).toBeLessThanOrEqual(2);
  });
});
