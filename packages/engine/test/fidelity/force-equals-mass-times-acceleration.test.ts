import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, particle } from '@physical/engine';

// Law 2 (Newton's second law): a constant force F on a body of mass m for T seconds changes its
// velocity by F T / m, within 1e-9 relative.

const DT = 1 / 60;
const RELATIVE_TOLERANCE = 1e-9;

function relativeError(actual: number, expected: number): number {
  return Math.abs(actual - expected) / Math.abs(expected);
}

describe('F = m a', () => {
  it.each([
    { name: 'circle, 2 s', make: () => particle({ radius: 0.3, density: 2.5 }), seconds: 2 },
    { name: 'box, 3.5 s', make: () => box({ width: 2, height: 0.5, density: 0.7 }), seconds: 3.5 },
    { name: 'heavy box, 1 s', make: () => box({ width: 1, height: 1, mass: 250 }), seconds: 1 },
  ])('a constant force gives v = F T / m ($name)', ({ make, seconds }) => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const body = world.add(make());
    const force = { x: 12.5, y: -4 };
    const handle = body.applyForce(force, { duration: 'constant' });
    const steps = Math.round(seconds / DT);
    for (let i = 0; i < steps; i++) world.step(DT);
    handle.remove();
    const t = steps * DT;
    const m = body.mass;
    reportMeasured(
      '2 F = m a, relative velocity error',
      relativeError(body.linearVelocity.x, (force.x * t) / m),
      RELATIVE_TOLERANCE,
    );
    expect(relativeError(body.linearVelocity.x, (force.x * t) / m)).toBeLessThanOrEqual(
      RELATIVE_TOLERANCE,
    );
    expect(relativeError(body.linearVelocity.y, (force.y * t) / m)).toBeLessThanOrEqual(
      RELATIVE_TOLERANCE,
    );
    expect(body.angularVelocity).toBe(0);
  });

  it('halving the mass doubles the acceleration', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const light = world.add(particle({ position: { x: 0, y: 0 }, radius: 0.2, mass: 1 }));
    const heavy = world.add(particle({ position: { x: 0, y: 10 }, radius: 0.2, mass: 2 }));
    light.applyForce({ x: 6, y: 0 }, { duration: 'constant' });
    heavy.applyForce({ x: 6, y: 0 }, { duration: 'constant' });
    for (let i = 0; i < 90; i++) world.step(DT);
    const t = 90 * DT;
    expect(relativeError(light.linearVelocity.x, 6 * t)).toBeLessThanOrEqual(RELATIVE_TOLERANCE);
    expect(relativeError(heavy.linearVelocity.x, 3 * t)).toBeLessThanOrEqual(RELATIVE_TOLERANCE);
  });
});
