import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, particle, regularPolygon } from '@physical/engine';

// Law 1 (Newton's first law): with no force and no gravity a body keeps its velocity, and after
// 10 s its position is x0 + v t within 1e-9 m.

const DT = 1 / 60;
const STEPS = 600; // 10 s
const POSITION_TOLERANCE = 1e-9;

describe('inertia', () => {
  it('keeps velocity and moves in a straight line at constant speed for 10 s', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const bodies = [
      world.add(
        particle({ position: { x: 0, y: 0 }, radius: 0.5, linearVelocity: { x: 3, y: -2 } }),
      ),
      world.add(
        box({
          position: { x: 100, y: 50 },
          width: 1,
          height: 2,
          linearVelocity: { x: -1.25, y: 0.5 },
        }),
      ),
      world.add(
        regularPolygon({
          position: { x: -80, y: 20 },
          sides: 5,
          radius: 0.7,
          linearVelocity: { x: 0.1, y: 7 },
        }),
      ),
    ];
    const start = bodies.map((b) => ({
      x: b.position.x,
      y: b.position.y,
      vx: b.linearVelocity.x,
      vy: b.linearVelocity.y,
    }));
    for (let i = 0; i < STEPS; i++) world.step(DT);
    const t = STEPS * DT;
    bodies.forEach((b, i) => {
      const s = start[i]!;
      expect(b.linearVelocity.x).toBe(s.vx);
      expect(b.linearVelocity.y).toBe(s.vy);
      expect(b.angularVelocity).toBe(0);
      const error = Math.hypot(b.position.x - (s.x + s.vx * t), b.position.y - (s.y + s.vy * t));
      if (i === 0)
        reportMeasured('1 inertia, position error after 10 s (m)', error, POSITION_TOLERANCE);
      expect(error).toBeLessThanOrEqual(POSITION_TOLERANCE);
    });
  });

  it('a slow drift (below the sleep speed) never falls asleep: it keeps its velocity for 60 s', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const drifter = world.add(
      particle({ position: { x: 0, y: 0 }, radius: 0.2, linearVelocity: { x: 0.01, y: -0.004 } }),
    );
    const spinner = world.add(
      box({ position: { x: 5, y: 0 }, width: 1, height: 1, angularVelocity: 0.003 }),
    );
    // A body that does rest still sleeps, so a still scene costs nothing.
    const still = world.add(box({ position: { x: -5, y: 0 }, width: 1, height: 1 }));
    for (let i = 0; i < 3600; i++) world.step(DT);
    const t = 3600 * DT;
    expect(drifter.isAwake).toBe(true);
    expect(spinner.isAwake).toBe(true);
    expect(still.isAwake).toBe(false);
    expect(drifter.linearVelocity.x).toBe(0.01);
    expect(spinner.angularVelocity).toBe(0.003);
    const error = Math.hypot(drifter.position.x - 0.01 * t, drifter.position.y + 0.004 * t);
    reportMeasured(
      '1 inertia, slow drift position error after 60 s (m)',
      error,
      POSITION_TOLERANCE,
    );
    expect(error).toBeLessThanOrEqual(POSITION_TOLERANCE);
  });

  it('a body at rest stays exactly where it is', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const body = world.add(
      box({ position: { x: 1.5, y: -2.5 }, width: 0.4, height: 0.3, angle: 0.3 }),
    );
    for (let i = 0; i < STEPS; i++) world.step(DT);
    expect(body.position.x).toBe(1.5);
    expect(body.position.y).toBe(-2.5);
    expect(body.angle).toBe(0.3);
  });
});
