// The scenes of the impact laws (issue #29), shared by test/fidelity/impacts-that-travel.test.ts,
// which runs them on a few cases, and scripts/impacts-probe.ts, which runs them on many more.
// Imported by path (not '@physical/engine') so the probe runs on the sources without a build;
// vitest's alias points '@physical/engine' at the same file.
import { World, box, particle, revoluteJoint } from '../../src/index.ts';
import type { Body } from '../../src/index.ts';

export const DT = 1 / 60;

/** Mulberry32: a small seeded PRNG, so a scene is the same on every run. */
export function random(seed: number): () => number {
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
 * Sequential impacts (e = 1) of a top ball falling at speed 1 on a column of balls resting on the
 * floor, `masses` from the top down: each round, every touching pair that approaches from the top
 * down, then the floor, until nothing approaches. Returns the top ball's rebound speed squared,
 * i.e. its rebound height over its drop height. (With two balls the order is forced; with three
 * equal ones every order gives the same answer: the impulse passes through unchanged.)
 */
export function sequentialRebound(...masses: number[]): number {
  // Downward positive.
  const v: number[] = masses.map((_, i) => (i === 0 ? 1 : 0));
  const n = masses.length;
  for (let round = 0; round < 1000; round++) {
    let acted = false;
    for (let i = 0; i + 1 < n; i++) {
      if (v[i]! > v[i + 1]!) {
        const m1 = masses[i]!;
        const m2 = masses[i + 1]!;
        const u1 = ((m1 - m2) * v[i]! + 2 * m2 * v[i + 1]!) / (m1 + m2);
        v[i + 1] = ((m2 - m1) * v[i + 1]! + 2 * m1 * v[i]!) / (m1 + m2);
        v[i] = u1;
        acted = true;
      }
    }
    if (v[n - 1]! > 0) {
      v[n - 1] = -v[n - 1]!;
      acted = true;
    }
    if (!acted) break;
  }
  return v[0]! < 0 ? v[0]! * v[0]! : 0;
}

const RADIUS = 0.25;
const DROP = 1;
const ELASTIC = { restitution: 1, friction: 0 };

/**
 * Top ball's rebound height over its drop height: a ball of mass `masses[0]` dropped on a column
 * of balls of the other masses (from the top down) resting on the floor; with one mass, the ball
 * dropped on the floor itself.
 */
export function dropOnRestingBalls(...masses: number[]): number {
  const world = new World();
  // Floor's top face at y = 0 (y-down).
  world.add(box({ type: 'static', position: { x: 0, y: 0.5 }, width: 20, height: 1, ...ELASTIC }));
  const area = Math.PI * RADIUS * RADIUS;
  const resting = masses.length - 1;
  // The resting column, from the floor up.
  for (let k = 0; k < resting; k++) {
    world.add(
      particle({
        position: { x: 0, y: -RADIUS - 2 * RADIUS * k },
        radius: RADIUS,
        density: masses[resting - k]! / area,
        ...ELASTIC,
      }),
    );
  }
  const touchY = -RADIUS - 2 * RADIUS * resting;
  const top = world.add(
    particle({
      position: { x: 0, y: touchY - DROP },
      radius: RADIUS,
      density: masses[0]! / area,
      ...ELASTIC,
    }),
  );
  // The first rebound's apex: after the hit, until the top ball falls again (the balls may
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
export function energy(bodies: readonly Body[], g: number): number {
  let sum = 0;
  for (const body of bodies) sum += body.kineticEnergy - body.mass * g * body.position.y;
  return sum;
}

/** An e = 1, frictionless gas in a closed square box under gravity. */
export interface Gas {
  seed: number;
  /** How many balls, on a grid. */
  balls: number;
  /** The box's side (m). */
  size: number;
  /** Masses spread evenly on a log scale from the lightest to the heaviest (kg). */
  lightest: number;
  heaviest: number;
}

/**
 * Relative energy change in `seconds` of a gas of balls (radius 0.2-0.35 m, at most 0.45 of a grid
 * cell; speeds 2-6 m/s).
 */
export function gasEnergyChange(gas: Gas, seconds = 60): number {
  const world = new World();
  const { size } = gas;
  const h = size / 2;
  for (const [x, y, width, height] of [
    [h, -0.5, size + 2, 1],
    [h, size + 0.5, size + 2, 1],
    [-0.5, h, 1, size + 2],
    [size + 0.5, h, 1, size + 2],
  ] as const) {
    world.add(box({ type: 'static', position: { x, y }, width, height, ...ELASTIC }));
  }
  const rand = random(gas.seed);
  const balls: Body[] = [];
  const side = Math.ceil(Math.sqrt(gas.balls));
  const cell = size / side;
  for (let i = 0; i < gas.balls; i++) {
    const radius = Math.min(0.2 + 0.15 * rand(), 0.45 * cell);
    const mass = gas.lightest * (gas.heaviest / gas.lightest) ** rand();
    const speed = 2 + 4 * rand();
    const direction = 2 * Math.PI * rand();
    balls.push(
      world.add(
        particle({
          position: { x: cell * (0.5 + (i % side)), y: cell * (0.5 + Math.floor(i / side)) },
          radius,
          density: mass / (Math.PI * radius * radius),
          linearVelocity: { x: speed * Math.cos(direction), y: speed * Math.sin(direction) },
          ...ELASTIC,
        }),
      ),
    );
  }
  // Potential energy from the floor (its top at y = size, y-down), so the relative change is
  // of an energy that is positive throughout.
  const g = world.gravity.y;
  const total = (): number =>
    balls.reduce((sum, b) => sum + b.kineticEnergy + b.mass * g * (size - b.position.y), 0);
  const start = total();
  for (let i = 0; i < seconds / DT; i++) world.step(DT);
  return (total() - start) / start;
}

/**
 * Largest energy gain in a step of a light ball wedged under a heavy one, without gravity (so the
 * energy is all kinetic): the light ball sliding along the floor at `speed` into the heavy one
 * resting on it, or the heavy ball coming down at `speed` / 4 on the light one lying on the floor.
 */
export function wedgeEnergyGain(
  light: number,
  heavy: number,
  speed: number,
  scene: 'sliding' | 'coming down',
): number {
  const world = new World({ gravity: { x: 0, y: 0 } });
  world.add(box({ type: 'static', position: { x: 0, y: 0.5 }, width: 40, height: 1, ...ELASTIC }));
  const a = world.add(
    particle({
      position: scene === 'sliding' ? { x: -3, y: -0.1 } : { x: 0, y: -0.1 },
      radius: 0.1,
      density: light / (Math.PI * 0.01),
      linearVelocity: scene === 'sliding' ? { x: speed, y: 0 } : { x: 0, y: 0 },
      ...ELASTIC,
    }),
  );
  const b = world.add(
    particle({
      position: scene === 'sliding' ? { x: 0, y: -0.5 } : { x: 0.05, y: -2 },
      radius: 0.5,
      density: heavy / (Math.PI * 0.25),
      linearVelocity: scene === 'sliding' ? { x: 0, y: 0 } : { x: 0, y: speed / 4 },
      ...ELASTIC,
    }),
  );
  const bodies = [a, b];
  let worst = 0;
  let before = energy(bodies, 0);
  for (let i = 0; i < 180; i++) {
    world.step(DT);
    const after = energy(bodies, 0);
    worst = Math.max(worst, (after - before) / before);
    before = after;
  }
  return worst;
}

/** An elastic ballistic pendulum: a disc of mass `m` at speed `u` hits, at depth `d`, a rod of length `L` and mass `M` pinned at its top end. */
export interface BallisticPendulum {
  L: number;
  d: number;
  M: number;
  m: number;
  u: number;
}

/**
 * Relative errors of the rod's angular speed and the disc's speed after the hit against the closed
 * form: the rod turns about the pin with inertia M (L^2 + width^2) / 3, so its point at depth d has
 * the effective mass I / d^2, and the hit is an elastic collision of m with that mass. The disc's
 * error is relative to its speed after, or to 5 % of u where it nearly stops.
 */
export function ballisticPendulumErrors({ L, d, M, m, u }: BallisticPendulum): [number, number] {
  const world = new World({ gravity: { x: 0, y: 0 } });
  const ground = world.add(
    box({ type: 'static', position: { x: 0, y: -1 }, width: 1, height: 0.2 }),
  );
  const width = 0.1;
  // The rod hangs from its top end at the origin (y-down), along +y.
  const rod = world.add(
    box({ position: { x: 0, y: L / 2 }, width, height: L, density: M / (width * L), ...ELASTIC }),
  );
  world.addJoint(revoluteJoint({ bodyA: ground, bodyB: rod, anchor: { x: 0, y: 0 } }));
  const r = 0.1;
  const disc = world.add(
    particle({
      position: { x: -1, y: d },
      radius: r,
      density: m / (Math.PI * r * r),
      linearVelocity: { x: u, y: 0 },
      ...ELASTIC,
    }),
  );
  const inertia = (M * (L * L + width * width)) / 3;
  const mr = inertia / (d * d);
  const discAfter = ((m - mr) / (m + mr)) * u;
  const omegaAfter = (((2 * m) / (m + mr)) * u) / d;
  for (let i = 0; i < 40; i++) world.step(DT);
  // y-down: a rod swinging to +x turns clockwise on screen; compare speeds.
  return [
    Math.abs(Math.abs(rod.angularVelocity) - Math.abs(omegaAfter)) / Math.abs(omegaAfter),
    Math.abs(disc.linearVelocity.x - discAfter) / Math.max(Math.abs(discAfter), 0.05 * u),
  ];
}
