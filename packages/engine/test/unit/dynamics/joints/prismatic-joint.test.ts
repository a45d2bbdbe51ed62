import { describe, expect, it } from 'vitest';
import { World, box, prismaticJoint } from '@physical/engine';

// A prismatic joint lets body B slide along an axis of body A and nothing else.

const DT = 1 / 60;

describe('prismatic joint', () => {
  it('slides along the axis only: no sideways motion, no turning', () => {
    const world = new World({ enableSleep: false });
    const ground = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
    const block = world.add(box({ position: { x: 1, y: 0 }, width: 0.5, height: 0.5 }));
    // A 45 degree slope (y-down): gravity pulls the block along it at g / sqrt(2).
    const slide = world.addJoint(
      prismaticJoint({ bodyA: ground, bodyB: block, anchor: { x: 1, y: 0 }, axis: { x: 1, y: 1 } }),
    );
    for (let i = 0; i < 60; i++) world.step(DT);
    const p = block.position;
    expect(Math.abs(p.x - 1 - p.y)).toBeLessThan(1e-3);
    expect(Math.abs(block.angle)).toBeLessThan(1e-3);
    const t = 60 * DT;
    expect(slide.translation).toBeCloseTo(0.5 * (9.81 / Math.SQRT2) * t * t, 1);
  });

  it('stops at its limits', () => {
    const world = new World({ enableSleep: false });
    const ground = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
    const block = world.add(box({ position: { x: 0, y: 0 }, width: 0.5, height: 0.5 }));
    const slide = world.addJoint(
      prismaticJoint({
        bodyA: ground,
        bodyB: block,
        anchor: { x: 0, y: 0 },
        axis: { x: 0, y: 1 },
        enableLimit: true,
        lower: -0.5,
        upper: 1,
      }),
    );
    let farthest = 0;
    for (let i = 0; i < 120; i++) {
      world.step(DT);
      farthest = Math.max(farthest, slide.translation);
    }
    expect(farthest).toBeLessThan(1 + 0.01);
    expect(slide.translation).toBeCloseTo(1, 2);
    // At rest on the limit it carries the block's weight.
    expect(slide.reactionForce.y).toBeCloseTo(-block.mass * 9.81, 3);
  });

  it('a motor drives the slide at its speed against gravity', () => {
    const world = new World({ enableSleep: false });
    const ground = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
    const block = world.add(box({ position: { x: 0, y: 0 }, width: 0.5, height: 0.5 }));
    const lift = world.addJoint(
      prismaticJoint({
        bodyA: ground,
        bodyB: block,
        anchor: { x: 0, y: 0 },
        axis: { x: 0, y: -1 },
        enableMotor: true,
        motorSpeed: 0.5,
        maxMotorForce: 100,
      }),
    );
    for (let i = 0; i < 60; i++) world.step(DT);
    expect(block.linearVelocity.y).toBeCloseTo(-0.5, 6);
    // The motor holds the weight: F = m g.
    expect(lift.motorForce).toBeCloseTo(block.mass * 9.81, 3);
  });

  it('a spring along the axis oscillates at its frequency', () => {
    const world = new World({ gravity: { x: 0, y: 0 }, enableSleep: false });
    const ground = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
    const block = world.add(
      box({ position: { x: 0, y: 0 }, width: 0.5, height: 0.5, linearVelocity: { x: 1, y: 0 } }),
    );
    world.addJoint(
      prismaticJoint({
        bodyA: ground,
        bodyB: block,
        anchor: { x: 0, y: 0 },
        axis: { x: 1, y: 0 },
        enableSpring: true,
        hertz: 1,
      }),
    );
    // After one period (1 s) it is back at the start, moving the same way. (The soft step solves
    // springs implicitly, which costs an undamped spring some amplitude: 15 % per period at 1 Hz.)
    for (let i = 0; i < 60; i++) world.step(DT);
    expect(Math.abs(block.position.x)).toBeLessThan(0.01);
    expect(block.linearVelocity.x).toBeGreaterThan(0.8);
  });
});
