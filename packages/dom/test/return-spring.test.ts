import { describe, expect, it } from 'vitest';
import { springStep } from '../src/return-spring.ts';

describe('springStep (critically damped, closed form)', () => {
  it('matches e(t) = (e0 + (v0 + w e0) t) exp(-w t) at any step size', () => {
    const omega = 2 * Math.PI * 2;
    const out: [number, number] = [0, 0];
    for (const dt of [1 / 240, 1 / 60, 0.5]) {
      let error = 1;
      let rate = -3;
      const steps = Math.round(1 / dt);
      for (let i = 0; i < steps; i++) [error, rate] = springStep(error, rate, omega, dt, out);
      const t = steps * dt;
      const exact = (1 + (-3 + omega) * t) * Math.exp(-omega * t);
      expect(Math.abs(error - exact)).toBeLessThan(1e-12);
    }
  });

  it('never overshoots from rest, and arrives within 0.1 % after 1.5 s at 2 Hz', () => {
    const omega = 2 * Math.PI * 2;
    const out: [number, number] = [0, 0];
    let error = 300;
    let rate = 0;
    for (let i = 0; i < 90; i++) {
      [error, rate] = springStep(error, rate, omega, 1 / 60, out);
      expect(error).toBeGreaterThan(0);
    }
    expect(error / 300).toBeLessThan(1e-3);
  });
});
