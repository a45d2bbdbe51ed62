import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, particle, regularPolygon, wall } from '@physical/engine';
import type { Body } from '@physical/engine';

// Law 14: determinism. Two identically built worlds (a pile of mixed shapes falling into a box)
// stepped 1000 times have bitwise-equal states: every x, y, angle and velocity.

function build(): { world: World; bodies: Body[] } {
  const world = new World();
  world.add(wall({ from: { x: -6, y: 0 }, to: { x: 6, y: 0 } }));
  world.add(wall({ from: { x: -6, y: 0 }, to: { x: -6, y: -20 } }));
  world.add(wall({ from: { x: 6, y: 0 }, to: { x: 6, y: -20 } }));
  const bodies: Body[] = [];
  for (let i = 0; i < 60; i++) {
    const position = { x: -4.5 + (i % 10), y: -2 - 1.2 * Math.floor(i / 10) };
    const common = {
      position,
      angle: 0.1 * i,
      linearVelocity: { x: ((i * 7) % 5) - 2, y: 0 },
      restitution: (i % 4) * 0.2,
    };
    const kind = i % 3;
    bodies.push(
      world.add(
        kind === 0
          ? particle({ ...common, radius: 0.3 + 0.02 * (i % 5) })
          : kind === 1
            ? box({ ...common, width: 0.5 + 0.05 * (i % 4), height: 0.4 })
            : regularPolygon({ ...common, sides: 3 + (i % 6), radius: 0.4 }),
      ),
    );
  }
  return { world, bodies };
}

function snapshot(bodies: readonly Body[]): Float64Array {
  const data = new Float64Array(bodies.length * 6);
  bodies.forEach((b, i) => {
    data.set(
      [
        b.position.x,
        b.position.y,
        b.angle,
        b.linearVelocity.x,
        b.linearVelocity.y,
        b.angularVelocity,
      ],
      i * 6,
    );
  });
  return data;
}

describe('determinism', () => {
  it('two identical worlds stay bitwise equal for 1000 steps', () => {
    const first = build();
    const second = build();
    for (let i = 0; i < 1000; i++) {
      first.world.step(1 / 60);
      second.world.step(1 / 60);
    }
    const a = new BigUint64Array(snapshot(first.bodies).buffer);
    const b = new BigUint64Array(snapshot(second.bodies).buffer);
    let differences = 0;
    for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) differences++;
    reportMeasured('14 determinism, differing state bits', differences, 0);
    expect(differences).toBe(0);
    // And the pile really moved (a frozen scene would be trivially deterministic).
    const start = snapshot(build().bodies);
    const end = snapshot(first.bodies);
    let moved = 0;
    for (let i = 0; i < end.length; i++) if (!Object.is(start[i], end[i])) moved++;
    expect(moved).toBeGreaterThan(end.length / 2);
  });
});
