import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, particle } from '@physical/engine';
import type { Body } from '@physical/engine';

// Law: e = 1 is elastic in the default world (no restitutionThreshold set). 20 frictionless e = 1
// balls in a closed box without gravity keep their kinetic energy within 1 % for 60 s; yet a 20-row
// pyramid of e = 0.5 boxes stands still (top box moves < 1 cm after its first second) and sleeps by
// 12 s, and a ball with e = 0.5 dropped from 2 m comes to rest and sleeps within 4 s.

const DT = 1 / 60;
const ENERGY_TOLERANCE = 0.01;
const TOP_TOLERANCE = 0.01;
const BALL_SLEEPS_BY = 4;

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

describe('elastic by default', () => {
  it('an e = 1 gas keeps its kinetic energy for 60 s with the default threshold', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const material = { restitution: 1, friction: 0 };
    const walls = [
      [5, -0.5, 12, 1],
      [5, 10.5, 12, 1],
      [-0.5, 5, 1, 12],
      [10.5, 5, 1, 12],
    ] as const;
    for (const [x, y, width, height] of walls) {
      world.add(box({ type: 'static', position: { x, y }, width, height, ...material }));
    }
    const rand = random(12345);
    const balls: Body[] = [];
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
    const energy = (): number => balls.reduce((sum, ball) => sum + ball.kineticEnergy, 0);
    const start = energy();
    let worst = 0;
    for (let i = 0; i < 60 / DT; i++) {
      world.step(DT);
      worst = Math.max(worst, Math.abs(energy() - start) / start);
    }
    reportMeasured('elastic by default: gas energy drift in 60 s', worst, ENERGY_TOLERANCE);
    expect(worst).toBeLessThan(ENERGY_TOLERANCE);
  }, 60_000);

  it('a pyramid of e = 0.5 boxes stands without jitter and sleeps', () => {
    const world = new World();
    world.add(
      box({ type: 'static', position: { x: 0, y: 0.5 }, width: 80, height: 1, restitution: 0.5 }),
    );
    const boxes: Body[] = [];
    for (let row = 0; row < 20; row++) {
      for (let k = 0; k < 20 - row; k++) {
        const x = (k - (19 - row) / 2) * 1.05;
        boxes.push(
          world.add(box({ position: { x, y: -0.5 - row }, width: 1, height: 1, restitution: 0.5 })),
        );
      }
    }
    const top = boxes[boxes.length - 1]!;
    let settled = { x: 0, y: 0 };
    let move = 0;
    for (let i = 1; i <= 12 / DT; i++) {
      world.step(DT);
      if (i === 60) settled = { x: top.position.x, y: top.position.y };
      else if (i > 60 && i <= 600) {
        move = Math.max(move, Math.hypot(top.position.x - settled.x, top.position.y - settled.y));
      }
    }
    reportMeasured('elastic by default: e = 0.5 pyramid top movement (m)', move, TOP_TOLERANCE);
    expect(move).toBeLessThan(TOP_TOLERANCE);
    expect(boxes.filter((b) => b.isAwake)).toHaveLength(0);
  }, 60_000);

  it('a ball with e = 0.5 stops bouncing and sleeps', () => {
    const world = new World();
    world.add(
      box({ type: 'static', position: { x: 0, y: 0.5 }, width: 40, height: 1, restitution: 0.5 }),
    );
    const ball = world.add(particle({ position: { x: 0, y: -2 }, radius: 0.25, restitution: 0.5 }));
    let asleepAt = Infinity;
    let bounced = false;
    for (let i = 1; i <= 10 / DT && asleepAt === Infinity; i++) {
      world.step(DT);
      if (ball.linearVelocity.y < -1) bounced = true;
      if (!ball.isAwake) asleepAt = i * DT;
    }
    reportMeasured('elastic by default: e = 0.5 ball asleep after (s)', asleepAt, BALL_SLEEPS_BY);
    expect(bounced).toBe(true);
    expect(asleepAt).toBeLessThan(BALL_SLEEPS_BY);
  });
});
