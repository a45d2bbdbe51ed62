import { describe, expect, it } from 'vitest';
import { World, box, weldJoint } from '@physical/engine';

// A weld joint makes two bodies one (rigid), or joins them with springs in position and angle.

const DT = 1 / 60;

describe('weld joint', () => {
  it('a rigid weld holds a cantilever: the angle and the anchor stay put', () => {
    const world = new World({ enableSleep: false });
    const wallBody = world.add(
      box({ type: 'static', position: { x: -0.5, y: 0 }, width: 1, height: 1 }),
    );
    const beam = world.add(box({ position: { x: 1, y: 0 }, width: 2, height: 0.2 }));
    const weld = world.addJoint(
      weldJoint({ bodyA: wallBody, bodyB: beam, anchor: { x: 0, y: 0 } }),
    );
    for (let i = 0; i < 120; i++) world.step(DT);
    expect(Math.abs(beam.angle)).toBeLessThan(0.01);
    const end = beam.getWorldPoint({ x: -1, y: 0 });
    expect(Math.hypot(end.x, end.y)).toBeLessThan(2e-3);
    // The wall holds the beam's weight and its moment: F = m g up, torque m g d about the anchor
    // (positive turns +x toward +y, so the wall's torque on the beam is negative).
    const weight = beam.mass * 9.81;
    expect(weld.reactionForce.y).toBeCloseTo(-weight, 3);
    expect(weld.reactionTorque).toBeCloseTo(-weight * 1, 2);
  });

  it('a soft weld bends like a torsion spring of its frequency', () => {
    const world = new World({ gravity: { x: 0, y: 0 }, enableSleep: false });
    const base = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
    const bar = world.add(box({ width: 1, height: 0.1 }));
    const hertz = 2;
    world.addJoint(
      weldJoint({
        bodyA: base,
        bodyB: bar,
        anchor: { x: 0, y: 0 },
        angularHertz: hertz,
        dampingRatio: 0,
      }),
    );
    bar.angularVelocity = 1;
    // The angle swings through zero every half period: count the sign changes over 2 s.
    let crossings = 0;
    let last = 0;
    for (let i = 0; i < 120; i++) {
      world.step(DT);
      if (i > 0 && Math.sign(bar.angle) !== Math.sign(last) && bar.angle !== 0) crossings++;
      last = bar.angle;
    }
    expect(crossings).toBe(2 * hertz * 2 - 1);
  });
});
