import { afterEach, describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, particle, wall } from '@physical/engine';
import type { Body } from '@physical/engine';
import { kernelSettings } from '../../src/dynamics/solver-memory.ts';
// The JavaScript build of the contact passes, compared here with the WebAssembly one.
import '@physical/engine/javascript-kernel';

// A pile stands on bouncy particles. A particle pressed into its neighbour by the bodies above
// approaches it faster than the restitution threshold every sub-step; were each approach an
// impact, its overlap would never be pushed out and the load would pass through it: a bin of
// 240 particles with e = 0.3 went through its floor within 2 s. A contact that keeps bouncing
// while it overlaps is a contact (contact-solver.ts, PRESSED_AFTER_BOUNCING_STEPS).

const DT = 1 / 60;
const SECONDS = 6;
// Centres stay above the floor's top (y = 0, y-down) by more than this: a particle of radius
// 0.2 m overlaps the floor by at most 10 cm, a box 0.35 m tall by at most 7.5 cm.
const FLOOR_MARGIN = 0.1;
// A pile that can lose energy comes to rest.
const REST_SPEED = 0.5;

const DEFAULT_KERNEL_THRESHOLD = kernelSettings.minConstraints;
afterEach(() => {
  kernelSettings.minConstraints = DEFAULT_KERNEL_THRESHOLD;
});

/** 12 rows of 20 in a 12 m bin: particles (every `every`-th body) with restitution `e`, boxes. */
function bin(e: number, every: number): { world: World; bodies: Body[] } {
  const world = new World();
  world.add(wall({ from: { x: -6, y: 0 }, to: { x: 6, y: 0 } }));
  world.add(wall({ from: { x: -6, y: 0 }, to: { x: -6, y: -40 } }));
  world.add(wall({ from: { x: 6, y: 0 }, to: { x: 6, y: -40 } }));
  const bodies: Body[] = [];
  for (let i = 0; i < 240; i++) {
    const position = { x: -5 + (i % 20) * 0.5, y: -1 - Math.floor(i / 20) * 0.6 };
    bodies.push(
      world.add(
        i % every === 0
          ? particle({ position, radius: 0.2, restitution: e })
          : box({ position, angle: 0.05 * (i % 7), width: 0.4, height: 0.35, friction: 0.6 }),
      ),
    );
  }
  return { world, bodies };
}

function run(e: number, every: number): { lowest: number; inside: boolean; speed: number } {
  const { world, bodies } = bin(e, every);
  let lowest = -Infinity;
  let inside = true;
  for (let i = 0; i < SECONDS / DT; i++) {
    world.step(DT);
    for (const body of bodies) {
      lowest = Math.max(lowest, body.position.y);
      if (Math.abs(body.position.x) > 6) inside = false;
    }
  }
  let speed = 0;
  for (const body of bodies) {
    speed = Math.max(speed, Math.hypot(body.linearVelocity.x, body.linearVelocity.y));
  }
  return { lowest, inside, speed };
}

describe('bouncy piles', () => {
  for (const [e, every] of [
    [0.3, 4],
    [0.3, 1],
    [0.6, 1],
    [1, 4],
  ] as const) {
    const what = every === 1 ? 'particles' : 'particles and boxes';
    it(`a 12-row pile of ${what} with e = ${e} stays in its bin for ${SECONDS} s`, () => {
      const { lowest, inside, speed } = run(e, every);
      reportMeasured(
        `pile of ${what}, e = ${e}: lowest centre's height over the floor (m, at least)`,
        -lowest,
        FLOOR_MARGIN,
      );
      expect(lowest).toBeLessThan(-FLOOR_MARGIN);
      expect(inside).toBe(true);
      // Elastic particles keep bouncing; a pile that loses energy settles.
      if (e < 1) expect(speed).toBeLessThan(REST_SPEED);
    }, 30_000);
  }

  it('holds with the JavaScript contact passes too (pages without WebAssembly)', () => {
    kernelSettings.minConstraints = Number.POSITIVE_INFINITY;
    const { lowest, inside, speed } = run(0.3, 1);
    expect(lowest).toBeLessThan(-FLOOR_MARGIN);
    expect(inside).toBe(true);
    expect(speed).toBeLessThan(REST_SPEED);
  }, 30_000);
});
