import { describe, expect, it } from 'vitest';
import { World, box, prismaticJoint } from '@physical/engine';

// The solver holds a dynamic body's solved velocity to maxLinearSpeed and a quarter turn per
// sub-step (solver.ts, integratePositions), not only the velocity it starts the solve with. A
// joint that cannot hold a tiny body against a large constant torque otherwise grew its impulses
// sub-step after sub-step until the velocities overflowed and every body went NaN.

const STEPS = 600;
const DT = 1 / 60;

/** A 0.01 kg box with a constant 2 N m torque, on a prismatic joint to a 0.06 kg box. */
function torquedPrismatic(world: World): void {
  const small = world.add(
    box({
      position: { x: 0, y: -8 },
      width: 0.15,
      height: 0.075,
      linearVelocity: { x: 15, y: 0 },
      angularVelocity: -5,
      sensor: true,
    }),
  );
  small.applyTorque(2, { duration: 'constant' });
  const big = world.add(
    box({ position: { x: 0.6, y: -8 }, width: 0.3, height: 0.2, angularVelocity: 1 }),
  );
  world.addJoint(
    prismaticJoint({
      bodyA: small,
      bodyB: big,
      collideConnected: true,
      anchor: { x: 0.3, y: -8 },
      axis: { x: 1, y: 0.3 },
      enableLimit: true,
      lower: -0.5,
      upper: 0.8,
      enableMotor: true,
      motorSpeed: 1.5,
      maxMotorForce: 20,
    }),
  );
}

/**
 * Steps the world, checking after every step that each body is finite and that its pose moved at
 * most maxLinearSpeed (400 m/s) and a quarter turn per sub-step. (The velocity a step reports is
 * the relax pass's, after the poses moved, so the limits are checked on the poses.)
 */
function stepWithinLimits(world: World, subSteps: number): void {
  const maxTurn = 0.25 * Math.PI * subSteps * (1 + 1e-9);
  const maxMove = 400 * DT * (1 + 1e-9);
  for (let i = 0; i < STEPS; i++) {
    const before = world.bodies.map((b) => ({ x: b.position.x, y: b.position.y, angle: b.angle }));
    world.step(DT);
    world.bodies.forEach((body, n) => {
      const { x, y } = body.position;
      const v = body.linearVelocity;
      const finite = [x, y, body.angle, v.x, v.y, body.angularVelocity].every(Number.isFinite);
      if (!finite) throw new Error(`step ${i}: body ${n} is not finite`);
      const was = before[n]!;
      if (Math.hypot(x - was.x, y - was.y) > maxMove) throw new Error(`step ${i}: moved too far`);
      if (Math.abs(body.angle - was.angle) > maxTurn) throw new Error(`step ${i}: turned too far`);
    });
  }
}

describe('a solved velocity stays within the speed limits', () => {
  it('keeps a torqued small body on a prismatic joint finite for 600 steps', () => {
    const world = new World({ subSteps: 4 });
    torquedPrismatic(world);
    expect(() => stepWithinLimits(world, 4)).not.toThrow();
  });
});
