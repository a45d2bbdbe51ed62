import { describe, expect, it } from 'vitest';
import { World, box, particle } from '@physical/engine';
import { physicalErrorOf } from './expect-physical-error.ts';

// Findings 7 and 8: a setter refuses what the factory refuses, and a Force handle's fields are
// checked like applyForce's arguments: the value stays, the world stays finite.

describe('shape material setters', () => {
  it.each([
    ['friction', NaN],
    ['friction', -5],
    ['friction', Infinity],
    ['restitution', -1],
    ['restitution', NaN],
    ['restitution', 1e300],
  ] as const)('shape.%s = %s is refused and the value kept', (key, value) => {
    const body = box({ width: 1, height: 1, friction: 0.3, restitution: 0.2 });
    const shape = body.shapes[0]!;
    const before = shape[key];
    expect(physicalErrorOf(() => (shape[key] = value)).field).toBe(key);
    expect(shape[key]).toBe(before);
    // The factory refuses the same value.
    physicalErrorOf(() => box({ width: 1, height: 1, [key]: value }));
  });
});

describe('Force handles', () => {
  it.each([
    ['x', NaN],
    ['y', Infinity],
    ['torque', NaN],
    ['remaining', NaN],
    ['remaining', -3],
    ['x', Number.MAX_VALUE],
  ] as const)('force.%s = %s is refused; the next step stays finite', (key, value) => {
    const world = new World();
    const ball = world.add(particle({ radius: 0.5 }));
    const force = ball.applyForce({ x: 1, y: 0 }, { duration: 2 });
    const before = force[key];
    expect(
      physicalErrorOf(() => ((force as unknown as Record<string, number>)[key] = value)).field,
    ).toBe(key);
    expect(force[key]).toBe(before);
    world.step();
    expect(Number.isFinite(ball.position.x)).toBe(true);
    expect(Number.isFinite(ball.position.y)).toBe(true);
  });

  it('valid changes to a Force handle apply', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const ball = world.add(particle({ radius: 0.5, density: 1 / Math.PI / 0.25 })); // 1 kg
    const force = ball.applyForce({ x: 0, y: 0 }, { duration: 'constant' });
    force.x = 60;
    world.step(1 / 60);
    // dv = F dt / m = 60 * (1/60) / 1 = 1 m/s.
    expect(ball.linearVelocity.x).toBeCloseTo(1, 9);
    force.remaining = 0;
    world.step(1 / 60);
    expect(ball.linearVelocity.x).toBeCloseTo(1, 9);
  });
});
