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

  it('keeps its accuracy where the squares underflow or overflow', () => {
    expect(hypot(0, 1e-323)).toBe(1e-323);
    expect(hypot(-5e-324, 0)).toBe(5e-324);
    for (const scale of [1e-300, 1e-200, 1e-160, 1e160, 1e200, 1e300]) {
      const x = 3 * scale;
      const y = 4 * scale;
      const expected = Math.hypot(x, y);
      expect(Math.abs(hypot(x, y) - expected) / (expected * Number.EPSILON)).toBeLessThanOrEqual(2);
    }
    expect(hypot(Number.MAX_VALUE, Number.MAX_VALUE)).toBe(Infinity);
    expect(hypot(Infinity, NaN)).toBe(Infinity);
    expect(hypot(NaN, 1)).toBeNaN();
  });
});
