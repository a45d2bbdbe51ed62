import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, particle } from '@physical/engine';

// Law 3: the thesis's force durations. At 60 Hz a force of 0.5 s acts in exactly 30 steps (the
// velocity changes in steps 1..30 and not in step 31), an 'instant' force in exactly one step, and
// a 'constant' force until it is removed. Each step that it acts adds exactly F dt / m.

const DT = 1 / 60;
const FORCE = 3;
const MASS = 1.5;
const TOLERANCE = 1e-9;

function setup(): { world: World; body: ReturnType<typeof particle> } {
  const world = new World({ gravity: { x: 0, y: 0 } });
  const body = world.add(particle({ radius: 0.25, mass: MASS }));
  return { world, body };
}

/** Velocity change (m/s) in each of `steps` steps. */
function velocityChanges(world: World, body: ReturnType<typeof particle>, steps: number): number[] {
  const changes: number[] = [];
  for (let i = 0; i < steps; i++) {
    const before = body.linearVelocity.x;
    world.step(DT);
    changes.push(body.linearVelocity.x - before);
  }
  return changes;
}

describe('force durations', () => {
  it('a 0.5 s force acts in exactly 30 steps at 60 Hz', () => {
    const { world, body } = setup();
    const force = body.applyForce({ x: FORCE, y: 0 }, { duration: 0.5 });
    const changes = velocityChanges(world, body, 40);
    const perStep = (FORCE * DT) / MASS;
    reportMeasured(
      '3 durations: steps in which a 0.5 s force acted at 60 Hz (exactly 30)',
      changes.filter((change) => change !== 0).length,
      30,
    );
    for (let i = 0; i < 30; i++) expect(Math.abs(changes[i]! - perStep)).toBeLessThan(TOLERANCE);
    for (let i = 30; i < 40; i++) expect(changes[i]).toBe(0);
    expect(Math.abs(body.linearVelocity.x - (FORCE * 0.5) / MASS)).toBeLessThan(TOLERANCE);
    expect(force.isExpired).toBe(true);
    expect(body.forces).toHaveLength(0);
  });

  it('a force whose duration is not a whole number of steps delivers exactly F * duration', () => {
    const { world, body } = setup();
    const duration = 0.1234;
    body.applyForce({ x: FORCE, y: 0 }, { duration });
    const changes = velocityChanges(world, body, 12);
    const fullSteps = Math.floor(duration / DT); // 7
    for (let i = 0; i < fullSteps; i++) {
      expect(Math.abs(changes[i]! - (FORCE * DT) / MASS)).toBeLessThan(TOLERANCE);
    }
    expect(changes[fullSteps]!).toBeGreaterThan(0);
    for (let i = fullSteps + 1; i < 12; i++) expect(changes[i]).toBe(0);
    expect(Math.abs(body.linearVelocity.x - (FORCE * duration) / MASS)).toBeLessThan(TOLERANCE);
  });

  it('an instant force acts in exactly one step', () => {
    const { world, body } = setup();
    body.applyForce({ x: FORCE, y: 0 }, { duration: 'instant' });
    const changes = velocityChanges(world, body, 5);
    expect(Math.abs(changes[0]! - (FORCE * DT) / MASS)).toBeLessThan(TOLERANCE);
    for (let i = 1; i < 5; i++) expect(changes[i]).toBe(0);
    expect(body.forces).toHaveLength(0);
  });

  it('a constant force acts until it is removed', () => {
    const { world, body } = setup();
    const force = body.applyForce({ x: FORCE, y: 0 }, { duration: 'constant' });
    const changes = velocityChanges(world, body, 100);
    for (const change of changes)
      expect(Math.abs(change - (FORCE * DT) / MASS)).toBeLessThan(TOLERANCE);
    force.remove();
    const after = velocityChanges(world, body, 10);
    for (const change of after) expect(change).toBe(0);
    expect(Math.abs(body.linearVelocity.x - (FORCE * 100 * DT) / MASS)).toBeLessThan(TOLERANCE);
  });

  it('a timed torque acts in exactly 30 steps too', () => {
    const { world, body } = setup();
    body.applyTorque(0.2, { duration: 0.5 });
    const changes: number[] = [];
    for (let i = 0; i < 40; i++) {
      const before = body.angularVelocity;
      world.step(DT);
      changes.push(body.angularVelocity - before);
    }
    const perStep = (0.2 * DT) / body.inertia;
    for (let i = 0; i < 30; i++)
      expect(Math.abs(changes[i]! - perStep) / perStep).toBeLessThan(TOLERANCE);
    for (let i = 30; i < 40; i++) expect(changes[i]).toBe(0);
  });
});
