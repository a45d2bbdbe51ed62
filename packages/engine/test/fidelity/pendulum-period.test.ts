import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, distanceJoint, particle, revoluteJoint, type Body } from '@physical/engine';

// A simple pendulum of length L swings with period T = 2 pi sqrt(L / g) for small angles (the
// first correction, theta0^2 / 16, is 1.6e-4 at 0.05 rad). A small bob on a revolute joint or a
// distance joint (a rod) must keep that period within 1 %.

const L = 1;
const G = 9.81;
const THETA = 0.05;
const DT = 1 / 60;
const TOLERANCE = 0.01;

/** Mean period from the downward zero crossings of x over 20 s (linearly interpolated). */
function measurePeriod(world: World, bob: Body): number {
  let last = bob.position.x;
  const crossings: number[] = [];
  for (let i = 0; i < 20 * 60; i++) {
    world.step(DT);
    const x = bob.position.x;
    if (last > 0 && x <= 0) crossings.push((i + last / (last - x)) * DT);
    last = x;
  }
  expect(crossings.length).toBeGreaterThanOrEqual(9);
  return (crossings[crossings.length - 1]! - crossings[0]!) / (crossings.length - 1);
}

describe('pendulum period', () => {
  it.each(['revolute', 'distance'] as const)(
    'on a %s joint: T = 2 pi sqrt(L / g) within 1 %%',
    (kind) => {
      const world = new World({ enableSleep: false, gravity: { x: 0, y: G } });
      const pivot = world.add(box({ type: 'static', width: 0.05, height: 0.05 }));
      const start = { x: L * Math.sin(THETA), y: L * Math.cos(THETA) };
      // A 1 cm bob: its own moment of inertia changes the period by 5e-5.
      const bob = world.add(particle({ position: start, radius: 0.01 }));
      if (kind === 'revolute') {
        world.addJoint(revoluteJoint({ bodyA: pivot, bodyB: bob, anchor: { x: 0, y: 0 } }));
      } else {
        world.addJoint(
          distanceJoint({ bodyA: pivot, bodyB: bob, anchorA: { x: 0, y: 0 }, anchorB: start }),
        );
      }
      const expected = 2 * Math.PI * Math.sqrt(L / G);
      const error = Math.abs(measurePeriod(world, bob) - expected) / expected;
      reportMeasured(`pendulum period on a ${kind} joint, relative error`, error, TOLERANCE);
      expect(error).toBeLessThan(TOLERANCE);
    },
  );
});
