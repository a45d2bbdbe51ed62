// The wide probe of the impact laws (issue #29): the laws of test/fidelity/impacts-that-travel.test.ts
// on many more cases than the test runs (gas seeds, mass ranges, ball counts, box sizes; chain mass
// ratios and a three-ball chain; the wedge at other masses; the ballistic pendulum at other rod
// lengths and hit depths), to find where the class fails rather than where its ten seeds pass.
//
//   npx tsx packages/engine/scripts/impacts-probe.ts [gas|chain|wedge|pendulum|all] [--seconds S]
//
// Prints one line per case and, at the end, the failures against the laws' tolerances.
import {
  ballisticPendulumErrors,
  dropOnRestingBalls,
  gasEnergyChange,
  sequentialRebound,
  wedgeEnergyGain,
} from '../test/fidelity/impact-scenes.ts';
import type { Gas } from '../test/fidelity/impact-scenes.ts';

const failures: string[] = [];
function report(name: string, value: number, tolerance: number): void {
  const bad = !(value < tolerance);
  // eslint-disable-next-line no-console
  console.log(
    `${bad ? 'FAIL' : 'ok  '} ${name}: ${value.toExponential(3)} (tolerance ${tolerance})`,
  );
  if (bad) failures.push(`${name}: ${value.toExponential(3)}`);
}

const args = process.argv.slice(2);
const section = args.find((a) => !a.startsWith('--')) ?? 'all';
const secondsIndex = args.indexOf('--seconds');
const seconds = secondsIndex >= 0 ? Number(args[secondsIndex + 1]) : 60;
const seedsIndex = args.indexOf('--seeds');
const seeds = seedsIndex >= 0 ? Number(args[seedsIndex + 1]) : 40;

if (section === 'gas' || section === 'all') {
  const cases: Gas[] = [];
  for (let seed = 1; seed <= seeds; seed++) {
    cases.push({ seed, balls: 16, size: 10, lightest: 0.1, heaviest: 6 });
  }
  for (let seed = 1; seed <= Math.min(seeds, 8); seed++) {
    cases.push({ seed, balls: 16, size: 10, lightest: 0.1, heaviest: 10 });
    cases.push({ seed, balls: 20 + 5 * (seed % 9), size: 10, lightest: 0.1, heaviest: 6 });
    cases.push({ seed, balls: 24, size: 6, lightest: 0.1, heaviest: 10 });
  }
  for (const c of cases) {
    const change = gasEnergyChange(c, seconds);
    report(
      `gas seed ${c.seed}, ${c.balls} balls, ${c.size} m box, ${c.lightest}-${c.heaviest} kg, ${seconds} s: signed change ${(100 * change).toFixed(2)} %`,
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
    const expected = sequentialRebound(...masses) * dropOnRestingBalls(masses[0]!);
    const got = dropOnRestingBalls(...masses);
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
        wedgeEnergyGain(light, heavy, speed, scene),
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
    const [omega, disc] = ballisticPendulumErrors({ L, d, M, m, u });
    report(`pendulum L ${L} d ${d} M ${M} m ${m} u ${u}: rod angular speed`, omega, 0.01);
    report(`pendulum L ${L} d ${d} M ${M} m ${m} u ${u}: disc speed`, disc, 0.01);
  }
}
// eslint-disable-next-line no-console
console.log(`\n${failures.length} failures\n${failures.join('\n')}`);
