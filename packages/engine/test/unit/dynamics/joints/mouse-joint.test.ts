import { describe, expect, it } from 'vitest';
import { World, box, mouseJoint } from '@physical/engine';

// A mouse joint is a damped spring of bounded force from a point of the body to a target: it
// pulls the body there, never harder than maxForce.

const DT = 1 / 60;

describe('mouse joint', () => {
  it('pulls the grabbed point to the target and holds it against gravity', () => {
    const world = new World();
    const body = world.add(box({ width: 1, height: 1 }));
    const drag = world.addJoint(mouseJoint({ body, target: { x: 0, y: 0 } }));
    drag.target = { x: 3, y: -2 };
    for (let i = 0; i < 180; i++) world.step(DT);
    expect(body.position.x).toBeCloseTo(3, 3);
    // A spring of 5 Hz sags by g / omega^2 under its load.
    const sag = 9.81 / (2 * Math.PI * 5) ** 2;
    expect(body.position.y).toBeCloseTo(-2 + sag, 3);
    expect(drag.reactionForce.y).toBeCloseTo(-body.mass * 9.81, 3);
    expect(drag.body).toBe(body);
    expect(drag.bodyA).toBe(body);
    expect(drag.bodyB).toBe(body);
  });

  it('never pulls harder than maxForce', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const body = world.add(box({ width: 1, height: 1 }));
    // Grabbed at its centre (the target at creation), then pulled far away.
    const drag = world.addJoint(mouseJoint({ body, target: { x: 0, y: 0 }, maxForce: 2 }));
    drag.target = { x: 100, y: 0 };
    for (let i = 0; i < 30; i++) {
      world.step(DT);
      expect(Math.hypot(drag.reactionForce.x, drag.reactionForce.y)).toBeLessThanOrEqual(2 + 1e-9);
    }
    // Far from the target the spring saturates: a = F / m exactly.
    expect(body.linearVelocity.x).toBeCloseTo((2 / body.mass) * 30 * DT, 6);
  });

  it('defaults maxForce to 1000 times the mass', () => {
    const world = new World();
    const body = world.add(box({ width: 2, height: 1, density: 3 }));
    expect(mouseJoint({ body, target: { x: 0, y: 0 } }).maxForce).toBeCloseTo(6000, 9);
  });

  it('wakes a sleeping body when the target moves', () => {
    const world = new World();
    world.add(box({ type: 'static', position: { x: 0, y: 1 }, width: 10, height: 1 }));
    const body = world.add(box({ position: { x: 0, y: 0 }, width: 1, height: 1 }));
    for (let i = 0; i < 240; i++) world.step(DT);
    expect(body.isAwake).toBe(false);
    const drag = world.addJoint(mouseJoint({ body, target: { x: 0, y: 0 } }));
    expect(body.isAwake).toBe(true);
    for (let i = 0; i < 240; i++) world.step(DT);
    expect(body.isAwake).toBe(false);
    drag.target = { x: 0, y: -3 };
    expect(body.isAwake).toBe(true);
    for (let i = 0; i < 120; i++) world.step(DT);
    expect(body.position.y).toBeLessThan(-2.9);
  });
});
