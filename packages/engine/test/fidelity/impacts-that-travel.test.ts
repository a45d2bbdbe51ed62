import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, particle, revoluteJoint } from '@physical/engine';
import type { Body } from '@physical/engine';

// Laws of impacts that travel (issue #29): an impact that passes through a body already pressed
// (by the ground, by another body) or held (by a joint) keeps momentum, and with e = 1 energy.
// - A ball dropped on a ball resting on the floor, e = 1, rebounds as sequential impacts say
//   (a vertical Newton's cradle): equal masses to the drop height, within 2 %; top:bottom mass
//   ratios 1:2, 1:3 and 2:1 to the sequential-impact height, within 2 %.
// - An elastic gas of unlike masses (0.1-6 kg, e = 1, no friction) under gravity in a closed box
//   keeps its energy within 2 % for 60 s, in each of 10 seeded starts.
// - A light ball wedged between the floor and a heavy one (e = 1): the energy never rises in a step
//   by more than 0.1 %.
// - An elastic ballistic pendulum (a disc hits a rod pinned at one end, e = 1): the rod's angular
//   speed and the disc's speed are the closed form's within 1 %.
// - A resting e = 1 ball on the ground stays put (< 1 cm) and sleeps by 12 s (the resting 20-row
//   pyramid of e = 0.5 boxes is test/fidelity/elastic-by-default.test.ts).

const DT = 1 / 60;

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

/**
 * Sequential impacts (e = 1) of a top ball of mass m1 falling at speed 1 on a ball of mass m2
 * resting on the floor: top on bottom, bottom on floor, top on bottom ... until nothing approaches.
 * Returns the top ball's rebound speed squared, i.e. its rebound height over its drop height.
 */
function sequentialRebound(m1: number, m2: number): number {
  // Downward positive.
  let v1 = 1;
  let v2 = 0;
  for (let k = 0; k < 1000; k++) {
    if (v1 > v2) {
      const total = m1 + m2;
      const u1 = ((m1 - m2) * v1 + 2 * m2 * v2) / total;
      const u2 = ((m2 - m1) * v2 + 2 * m1 * v1) / total;
      v1 = u1;
      v2 = u2;
    } else if (v2 > 0) v2 = -v2;
    else break;
  }
  return v1 < 0 ? v1 * v1 : 0;
}

const RADIUS = 0.25;
const DROP = 1;

/**
 * Top ball's rebound height over its drop height, for masses m1 (top) and m2 (bottom); with m2
 * null, the ball dropped on the floor itself.
 */
function dropOnRestingBall(m1: number, m2: number | null): number {
  const world = new World();
  const material = { restitution: 1, friction: 0 };
  // Floor's top face at y = 0 (y-down).
  world.add(box({ type: 'static', position: { x: 0, y: 0.5 }, width: 20, height: 1, ...material }));
  const area = Math.PI * RADIUS * RADIUS;
  if (m2 !== null) {
    world.add(
      particle({ position: { x: 0, y: -RADIUS }, radius: RADIUS, density: m2 / area, ...material }),
    );
  }
  const touchY = m2 === null ? -RADIUS : -3 * RADIUS;
  const top = world.add(
    particle({
      position: { x: 0, y: touchY - DROP },
      radius: RADIUS,
      density: m1 / area,
      ...material,
    }),
  );
  // The first rebound's apex: after the hit, until the top ball falls again (the two balls may
  // come down together and bounce again).
  let hit = false;
  let peak = Infinity;
  for (let i = 0; i < 240; i++) {
    world.step(DT);
    if (top.linearVelocity.y < 0) hit = true;
    if (hit && top.linearVelocity.y > 0) break;
    if (hit) peak = Math.min(peak, top.position.y);
  }
  return hit ? (touchY - peak) / DROP : 0;
}

/** Kinetic plus potential energy (y-down, gravity g, zero at y = 0). */
function energy(bodies: readonly Body[], g: number): number {
  let sum = 0;
  for (const body of bodies) sum += body.kineticEnergy - body.mass * g * body.position.y;
  return sum;
}

