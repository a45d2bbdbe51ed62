// The wide probe of the impact laws (issue #29): the laws of test/fidelity/impacts-that-travel.test.ts
// on many more cases than the test runs (gas seeds, mass ranges, ball counts, box sizes; chain mass
// ratios and a three-ball chain; the wedge at other masses; the ballistic pendulum at other rod
// lengths and hit depths), to find where the class fails rather than where its ten seeds pass.
//
//   npx tsx packages/engine/scripts/impacts-probe.ts [gas|chain|wedge|pendulum|all] [--seconds S]
//
// Prints one line per case and, at the end, the failures against the laws' tolerances.
import { World, box, particle, revoluteJoint } from '../src/index.ts';
import type { Body } from '../src/index.ts';

const DT = 1 / 60;

/** Mulberry32, as in the fidelity test. */
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

const failures: string[] = [];
function report(name: string, value: number, tolerance: number): void {
  const bad = !(value < tolerance);
  // eslint-disable-next-line no-console
  console.log(
    `${bad ? 'FAIL' : 'ok  '} ${name}: ${value.toExponential(3)} (tolerance ${tolerance})`,
  );
  if (bad) failures.push(`${name}: ${value.toExponential(3)}`);
}

interface GasCase {
  seed: number;
  balls: number;
  size: number;
  minMass: number;
  maxMass: number;
}

