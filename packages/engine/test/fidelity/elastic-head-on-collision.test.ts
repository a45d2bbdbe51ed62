import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, particle } from '@physical/engine';

// Law 7: a head-on elastic collision (e = 1, no friction) conserves momentum and kinetic energy:
//   v1' = ((m1 - m2) v1 + 2 m2 v2) / (m1 + m2),  v2' = ((m2 - m1) v2 + 2 m1 v1) / (m1 + m2),
// so equal masses exchange velocities. Within 1e-6 of the speeds. restitutionThreshold 0.

const DT = 1 / 60;
const TOLERANCE = 1e-6;

interface Case {
  name: string;
  r1: number;
  r2: number;
  density1: number;
  density2: number;
  v1: number;
  v2: number;
}

function collide(c: Case): {
  v1: number;
  v2: number;
  m1: number;
  m2: number;
  w: number;
  vy: number;
} {
  const world = new World({ gravity: { x: 0, y: 0 }, restitutionThreshold: 0 });
  const common = { restitution: 1, friction: 0 };
  const a = world.add(
    particle({
      ...common,
      position: { x: -2, y: 0 },
      radius: c.r1,
      density: c.density1,
      linearVelocity: { x: c.v1, y: 0 },
    }),
  );
  const b = world.add(
    particle({
      ...common,
      position: { x: 2, y: 0 },
      radius: c.r2,
      density: c.density2,
      linearVelocity: { x: c.v2, y: 0 },
    }),
  );
  // Run until well after the collision (the gap closes at |v1 - v2|).
  const seconds = 4 / Math.abs(c.v1 - c.v2) + 1;
  for (let i = 0; i < Math.ceil(seconds / DT); i++) world.step(DT);
  return {
    v1: a.linearVelocity.x,
    v2: b.linearVelocity.x,
    m1: a.mass,
    m2: b.mass,
    w: Math.abs(a.angularVelocity) + Math.abs(b.angularVelocity),
    vy: Math.abs(a.linearVelocity.y) + Math.abs(b.linearVelocity.y),
  };
}

describe('elastic head-on collision', () => {
  it.each<Case>([
    {
      name: 'equal circles, one at rest',
      r1: 0.5,
      r2: 0.5,
      density1: 1,
      density2: 1,
      v1: 3,
      v2: 0,
    },
    {
      name: 'equal circles, both moving',
      r1: 0.3,
      r2: 0.3,
      density1: 2,
      density2: 2,
      v1: 4,
      v2: -1.5,
    },
    { name: 'light onto heavy', r1: 0.25, r2: 0.5, density1: 1, density2: 3, v1: 5, v2: 0 },
    { name: 'heavy onto light', r1: 0.6, r2: 0.2, density1: 1, density2: 1, v1: 2, v2: -1 },
    {
      name: 'fast and slow, same direction',
      r1: 0.4,
      r2: 0.3,
      density1: 1,
      density2: 4,
      v1: 6,
      v2: 1,
    },
  ])('matches the 1-D formulas ($name)', (c) => {
    const result = collide(c);
    const { m1, m2 } = result;
    const expected1 = ((m1 - m2) * c.v1 + 2 * m2 * c.v2) / (m1 + m2);
    const expected2 = ((m2 - m1) * c.v2 + 2 * m1 * c.v1) / (m1 + m2);
    const scale = Math.max(Math.abs(c.v1), Math.abs(c.v2));
    reportMeasured(
      '7 head-on elastic, velocity error / speed',
      Math.max(Math.abs(result.v1 - expected1), Math.abs(result.v2 - expected2)) / scale,
      TOLERANCE,
    );
    expect(Math.abs(result.v1 - expected1) / scale).toBeLessThanOrEqual(TOLERANCE);
    expect(Math.abs(result.v2 - expected2) / scale).toBeLessThanOrEqual(TOLERANCE);
    // Head-on: no sideways motion, no spin.
    expect(result.vy).toBeLessThanOrEqual(TOLERANCE * scale);
    expect(result.w).toBeLessThanOrEqual(TOLERANCE * scale);
  });

  it('equal circles exchange velocities', () => {
    const result = collide({
      name: '',
      r1: 0.5,
      r2: 0.5,
      density1: 1,
      density2: 1,
      v1: 2.5,
      v2: -0.75,
    });
    expect(Math.abs(result.v1 - -0.75) / 2.5).toBeLessThanOrEqual(TOLERANCE);
    expect(Math.abs(result.v2 - 2.5) / 2.5).toBeLessThanOrEqual(TOLERANCE);
  });
});