describe('impacts that travel', () => {
  it('a ball dropped on an equal ball resting on the floor (e = 1) rebounds to its drop height', () => {
    const ratio = dropOnRestingBall(1, 1);
    expect(sequentialRebound(1, 1)).toBeCloseTo(1, 12);
    const error = Math.abs(ratio - 1);
    reportMeasured('ball on a resting equal ball, e = 1: rebound / drop height - 1', error, 0.02);
    expect(error).toBeLessThan(0.02);
  });

  it.each([
    [1, 2],
    [1, 3],
    [2, 1],
  ])(
    'a %s kg ball dropped on a %s kg ball resting on the floor rebounds to the sequential-impact height',
    (m1, m2) => {
      // Against the ball's own rebound off the floor (restitution.test.ts's law): the
      // semi-implicit Euler flight loses u h / 2 of height at launch speed u, 2 % of a rebound to
      // a quarter of the drop height, which is the integrator's, not the impact's.
      const expected = sequentialRebound(m1, m2) * dropOnRestingBall(m1, null);
      const error = Math.abs(dropOnRestingBall(m1, m2) - expected) / expected;
      reportMeasured(
        `ball on a resting ball, ${m1}:${m2} kg, e = 1: rebound height, relative error`,
        error,
        0.02,
      );
      expect(error).toBeLessThan(0.02);
    },
  );

  it('an e = 1 gas of unlike masses (0.1-6 kg) under gravity keeps its energy within 2 % for 60 s, every one of 10 starts', () => {
    const SIZE = 10;
    const changes: number[] = [];
    for (let seed = 1; seed <= 10; seed++) {
      const world = new World();
      const material = { restitution: 1, friction: 0 };
      // A closed 10 m box, the floor's top at y = SIZE (y-down).
      const h = SIZE / 2;
      for (const [x, y, width, height] of [
        [h, -0.5, SIZE + 2, 1],
        [h, SIZE + 0.5, SIZE + 2, 1],
        [-0.5, h, 1, SIZE + 2],
        [SIZE + 0.5, h, 1, SIZE + 2],
      ] as const) {
        world.add(box({ type: 'static', position: { x, y }, width, height, ...material }));
      }
      const rand = random(seed);
      const balls: Body[] = [];
      const cell = SIZE / 4;
      for (let i = 0; i < 16; i++) {
        const radius = 0.2 + 0.15 * rand();
        // Masses spread evenly on a log scale from 0.1 to 6 kg.
        const mass = 0.1 * 60 ** rand();
        const speed = 2 + 4 * rand();
        const direction = 2 * Math.PI * rand();
        balls.push(
          world.add(
            particle({
              position: { x: cell * (0.5 + (i % 4)), y: cell * (0.5 + Math.floor(i / 4)) },
              radius,
              density: mass / (Math.PI * radius * radius),
              linearVelocity: { x: speed * Math.cos(direction), y: speed * Math.sin(direction) },
              ...material,
            }),
          ),
        );
      }
      const g = world.gravity.y;
      const energy = (): number =>
        balls.reduce((sum, b) => sum + b.kineticEnergy + b.mass * g * (SIZE - b.position.y), 0);
      const start = energy();
      for (let i = 0; i < 60 / DT; i++) world.step(DT);
      changes.push(Math.abs(energy() - start) / start);
    }
    const worst = Math.max(...changes);
    reportMeasured(
      'e = 1 gas of unlike masses under gravity, worst of 10 starts, energy change in 60 s',
      worst,
      0.02,
    );
    expect(changes).toHaveLength(10);
    expect(worst).toBeLessThan(0.02);
  }, 120_000);

  it('a light ball wedged between the floor and a heavy one (e = 1) never gains more than 0.1 % of the energy in a step', () => {
    // Two wedges: a light ball sliding along the floor into a heavy one that touches the floor (the
    // heavy ball's slope presses it into the floor), and a heavy ball coming down on a light one
    // lying on the floor. Without gravity, so that the energy is all kinetic: under gravity the
    // semi-implicit Euler flight and a bounce's catch-up change the energy between step ends by up
    // to 2 % for a single ball bouncing on the floor, which would hide what the wedge does.
    let worst = 0;
    for (const scene of ['sliding', 'coming down'] as const) {
      const world = new World({ gravity: { x: 0, y: 0 } });
      const material = { restitution: 1, friction: 0 };
      world.add(
        box({ type: 'static', position: { x: 0, y: 0.5 }, width: 40, height: 1, ...material }),
      );
      const light = world.add(
        particle({
          position: scene === 'sliding' ? { x: -3, y: -0.1 } : { x: 0, y: -0.1 },
          radius: 0.1,
          density: 0.15 / (Math.PI * 0.01),
          linearVelocity: scene === 'sliding' ? { x: 17, y: 0 } : { x: 0, y: 0 },
          ...material,
        }),
      );
      const heavy = world.add(
        particle({
          position: scene === 'sliding' ? { x: 0, y: -0.5 } : { x: 0.05, y: -2 },
          radius: 0.5,
          density: 5.9 / (Math.PI * 0.25),
          linearVelocity: scene === 'sliding' ? { x: 0, y: 0 } : { x: 0, y: 4 },
          ...material,
        }),
      );
      const bodies = [light, heavy];
      let before = energy(bodies, 0);
      for (let i = 0; i < 180; i++) {
        world.step(DT);
        const after = energy(bodies, 0);
        worst = Math.max(worst, (after - before) / before);
        before = after;
      }
    }
    reportMeasured(
      'light ball wedged under a heavy one, e = 1: largest energy gain in a step',
      worst,
      0.001,
    );
    expect(worst).toBeLessThan(0.001);
  });

  it('an elastic ballistic pendulum (a disc hits a rod pinned at one end) leaves at the closed-form speeds', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const ground = world.add(
      box({ type: 'static', position: { x: 0, y: -1 }, width: 1, height: 0.2 }),
    );
    const L = 2;
    const M = 2;
    const width = 0.1;
    // The rod hangs from its top end at the origin (y-down), along +y.
    const rod = world.add(
      box({
        position: { x: 0, y: L / 2 },
        width,
        height: L,
        density: M / (width * L),
        restitution: 1,
        friction: 0,
      }),
    );
    world.addJoint(revoluteJoint({ bodyA: ground, bodyB: rod, anchor: { x: 0, y: 0 } }));
    const m = 1;
    const u = 3;
    const d = 1;
    const r = 0.1;
    const disc = world.add(
      particle({
        position: { x: -1, y: d },
        radius: r,
        density: m / (Math.PI * r * r),
        linearVelocity: { x: u, y: 0 },
        restitution: 1,
        friction: 0,
      }),
    );
    // Closed form: the rod turns about the pin, inertia M (L^2 + width^2) / 3 there; its point at
    // depth d has the effective mass I / d^2. Elastic collision of m with that mass.
    const inertia = (M * (L * L + width * width)) / 3;
    const mr = inertia / (d * d);
    const discAfter = ((m - mr) / (m + mr)) * u;
    const omegaAfter = (((2 * m) / (m + mr)) * u) / d;
    for (let i = 0; i < 40; i++) world.step(DT);
    // y-down: a rod swinging to +x turns clockwise on screen, a negative angle in y-up terms;
    // compare speeds.
    const omegaError =
      Math.abs(Math.abs(rod.angularVelocity) - Math.abs(omegaAfter)) / Math.abs(omegaAfter);
    const discError = Math.abs(disc.linearVelocity.x - discAfter) / Math.abs(discAfter);
    reportMeasured(
      'elastic ballistic pendulum: rod angular speed, relative error',
      omegaError,
      0.01,
    );
    reportMeasured('elastic ballistic pendulum: disc speed, relative error', discError, 0.01);
    expect(omegaError).toBeLessThan(0.01);
    expect(discError).toBeLessThan(0.01);
  });

  it('a resting e = 1 ball on the ground stays put and sleeps by 12 s', () => {
    const world = new World();
    world.add(
      box({ type: 'static', position: { x: 0, y: 0.5 }, width: 20, height: 1, restitution: 1 }),
    );
    const ball = world.add(
      particle({ position: { x: 0, y: -0.25 }, radius: 0.25, restitution: 1 }),
    );
    let move = 0;
    let asleepAt = Infinity;
    for (let i = 1; i <= 12 / DT; i++) {
      world.step(DT);
      move = Math.max(move, Math.hypot(ball.position.x, ball.position.y + 0.25));
      if (!ball.isAwake && asleepAt === Infinity) asleepAt = i * DT;
    }
    reportMeasured('resting e = 1 ball: largest move (m)', move, 0.01);
    reportMeasured('resting e = 1 ball: asleep after (s)', asleepAt, 12);
    expect(move).toBeLessThan(0.01);
    expect(asleepAt).toBeLessThanOrEqual(12);
  });
});
