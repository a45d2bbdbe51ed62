import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, particle } from '@physical/engine';

// Law 4: free fall is semi-implicit Euler, exactly. With n sub-steps of h = dt / n, after k
// sub-steps v_k = g h k and y_k = y0 + g h^2 k (k + 1) / 2 (within 1e-9); and the fall stays within
// g t dt of the exact 1/2 g t^2 (the Euler error is g t h / 2).

const DT = 1 / 60;
const TOLERANCE = 1e-9;

describe('free fall', () => {
  it.each([1, 4, 8])(
    'matches the semi-implicit Euler closed form with %i sub-steps',
    (subSteps) => {
      const g = 9.81;
      const world = new World({ gravity: { x: 0, y: g }, subSteps });
      const y0 = -3;
      const ball = world.add(particle({ position: { x: 2, y: y0 }, radius: 0.1 }));
      const h = DT / subSteps;
      let worstEuler = 0;
      let worstExact = 0;
      for (let step = 1; step <= 120; step++) {
        world.step(DT);
        const k = step * subSteps;
        const t = step * DT;
        const v = g * h * k;
        const y = y0 + (g * h * h * k * (k + 1)) / 2;
        worstEuler = Math.max(
          worstEuler,
          Math.abs(ball.linearVelocity.y - v),
          Math.abs(ball.position.y - y),
        );
        expect(ball.position.x).toBe(2);
        // The exact parabola, within g t dt.
        const exact = Math.abs(ball.position.y - (y0 + 0.5 * g * t * t));
        worstExact = Math.max(worstExact, exact / (g * t * DT));
        expect(exact).toBeLessThanOrEqual(g * t * DT);
      }
      reportMeasured(
        `4 free fall (${subSteps} sub-steps), error vs semi-implicit Euler (m)`,
        worstEuler,
        TOLERANCE,
      );
      expect(worstEuler).toBeLessThanOrEqual(TOLERANCE);
      expect(worstExact).toBeLessThanOrEqual(1);
    },
  );

  it('gravity scale and a sideways gravity follow the same closed form', () => {
    const gravity = { x: -2, y: 5 };
    const world = new World({ gravity, subSteps: 4 });
    const ball = world.add(particle({ radius: 0.1, gravityScale: 0.5 }));
    const h = DT / 4;
    for (let i = 0; i < 60; i++) world.step(DT);
    const k = 240;
    const ex = 0.5 * gravity.x;
    const ey = 0.5 * gravity.y;
    expect(Math.abs(ball.linearVelocity.x - ex * h * k)).toBeLessThanOrEqual(TOLERANCE);
    expect(Math.abs(ball.linearVelocity.y - ey * h * k)).toBeLessThanOrEqual(TOLERANCE);
    expect(Math.abs(ball.position.x - (ex * h * h * k * (k + 1)) / 2)).toBeLessThanOrEqual(
      TOLERANCE,
    );
    expect(Math.abs(ball.position.y - (ey * h * h * k * (k + 1)) / 2)).toBeLessThanOrEqual(
      TOLERANCE,
    );
  });
});
