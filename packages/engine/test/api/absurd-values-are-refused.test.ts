import { describe, expect, it } from 'vitest';
import {
  World,
  box,
  capsule,
  distanceJoint,
  mouseJoint,
  particle,
  revoluteJoint,
  wall,
  weldJoint,
} from '@physical/engine';
import { physicalErrorOf } from './expect-physical-error.ts';

// Finding 12: finite but absurd values, whose squares or products overflow inside a step, are
// refused where they come in (the documented ranges), instead of turning into NaN later.

const MAX = Number.MAX_VALUE;

function scene(): {
  world: World;
  ground: ReturnType<typeof wall>;
  ball: ReturnType<typeof particle>;
} {
  const world = new World();
  const ground = world.add(wall({ from: { x: -5, y: 1 }, to: { x: 5, y: 1 } }));
  const ball = world.add(particle({ radius: 0.5 }));
  return { world, ground, ball };
}

describe('absurd values are refused', () => {
  it.each([
    ['dt', () => scene().world.step(1e300)],
    // Found by the long fuzz run: a step of 1e-300 s turned a joint's impulse into an infinite force.
    ['dt', () => scene().world.step(1e-300)],
    ['radius', () => particle({ radius: 1e50 })],
    ['width', () => box({ width: 1e300, height: 1 })],
    ['restitution', () => particle({ radius: 1, restitution: 1e300 })],
    ['density', () => particle({ radius: 1, density: MAX })],
    ['mass', () => particle({ radius: 1, mass: MAX })],
    ['linearVelocity.x', () => particle({ radius: 1, linearVelocity: { x: MAX, y: 0 } })],
    ['position.x', () => particle({ radius: 1, position: { x: 1e100, y: 0 } })],
    ['radius', () => capsule({ radius: 1e300, length: 1 })],
    ['gravity.y', () => new World({ gravity: { x: 0, y: MAX } })],
  ])('%s', (field, action) => {
    expect(physicalErrorOf(action).field).toBe(field);
  });

  it('setters and actions on a body', () => {
    const { world, ball } = scene();
    expect(physicalErrorOf(() => (ball.mass = 1e-300)).field).toBe('mass');
    expect(physicalErrorOf(() => (ball.mass = MAX)).field).toBe('mass');
    expect(physicalErrorOf(() => ball.applyForce({ x: MAX, y: 0 })).field).toBe('force.x');
    expect(physicalErrorOf(() => ball.applyImpulse({ x: MAX, y: 0 })).field).toBe('impulse.x');
    expect(physicalErrorOf(() => ball.applyTorque(MAX)).field).toBe('torque');
    expect(physicalErrorOf(() => (ball.linearVelocity = { x: 0, y: MAX })).field).toBe(
      'linearVelocity.y',
    );
    expect(physicalErrorOf(() => (ball.angularVelocity = MAX)).field).toBe('angularVelocity');
    expect(physicalErrorOf(() => (ball.position = { x: 1e100, y: 0 })).field).toBe('position.x');
    expect(physicalErrorOf(() => (world.gravity = { x: MAX, y: 0 })).field).toBe('gravity.x');
    world.step();
    expect(Number.isFinite(ball.position.y)).toBe(true);
  });

  it('joints: hertz 1e300 and anchors at 1e100', () => {
    const { ground, ball } = scene();
    expect(
      physicalErrorOf(() => mouseJoint({ body: ball, target: { x: 0, y: 0 }, hertz: 1e300 })).field,
    ).toBe('hertz');
    expect(
      physicalErrorOf(() =>
        revoluteJoint({ bodyA: ground, bodyB: ball, anchor: { x: 1e100, y: 0 } }),
      ).field,
    ).toBe('anchor.x');
    expect(
      physicalErrorOf(() =>
        distanceJoint({
          bodyA: ground,
          bodyB: ball,
          anchorA: { x: 0, y: 1 },
          anchorB: { x: 0, y: 0 },
          hertz: 1e300,
        }),
      ).field,
    ).toBe('hertz');
    const weld = weldJoint({ bodyA: ground, bodyB: ball, anchor: { x: 0, y: 0 } });
    expect(physicalErrorOf(() => (weld.linearHertz = 1e300)).field).toBe('linearHertz');
    const hinge = revoluteJoint({ bodyA: ground, bodyB: ball, anchor: { x: 0, y: 0 } });
    expect(physicalErrorOf(() => (hinge.maxMotorTorque = MAX)).field).toBe('maxMotorTorque');
  });

  it('the largest values in range keep the world finite', () => {
    const world = new World();
    world.add(wall({ from: { x: -5, y: 1 }, to: { x: 5, y: 1 } }));
    const ball = world.add(particle({ radius: 0.5, restitution: 10, friction: 100 }));
    ball.applyForce({ x: 1e18, y: 1e18 }, { duration: 'constant' });
    ball.applyImpulse({ x: -1e18, y: 1e18 }, { x: 0.3, y: 0.2 });
    for (let i = 0; i < 10; i++) world.step(1);
    expect(Number.isFinite(ball.position.x) && Number.isFinite(ball.position.y)).toBe(true);
    expect(Number.isFinite(ball.angle)).toBe(true);
  });
});
