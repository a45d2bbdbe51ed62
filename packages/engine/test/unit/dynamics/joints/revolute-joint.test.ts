import { describe, expect, it } from 'vitest';
import { World, box, particle, revoluteJoint, type Body } from '@physical/engine';

// A revolute joint keeps one point of two bodies together and leaves them free to turn about it;
// its limits, motor and spring act only on the relative angle.

const DT = 1 / 60;

function hanging(): { world: World; ground: Body; bob: Body } {
  const world = new World({ enableSleep: false });
  const ground = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
  const bob = world.add(particle({ position: { x: 1, y: 0 }, radius: 0.1 }));
  return { world, ground, bob };
}

describe('revolute joint', () => {
  it('keeps the anchor points together while the body swings (under 1 mm)', () => {
    const { world, ground, bob } = hanging();
    world.addJoint(revoluteJoint({ bodyA: ground, bodyB: bob, anchor: { x: 0, y: 0 } }));
    let worst = 0;
    for (let i = 0; i < 300; i++) {
      world.step(DT);
      worst = Math.max(worst, Math.abs(Math.hypot(bob.position.x, bob.position.y) - 1));
    }
    expect(worst).toBeLessThan(1e-3);
    // It did swing: the bob went below the pivot.
    expect(bob.position.y).not.toBeCloseTo(0, 1);
  });

  it('holds a hanging body with a reaction force equal to its weight', () => {
    const world = new World({ enableSleep: false });
    const ground = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
    const bob = world.add(particle({ position: { x: 0, y: 1 }, radius: 0.1, density: 3 }));
    const hinge = world.addJoint(
      revoluteJoint({ bodyA: ground, bodyB: bob, anchor: { x: 0, y: 0 } }),
    );
    for (let i = 0; i < 60; i++) world.step(DT);
    // y-down: the joint pulls the bob up with m g.
    expect(hinge.reactionForce.y).toBeCloseTo(-bob.mass * 9.81, 6);
    expect(hinge.reactionForce.x).toBeCloseTo(0, 9);
    expect(hinge.reactionTorque).toBeCloseTo(0, 9);
  });

  it('stops the angle at its limits', () => {
    const world = new World({ enableSleep: false });
    const ground = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
    const bob = world.add(box({ position: { x: 0.5, y: 0 }, width: 1, height: 0.1 }));
    const hinge = world.addJoint(
      revoluteJoint({
        bodyA: ground,
        bodyB: bob,
        anchor: { x: 0, y: 0 },
        enableLimit: true,
        lowerAngle: -0.2,
        upperAngle: 0.5,
      }),
    );
    let largest = -Infinity;
    for (let i = 0; i < 240; i++) {
      world.step(DT);
      largest = Math.max(largest, hinge.angle);
    }
    // Gravity turns the bob toward +pi/2 (y-down); the upper limit stops it within 0.01 rad.
    expect(largest).toBeLessThan(0.5 + 0.01);
    expect(hinge.angle).toBeCloseTo(0.5, 2);
    hinge.motorSpeed = -3;
    // Ten times the torque of the bar's weight. (The limit is a stiff soft constraint: its
    // steady error grows with the load, 0.004 rad here.)
    hinge.maxMotorTorque = 5;
    hinge.enableMotor = true;
    for (let i = 0; i < 120; i++) world.step(DT);
    expect(hinge.angle).toBeGreaterThan(-0.2 - 0.01);
    expect(hinge.angle).toBeCloseTo(-0.2, 2);
  });

  it('drives the relative rotation at the motor speed, with the torque bounded', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const ground = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
    const wheel = world.add(particle({ radius: 0.5 }));
    const hinge = world.addJoint(
      revoluteJoint({
        bodyA: ground,
        bodyB: wheel,
        anchor: { x: 0, y: 0 },
        enableMotor: true,
        motorSpeed: 2,
        maxMotorTorque: 0.1,
      }),
    );
    world.step(DT);
    // Torque-limited at first: alpha = tau / I.
    expect(wheel.angularVelocity).toBeCloseTo((0.1 * DT) / wheel.inertia, 9);
    expect(hinge.reactionTorque).toBeCloseTo(0.1, 9);
    for (let i = 0; i < 600; i++) world.step(DT);
    expect(wheel.angularVelocity).toBeCloseTo(2, 9);
  });

  it('springs back toward the angle at creation', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const ground = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
    const bar = world.add(box({ width: 1, height: 0.1, angularVelocity: 3 }));
    const hinge = world.addJoint(
      revoluteJoint({
        bodyA: ground,
        bodyB: bar,
        anchor: { x: 0, y: 0 },
        enableSpring: true,
        hertz: 2,
        dampingRatio: 1,
      }),
    );
    let largest = 0;
    for (let i = 0; i < 240; i++) {
      world.step(DT);
      largest = Math.max(largest, Math.abs(hinge.angle));
    }
    expect(largest).toBeGreaterThan(0.05);
    expect(Math.abs(hinge.angle)).toBeLessThan(1e-3);
  });

  it('joins two dynamic bodies: their common point stays common', () => {
    const world = new World({ enableSleep: false });
    const ground = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
    const upper = world.add(box({ position: { x: 0.5, y: 0 }, width: 1, height: 0.1 }));
    const lower = world.add(box({ position: { x: 1.5, y: 0 }, width: 1, height: 0.1 }));
    world.addJoint(revoluteJoint({ bodyA: ground, bodyB: upper, anchor: { x: 0, y: 0 } }));
    world.addJoint(revoluteJoint({ bodyA: upper, bodyB: lower, anchor: { x: 1, y: 0 } }));
    let worst = 0;
    for (let i = 0; i < 300; i++) {
      world.step(DT);
      const p = upper.getWorldPoint({ x: 0.5, y: 0 });
      const q = lower.getWorldPoint({ x: -0.5, y: 0 });
      worst = Math.max(worst, Math.hypot(p.x - q.x, p.y - q.y));
    }
    expect(worst).toBeLessThan(5e-3);
  });
});
