import { describe, expect, it } from 'vitest';
import { World, box, particle, revoluteJoint } from '@physical/engine';

// Speed limits keep a runaway body finite: linear speed at most maxLinearSpeed, rotation at most
// a quarter turn per sub-step (Box2D v3's rule).

describe('speed limits', () => {
  it('caps linear speed at maxLinearSpeed', () => {
    const world = new World({ gravity: { x: 0, y: 0 }, maxLinearSpeed: 50 });
    const ball = world.add(
      particle({ position: { x: 0, y: 0 }, radius: 0.1, linearVelocity: { x: 300, y: 400 } }),
    );
    world.step(1 / 60);
    expect(Math.hypot(ball.linearVelocity.x, ball.linearVelocity.y)).toBeCloseTo(50, 9);
  });

  it('caps rotation at a quarter turn per sub-step', () => {
    const world = new World({ gravity: { x: 0, y: 0 }, subSteps: 4 });
    const spinner = world.add(
      box({ position: { x: 0, y: 0 }, width: 1, height: 1, angularVelocity: -5000 }),
    );
    world.step(1 / 60);
    const limit = (0.25 * Math.PI * 4) / (1 / 60);
    expect(spinner.angularVelocity).toBeCloseTo(-limit, 9);
    // A slower spin is untouched.
    spinner.angularVelocity = 100;
    world.step(1 / 60);
    expect(spinner.angularVelocity).toBe(100);
  });

  it('a tiny body on a long lever stays finite', () => {
    const world = new World();
    const anchor = world.add(
      box({ type: 'static', position: { x: 0, y: 0 }, width: 1, height: 1 }),
    );
    const speck = world.add(
      particle({ position: { x: 20, y: 0 }, radius: 0.001, density: 0.001, angularVelocity: 1e6 }),
    );
    world.addJoint(revoluteJoint({ bodyA: anchor, bodyB: speck, anchor: { x: 0, y: 0 } }));
    for (let i = 0; i < 600; i++) world.step(1 / 60);
    expect(Number.isFinite(speck.position.x) && Number.isFinite(speck.angularVelocity)).toBe(true);
    expect(Math.hypot(speck.position.x, speck.position.y)).toBeCloseTo(20, 1);
  });
});
