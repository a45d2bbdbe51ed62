import fc from 'fast-check';
import { publicApiProperty } from './public-api-fuzz.ts';

// Long mode of the public API fuzz suite: `npm run fuzz -- --runs N [--seed S] [--path P]`. A new seed each
// run unless given; a failure prints the seed and the shrunk call sequence to replay it.

function option(name: string): string | undefined {
  const i = process.argv.indexOf(`--${name}`);
  return i >= 0 ? process.argv[i + 1] : undefined;
}

const runs = Number(option('runs') ?? 20000);
const seed = Number(option('seed') ?? Date.now() % 2 ** 31);
if (!Number.isInteger(runs) || runs < 1)
  throw new Error(`--runs must be a whole number, got ${runs}`);
const start = performance.now();
process.stdout.write(`fuzzing the public API: ${runs} runs, seed ${seed}\n`);
// --path replays one failure exactly (fast-check prints its seed and path).
const path = option('path');
fc.assert(publicApiProperty, { seed, numRuns: runs, ...(path === undefined ? {} : { path }) });
const seconds = ((performance.now() - start) / 1000).toFixed(1);
process.stdout.write(`${runs} runs passed in ${seconds} s (seed ${seed})\n`);
