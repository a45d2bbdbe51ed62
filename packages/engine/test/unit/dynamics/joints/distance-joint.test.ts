import { describe, expect, it } from 'vitest';
import { World, box, distanceJoint, particle } from '@physical/engine';

// A distance joint keeps two points a set distance apart (a rod), pulls them there like a spring,
// or only stops them from going farther than maxLength (a rope) or closer than minLength.

const DT = 1 / 60;

function scene(): {
  world: World;
  ceiling: ReturnType<typeof box>;
  ball: ReturnType<typeof particle>;
} {
  const world = new World({ enableSleep: false });
  const ceiling = world.add(box({ type: 'static', width: 2, height: 0.2 }));
  const ball = world.add(particle({ position: { x: 1, y: 1 }, radius: 0.1 }));
  return { world, ceiling, ball };
}

describe('distance joint', () => {
  it('as a rod keeps the distance (under 1 mm) and defaults to the distance at creation', () => {
    const { world, ceiling, ball } = scene();
    const rod = world.addJoint(
      distanceJoint({
        bodyA: ceiling,
        bodyB: ball,
        anchorA: { x: 0, y: 0 },
        anchorB: { x: 1, y: 1 },
      }),
    );
    expect(rod.length).toBeCloseTo(Math.SQRT2, 12);
    let worst = 0;
    for (let i = 0; i < 300; i++) {
      world.step(DT);
      worst = Math.max(worst, Math.abs(rod.currentLength - Math.SQRT2));
    }
    expect(worst).toBeLessThan(1e-3);
  });

  it('the tension of a hanging rope at rest is the weight it holds', () => {
    const world = new World({ enableSleep: false });
    const ceiling = world.add(box({ type: 'static', width: 2, height: 0.2 }));
    const ball = world.add(particle({ position: { x: 0, y: 2 }, radius: 0.2, density: 5 }));
    const rope = world.addJoint(
      distanceJoint({
        bodyA: ceiling,
        bodyB: ball,
        anchorA: { x: 0, y: 0 },
        anchorB: { x: 0, y: 2 },
        enableSpring: true,
        maxLength: 2,
      }),
    );
    for (let i = 0; i < 60; i++) world.step(DT);
    expect(rope.reactionForce.y).toBeCloseTo(-ball.mass * 9.81, 6);
    expect(rope.reactionForce.x).toBeCloseTo(0, 9);
  });

  it('a rope goes slack: the body falls freely until the rope is taut', () => {
    const world = new World({ enableSleep: false });
    const ceiling = world.add(box({ type: 'static', width: 2, height: 0.2 }));
    const ball = world.add(particle({ position: { x: 0, y: 1 }, radius: 0.1 }));
    const rope = world.addJoint(
      distanceJoint({
        bodyA: ceiling,
        bodyB: ball,
        anchorA: { x: 0, y: 0 },
        anchorB: { x: 0, y: 1 },
        length: 1,
        enableSpring: true,
        maxLength: 2,
      }),
    );
    world.step(DT);
    expect(ball.linearVelocity.y).toBeCloseTo(9.81 * DT, 9);
    expect(rope.reactionForce.y).toBe(0);
    let longest = 0;
    for (let i = 0; i < 120; i++) {
      world.step(DT);
      longest = Math.max(longest, rope.currentLength);
    }
    expect(longest).toBeLessThan(2 + 2e-3);
    expect(rope.currentLength).toBeGreaterThan(1.99);
  });

  it('minLength keeps the points apart', () => {
    const world = new World({ gravity: { x: 0, y: 0 }, enableSleep: false });
    const a = world.add(particle({ position: { x: 0, y: 0 }, radius: 0.1 }));
    const b = world.add(
      particle({ position: { x: 2, y: 0 }, radius: 0.1, linearVelocity: { x: -3, y: 0 } }),
    );
    const joint = world.addJoint(
      distanceJoint({
        bodyA: a,
        bodyB: b,
        anchorA: { x: 0, y: 0 },
        anchorB: { x: 2, y: 0 },
        enableSpring: true,
        minLength: 1,
      }),
    );
    let shortest = Infinity;
    for (let i = 0; i < 120; i++) {
      world.step(DT);
      shortest = Math.min(shortest, joint.currentLength);
    }
    expect(shortest).toBeGreaterThan(1 - 2e-3);
    // Momentum is kept: the joint's forces are equal and opposite.
    expect(a.mass * a.linearVelocity.x + b.mass * b.linearVelocity.x).toBeCloseTo(-3 * b.mass, 9);
  });

  it('setting the length pulls the body to the new length and wakes it', () => {
    const world = new World();
    const ceiling = world.add(box({ type: 'static', width: 2, height: 0.2 }));
    const ball = world.add(particle({ position: { x: 0, y: 1 }, radius: 0.1 }));
    const rod = world.addJoint(
      distanceJoint({
        bodyA: ceiling,
        bodyB: ball,
        anchorA: { x: 0, y: 0 },
        anchorB: { x: 0, y: 1 },
      }),
    );
    for (let i = 0; i < 60; i++) world.step(DT);
    expect(ball.isAwake).toBe(false);
    rod.length = 0.5;
    expect(ball.isAwake).toBe(true);
    for (let i = 0; i < 120; i++) world.step(DT);
    expect(rod.currentLength).toBeCloseTo(0.5, 3);
  });
});
