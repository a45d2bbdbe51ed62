import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, distanceJoint, particle, revoluteJoint } from '@physical/engine';

// Joint springs oscillate at the frequency they are given, f = (1 / 2 pi) sqrt(k / m) with k set
// from the body's mass; motors reach their speed; limits hold.

const DT = 1 / 60;

describe('joint springs, motors and limits', () => {
  it.each([0.5, 1, 2, 5])(
    'a %s Hz distance-joint spring oscillates at its frequency within 2 %%',
    (hertz) => {
      const world = new World({ gravity: { x: 0, y: 0 }, enableSleep: false });
      const wallBody = world.add(box({ type: 'static', width: 0.05, height: 0.05 }));
      const ball = world.add(particle({ position: { x: 1.1, y: 0 }, radius: 0.05 }));
      world.addJoint(
        distanceJoint({
          bodyA: wallBody,
          bodyB: ball,
          anchorA: { x: 0, y: 0 },
          anchorB: { x: 1.1, y: 0 },
          length: 1,
          enableSpring: true,
          hertz,
          dampingRatio: 0,
        }),
      );
      let last = ball.position.x - 1;
      const crossings: number[] = [];
      for (let i = 0; i < 10 * 60; i++) {
        world.step(DT);
        const x = ball.position.x - 1;
        if (last > 0 && x <= 0) crossings.push((i + last / (last - x)) * DT);
        last = x;
      }
      expect(crossings.length).toBeGreaterThanOrEqual(4);
      const period = (crossings[crossings.length - 1]! - crossings[0]!) / (crossings.length - 1);
      const error = Math.abs(1 / period - hertz) / hertz;
      reportMeasured(`${hertz} Hz joint spring, relative frequency error`, error, 0.02);
      expect(error).toBeLessThan(0.02);
    },
  );

  it('a revolute motor spins a loaded wheel up to its speed', () => {
    const world = new World({ enableSleep: false });
    const axle = world.add(box({ type: 'static', width: 0.1, height: 0.1 }));
    // An unbalanced wheel: a disc with its hinge 0.2 m off-centre, so gravity fights the motor.
    const wheel = world.add(particle({ position: { x: 0.2, y: 0 }, radius: 0.5 }));
    const motor = world.addJoint(
      revoluteJoint({
        bodyA: axle,
        bodyB: wheel,
        anchor: { x: 0, y: 0 },
        enableMotor: true,
        motorSpeed: 4,
        maxMotorTorque: 50,
      }),
    );
    for (let i = 0; i < 120; i++) world.step(DT);
    const error = Math.abs(wheel.angularVelocity - 4) / 4;
    // The motor row is solved before the hinge's point row, which nudges the spin a little.
    reportMeasured('revolute motor speed under load, relative error', error, 1e-3);
    expect(error).toBeLessThan(1e-3);
    expect(motor.angularSpeed).toBeCloseTo(4, 2);
  });

  it('a revolute limit stops a falling bar within 0.01 rad', () => {
    const world = new World({ enableSleep: false });
    const pivot = world.add(box({ type: 'static', width: 0.1, height: 0.1 }));
    const bar = world.add(box({ position: { x: 0.5, y: 0 }, width: 1, height: 0.1 }));
    const hinge = world.addJoint(
      revoluteJoint({
        bodyA: pivot,
        bodyB: bar,
        anchor: { x: 0, y: 0 },
        enableLimit: true,
        lowerAngle: -1,
        upperAngle: Math.PI / 4,
      }),
    );
    let overshoot = 0;
    for (let i = 0; i < 180; i++) {
      world.step(DT);
      overshoot = Math.max(overshoot, hinge.angle - Math.PI / 4);
    }
    reportMeasured('revolute limit overshoot (rad)', overshoot, 0.01);
    expect(overshoot).toBeLessThan(0.01);
    expect(hinge.angle).toBeCloseTo(Math.PI / 4, 2);
  });
});
