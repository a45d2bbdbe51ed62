import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, wall } from '@physical/engine';
import type { Body } from '@physical/engine';

// Law 10: Coulomb friction on a 30 degree incline. With mu = 0.7 > tan 30 the box stays (drift
// under 1 mm in 5 s, sleeping off so it cannot hide drift); with mu = 0.2 it slides with
// a = g (sin 30 - mu cos 30) within 2 %. Friction mixes as sqrt(fA fB): the incline gets the same
// coefficient as the box, so the pair's coefficient is exactly mu.

const DT = 1 / 60;
const G = 9.81;
const ANGLE = Math.PI / 6;
const SIZE = 0.5;

function setup(mu: number): {
  world: World;
  block: Body;
  along: () => number;
  speed: () => number;
} {
  const world = new World({ gravity: { x: 0, y: G }, enableSleep: false });
  // y-down: an incline descending to the right, at 30 degrees below the horizontal.
  const c = Math.cos(ANGLE);
  const s = Math.sin(ANGLE);
  const length = 40;
  world.add(
    wall({
      from: { x: -length * c, y: -length * s },
      to: { x: length * c, y: length * s },
      friction: mu,
    }),
  );
  // The box rests on the surface: its centre is half its height along the surface's upward normal
  // (s, -c), at distance 0 along the slope from the origin (a little lifted into the slop margin).
  const start = { x: -2 * c, y: -2 * s };
  const block = world.add(
    box({
      position: { x: start.x + (SIZE / 2) * s, y: start.y - (SIZE / 2) * c },
      angle: ANGLE,
      width: SIZE,
      height: SIZE,
      friction: mu,
    }),
  );
  const origin = { x: block.position.x, y: block.position.y };
  return {
    world,
    block,
    along: () => (block.position.x - origin.x) * c + (block.position.y - origin.y) * s,
    speed: () => block.linearVelocity.x * c + block.linearVelocity.y * s,
  };
}

describe('incline friction', () => {
  it('a box with mu = 0.7 stays on a 30 degree incline', () => {
    const { world, block, along } = setup(0.7);
    for (let i = 0; i < 5 / DT; i++) world.step(DT);
    const drift = Math.abs(along());
    reportMeasured('10 incline mu = 0.7, drift in 5 s (m)', drift, 1e-3);
    expect(drift).toBeLessThan(1e-3);
    expect(Math.abs(block.angle - ANGLE)).toBeLessThan(1e-3);
  });

  it('a box with mu = 0.2 slides down with a = g (sin - mu cos)', () => {
    const mu = 0.2;
    const { world, along, speed } = setup(mu);
    const expected = G * (Math.sin(ANGLE) - mu * Math.cos(ANGLE));
    // Let it settle onto the surface, then measure the acceleration over 2 s.
    for (let i = 0; i < 30; i++) world.step(DT);
    const v0 = speed();
    const x0 = along();
    const steps = 120;
    for (let i = 0; i < steps; i++) world.step(DT);
    const t = steps * DT;
    const fromSpeed = (speed() - v0) / t;
    const fromDistance = (2 * (along() - x0 - v0 * t)) / (t * t);
    reportMeasured(
      '10 incline mu = 0.2, acceleration relative error',
      Math.abs(fromDistance - expected) / expected,
      0.02,
    );
    expect(Math.abs(fromSpeed - expected) / expected).toBeLessThanOrEqual(0.02);
    expect(Math.abs(fromDistance - expected) / expected).toBeLessThanOrEqual(0.02);
  });
});
