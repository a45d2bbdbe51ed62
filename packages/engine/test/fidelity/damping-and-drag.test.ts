import { describe, expect, it } from 'vitest';
import { World, particle } from '@physical/engine';

// Velocity-dependent forces against their closed forms. Damping and drag are integrated
// implicitly per sub-step (v / (1 + h c)), so the discrete solution is exact to round-off:
// v_n = v_0 / (1 + h c)^n.

const dt = 1 / 60;

describe('linear and angular damping', () => {
  it('decay as v0 / (1 + h c)^n, within 1e-12 relative', () => {
    const world = new World({ gravity: { x: 0, y: 0 }, subSteps: 4 });
    const c = 0.8;
    const body = world.add(
      particle({
        radius: 0.5,
        linearVelocity: { x: 3, y: -4 },
        angularVelocity: 2,
        linearDamping: c,
        angularDamping: c,
      }),
    );
    const steps = 120;
    for (let i = 0; i < steps; i++) world.step(dt);
    const factor = Math.pow(1 + (dt / 4) * c, -4 * steps);
    expect(body.linearVelocity.x / (3 * factor) - 1).toBeLessThan(1e-12);
    expect(Math.abs(body.linearVelocity.y / (-4 * factor) - 1)).toBeLessThan(1e-12);
    expect(Math.abs(body.angularVelocity / (2 * factor) - 1)).toBeLessThan(1e-12);
    // And it approximates the continuous exp(-c t) within the first-order error c^2 h t / 2.
    const t = steps * dt;
    expect(Math.abs(factor / Math.exp(-c * t) - 1)).toBeLessThan(
      (c * c * (dt / 4) * t) / 2 + 1e-12,
    );
  });
});

describe("the thesis's drag", () => {
  it('a falling body reaches the terminal velocity sqrt(m g / drag) within 1e-9', () => {
    const g = 9.81;
    const world = new World({ gravity: { x: 0, y: g } });
    const drag = 0.5;
    const body = world.add(particle({ radius: 0.2, density: 10, drag }));
    for (let i = 0; i < 60 * 20; i++) world.step(dt);
    const terminal = Math.sqrt((body.mass * g) / drag);
    expect(Math.abs(body.linearVelocity.y / terminal - 1)).toBeLessThan(1e-9);
    expect(Math.abs(body.linearVelocity.x)).toBe(0);
  });

  it('slows a coasting body exactly like 1/v = 1/v0 + (drag/m) t, within 1e-9', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const drag = 0.3;
    const v0 = 10;
    const body = world.add(particle({ radius: 0.5, drag, linearVelocity: { x: v0, y: 0 } }));
    const t = 2;
    for (let i = 0; i < t / dt; i++) world.step(dt);
    const expected = 1 / (1 / v0 + (drag / body.mass) * t);
    expect(Math.abs(body.linearVelocity.x / expected - 1)).toBeLessThan(1e-9);
  });
});

describe('gravity scale', () => {
  it('scales the acceleration of one body: v = s g t within 1e-12', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    const normal = world.add(particle({ radius: 0.1 }));
    const half = world.add(particle({ radius: 0.1, position: { x: 5, y: 0 }, gravityScale: 0.5 }));
    const floating = world.add(
      particle({ radius: 0.1, position: { x: 10, y: 0 }, gravityScale: 0 }),
    );
    for (let i = 0; i < 60; i++) world.step(dt);
    expect(Math.abs(normal.linearVelocity.y / 10 - 1)).toBeLessThan(1e-12);
    expect(Math.abs(half.linearVelocity.y / 5 - 1)).toBeLessThan(1e-12);
    expect(floating.linearVelocity.y).toBe(0);
    expect(floating.position.y).toBe(0);
  });
});
