import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, particle, regularPolygon } from '@physical/engine';

// Law 5: rotation. A torque tau gives alpha = tau / I, and an impulse J at a point r from the
// centre of mass gives omega = (r x J) / I with r x J = r.x J.y - r.y J.x (positive omega turns +x
// toward +y); both within 1e-9 relative.

const DT = 1 / 60;
const TOLERANCE = 1e-9;

function relativeError(actual: number, expected: number): number {
  return Math.abs(actual - expected) / Math.abs(expected);
}

describe('torque', () => {
  it('a constant torque gives omega = tau t / I', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const body = world.add(box({ width: 2, height: 0.5, density: 3 }));
    // Moment of inertia of a w x h box about its centre: m (w^2 + h^2) / 12.
    const expectedInertia = (body.mass * (4 + 0.25)) / 12;
    expect(relativeError(body.inertia, expectedInertia)).toBeLessThanOrEqual(TOLERANCE);
    const tau = -1.7;
    body.applyTorque(tau, { duration: 'constant' });
    const steps = 150;
    for (let i = 0; i < steps; i++) world.step(DT);
    const t = steps * DT;
    expect(relativeError(body.angularVelocity, (tau * t) / expectedInertia)).toBeLessThanOrEqual(
      TOLERANCE,
    );
    // The centre of mass does not move under a pure torque.
    expect(body.linearVelocity.x).toBe(0);
    expect(body.linearVelocity.y).toBe(0);
  });

  it('a force at a point adds torque r x F', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const body = world.add(particle({ radius: 0.5, density: 2 }));
    const inertia = 0.5 * body.mass * 0.25; // disc: m r^2 / 2
    expect(relativeError(body.inertia, inertia)).toBeLessThanOrEqual(TOLERANCE);
    // Force (0, 4) at (0.5, 0): torque 0.5 * 4 = 2, for one instant step.
    body.applyForce({ x: 0, y: 4 }, { point: { x: 0.5, y: 0 } });
    world.step(DT);
    expect(relativeError(body.angularVelocity, (2 * DT) / inertia)).toBeLessThanOrEqual(TOLERANCE);
    expect(body.angularVelocity).toBeGreaterThan(0);
  });

  it.each([
    { r: { x: 0.5, y: 0 }, j: { x: 0, y: 2 } },
    { r: { x: 0, y: 0.5 }, j: { x: 3, y: 0 } },
    { r: { x: -0.3, y: 0.2 }, j: { x: 1, y: -1.5 } },
  ])('an off-centre impulse gives omega = (r x J) / I (r = $r.x, $r.y)', ({ r, j }) => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const center = { x: 3, y: -1 };
    const body = world.add(regularPolygon({ position: center, sides: 6, radius: 0.8, angle: 0.4 }));
    body.applyImpulse(j, { x: center.x + r.x, y: center.y + r.y });
    const cross = r.x * j.y - r.y * j.x;
    reportMeasured(
      '5 off-centre impulse, omega vs (r x J) / I relative error',
      relativeError(body.angularVelocity, cross / body.inertia),
      TOLERANCE,
    );
    expect(relativeError(body.angularVelocity, cross / body.inertia)).toBeLessThanOrEqual(
      TOLERANCE,
    );
    // The centre of mass gets J / m whatever the point.
    expect(Math.abs(body.linearVelocity.x - j.x / body.mass)).toBeLessThanOrEqual(TOLERANCE);
    expect(Math.abs(body.linearVelocity.y - j.y / body.mass)).toBeLessThanOrEqual(TOLERANCE);
    // Positive omega turns +x toward +y: a point on +x moves toward +y.
    const beforeAngle = body.angle;
    world.step(DT);
    expect(Math.sign(body.angle - beforeAngle)).toBe(Math.sign(cross));
  });

  it('spins in the +x toward +y sense for a positive torque', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const body = world.add(box({ width: 1, height: 1 }));
    body.applyTorque(5);
    world.step(DT);
    // The local +x axis, (cos a, sin a), has turned toward +y.
    expect(body.getWorldPoint({ x: 1, y: 0 }).y).toBeGreaterThan(0);
  });
});