/** Energy change of an e = 1 gas after `seconds`, relative to its start. */
export function gas(c: GasCase, seconds: number): number {
  const world = new World();
  const material = { restitution: 1, friction: 0 };
  const size = c.size;
  const h = size / 2;
  for (const [x, y, width, height] of [
    [h, -0.5, size + 2, 1],
    [h, size + 0.5, size + 2, 1],
    [-0.5, h, 1, size + 2],
    [size + 0.5, h, 1, size + 2],
  ] as const) {
    world.add(box({ type: 'static', position: { x, y }, width, height, ...material }));
  }
  const rand = random(c.seed);
  const balls: Body[] = [];
  const side = Math.ceil(Math.sqrt(c.balls));
  const cell = size / side;
  for (let i = 0; i < c.balls; i++) {
    const radius = Math.min(0.2 + 0.15 * rand(), 0.45 * cell);
    const mass = c.minMass * (c.maxMass / c.minMass) ** rand();
    const speed = 2 + 4 * rand();
    const direction = 2 * Math.PI * rand();
    balls.push(
      world.add(
        particle({
          position: { x: cell * (0.5 + (i % side)), y: cell * (0.5 + Math.floor(i / side)) },
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
    balls.reduce((sum, b) => sum + b.kineticEnergy + b.mass * g * (size - b.position.y), 0);
  const start = energy();
  for (let i = 0; i < seconds / DT; i++) world.step(DT);
  return (energy() - start) / start;
}

/** Sequential impacts of a chain of balls (top first, downward positive) falling at 1 on the rest. */
function sequential(masses: readonly number[]): number {
  const v: number[] = masses.map((_, i) => (i === 0 ? 1 : 0));
  const n = masses.length;
  for (let k = 0; k < 100000; k++) {
    let acted = false;
    for (let i = 0; i < n; i++) {
      if (i < n - 1 && v[i]! > v[i + 1]!) {
        const m1 = masses[i]!;
        const m2 = masses[i + 1]!;
        const u1 = ((m1 - m2) * v[i]! + 2 * m2 * v[i + 1]!) / (m1 + m2);
        const u2 = ((m2 - m1) * v[i + 1]! + 2 * m1 * v[i]!) / (m1 + m2);
        v[i] = u1;
        v[i + 1] = u2;
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

/** Rebound height over drop height of the top ball of `masses` (top first) dropped on the rest. */
function chain(masses: readonly number[]): number {
  const world = new World();
  const material = { restitution: 1, friction: 0 };
  world.add(box({ type: 'static', position: { x: 0, y: 0.5 }, width: 20, height: 1, ...material }));
  const area = Math.PI * RADIUS * RADIUS;
  const n = masses.length;
  // Resting balls from the floor up (the last mass at the bottom).
  for (let k = n - 1; k >= 1; k--) {
    const level = n - 1 - k;
    world.add(
      particle({
        position: { x: 0, y: -RADIUS - 2 * RADIUS * level },
        radius: RADIUS,
        density: masses[k]! / area,
        ...material,
      }),
    );
  }
  const touchY = -RADIUS - 2 * RADIUS * (n - 1);
  const top = world.add(
    particle({
      position: { x: 0, y: touchY - DROP },
      radius: RADIUS,
      density: masses[0]! / area,
      ...material,
    }),
  );
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

/** Largest energy gain in a step of a light ball wedged under a heavy one (no gravity). */
function wedge(
  light: number,
  heavy: number,
  speed: number,
  scene: 'sliding' | 'coming down',
): number {
  const world = new World({ gravity: { x: 0, y: 0 } });
  const material = { restitution: 1, friction: 0 };
  world.add(box({ type: 'static', position: { x: 0, y: 0.5 }, width: 40, height: 1, ...material }));
  const a = world.add(
    particle({
      position: scene === 'sliding' ? { x: -3, y: -0.1 } : { x: 0, y: -0.1 },
      radius: 0.1,
      density: light / (Math.PI * 0.01),
      linearVelocity: scene === 'sliding' ? { x: speed, y: 0 } : { x: 0, y: 0 },
      ...material,
    }),
  );
  const b = world.add(
    particle({
      position: scene === 'sliding' ? { x: 0, y: -0.5 } : { x: 0.05, y: -2 },
      radius: 0.5,
      density: heavy / (Math.PI * 0.25),
      linearVelocity: scene === 'sliding' ? { x: 0, y: 0 } : { x: 0, y: speed / 4 },
      ...material,
    }),
  );
  const e = (): number => a.kineticEnergy + b.kineticEnergy;
  let worst = 0;
  let before = e();
  for (let i = 0; i < 180; i++) {
    world.step(DT);
    const after = e();
    worst = Math.max(worst, (after - before) / before);
    before = after;
  }
  return worst;
}

/** Elastic ballistic pendulum: relative errors of the rod's angular speed and the disc's speed. */
function pendulum(L: number, d: number, M: number, m: number, u: number): [number, number] {
  const world = new World({ gravity: { x: 0, y: 0 } });
  const ground = world.add(
    box({ type: 'static', position: { x: 0, y: -1 }, width: 1, height: 0.2 }),
  );
  const width = 0.1;
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
  const inertia = (M * (L * L + width * width)) / 3;
  const mr = inertia / (d * d);
  const discAfter = ((m - mr) / (m + mr)) * u;
  const omegaAfter = (((2 * m) / (m + mr)) * u) / d;
  for (let i = 0; i < 40; i++) world.step(DT);
  return [
    Math.abs(Math.abs(rod.angularVelocity) - Math.abs(omegaAfter)) / Math.abs(omegaAfter),
    Math.abs(disc.linearVelocity.x - discAfter) / Math.max(Math.abs(discAfter), 0.05 * u),
  ];
}

const args = process.argv.slice(2);
const section = args.find((a) => !a.startsWith('--')) ?? 'all';
const secondsIndex = args.indexOf('--seconds');
const seconds = secondsIndex >= 0 ? Number(args[secondsIndex + 1]) : 60;
const seedsIndex = args.indexOf('--seeds');
const seeds = seedsIndex >= 0 ? Number(args[seedsIndex + 1]) : 40;

if (section === 'gas' || section === 'all') {
  const cases: GasCase[] = [];
  for (let seed = 1; seed <= seeds; seed++) {
    cases.push({ seed, balls: 16, size: 10, minMass: 0.1, maxMass: 6 });
  }
  for (let seed = 1; seed <= Math.min(seeds, 8); seed++) {
    cases.push({ seed, balls: 16, size: 10, minMass: 0.1, maxMass: 10 });
    cases.push({ seed, balls: 20 + 5 * (seed % 9), size: 10, minMass: 0.1, maxMass: 6 });
    cases.push({ seed, balls: 24, size: 6, minMass: 0.1, maxMass: 10 });
  }
  for (const c of cases) {
    const change = gas(c, seconds);
    report(
      `gas seed ${c.seed}, ${c.balls} balls, ${c.size} m box, ${c.minMass}-${c.maxMass} kg, ${seconds} s: signed change ${(100 * change).toFixed(2)} %`,
      Math.abs(change),
      0.02,
    );
  }
}
if (section === 'chain' || section === 'all') {
  for (const masses of [
    [1, 1],
    [1, 2],
    [1, 3],
    [2, 1],
    [3, 1],
    [4, 1],
    [8, 1],
    [1, 1, 1],
    [1, 2, 3],
    [3, 2, 1],
  ]) {
    const expected = sequential(masses) * chain([masses[0]!]);
    const got = chain(masses);
    report(
      `chain ${masses.join(':')} (top first): rebound ${got.toFixed(4)} expected ${expected.toFixed(4)}`,
      Math.abs(got - expected) / Math.max(expected, 0.05),
      0.02,
    );
  }
}
if (section === 'wedge' || section === 'all') {
  for (const [light, heavy, speed] of [
    [0.15, 5.9, 17],
    [0.1, 10, 17],
    [0.5, 5, 10],
    [0.1, 3, 30],
    [1, 60, 8],
  ] as const) {
    for (const scene of ['sliding', 'coming down'] as const) {
      report(
        `wedge ${scene} ${light}:${heavy} kg at ${speed} m/s`,
        wedge(light, heavy, speed, scene),
        0.001,
      );
    }
  }
}
if (section === 'pendulum' || section === 'all') {
  for (const [L, d, M, m, u] of [
    [2, 1, 2, 1, 3],
    [1, 0.5, 2, 1, 3],
    [1, 0.9, 1, 1, 3],
    [3, 2.5, 2, 1, 3],
    [3, 1, 5, 0.5, 5],
    [2, 1.8, 0.5, 1, 2],
  ] as const) {
    const [omega, disc] = pendulum(L, d, M, m, u);
    report(`pendulum L ${L} d ${d} M ${M} m ${m} u ${u}: rod angular speed`, omega, 0.01);
    report(`pendulum L ${L} d ${d} M ${M} m ${m} u ${u}: disc speed`, disc, 0.01);
  }
}
// eslint-disable-next-line no-console
console.log(`\n${failures.length} failures\n${failures.join('\n')}`);
