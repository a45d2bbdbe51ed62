import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, particle } from '@physical/engine';
import type { Body } from '@physical/engine';

// Law 9: elastic, frictionless circles bouncing in a closed box without gravity keep their kinetic
// energy: after 60 s it is within 2 % of the start (restitutionThreshold 0).

const DT = 1 / 60;
const SECONDS = 60;
const TOLERANCE = 0.02;

/** Mulberry32: a small seeded PRNG, so the scene is the same on every run. */
function random(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function kineticEnergy(bodies: readonly Body[]): number {
  let sum = 0;
  for (const body of bodies) sum += body.kineticEnergy;
  return sum;
}

describe('energy conservation', () => {
  it('20 elastic frictionless circles in a closed box keep their kinetic energy for 60 s', () => {
    const world = new World({ gravity: { x: 0, y: 0 }, restitutionThreshold: 0 });
    const size = 10;
    const thickness = 1;
    const material = { restitution: 1, friction: 0 };
    // Four static walls around the square [0, size] x [0, size].
    const half = size / 2;
    world.add(
      box({
        type: 'static',
        position: { x: half, y: -thickness / 2 },
        width: size + 2,
        height: thickness,
        ...material,
      }),
    );
    world.add(
      box({
        type: 'static',
        position: { x: half, y: size + thickness / 2 },
        width: size + 2,
        height: thickness,
        ...material,
      }),
    );
    world.add(
      box({
        type: 'static',
        position: { x: -thickness / 2, y: half },
        width: thickness,
        height: size + 2,
        ...material,
      }),
    );
    world.add(
      box({
        type: 'static',
        position: { x: size + thickness / 2, y: half },
        width: thickness,
        height: size + 2,
        ...material,
      }),
    );

    const rand = random(12345);
    const balls: Body[] = [];
    // A 5 x 4 grid, so no two start overlapping.
    for (let i = 0; i < 20; i++) {
      const radius = 0.2 + 0.3 * rand();
      const speed = 2 + 3 * rand();
      const direction = 2 * Math.PI * rand();
      balls.push(
        world.add(
          particle({
            position: { x: 1 + 2 * (i % 5), y: 1.25 + 2.5 * Math.floor(i / 5) },
            radius,
            density: 0.5 + rand(),
            linearVelocity: { x: speed * Math.cos(direction), y: speed * Math.sin(direction) },
            ...material,
          }),
        ),
      );
    }
    let collisions = 0;
    world.on('collision', () => collisions++);
    const start = kineticEnergy(balls);
    let worst = 0;
    for (let i = 0; i < SECONDS / DT; i++) {
      world.step(DT);
      worst = Math.max(worst, Math.abs(kineticEnergy(balls) - start) / start);
    }
    // They really collided, with each other and with the walls.
    expect(collisions).toBeGreaterThan(200);
    reportMeasured('9 energy, worst relative drift in 60 s', worst, TOLERANCE);
    expect(worst).toBeLessThanOrEqual(TOLERANCE);
    // And they stayed inside the box.
    for (const ball of balls) {
      expect(ball.position.x).toBeGreaterThan(0);
      expect(ball.position.x).toBeLessThan(size);
      expect(ball.position.y).toBeGreaterThan(0);
      expect(ball.position.y).toBeLessThan(size);
    }
  });
});
