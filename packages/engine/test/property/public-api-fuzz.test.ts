import fc from 'fast-check';
import { describe, it } from 'vitest';
import { publicApiProperty } from './public-api-fuzz.ts';

// The public API under random valid and invalid calls (see public-api-fuzz.ts for what each run
// checks). Fixed seed and run count in CI; `npm run fuzz -- --runs N` runs it long with a new seed.

const RUNS = 2000;

describe('the public API under fuzzing', () => {
  it(`every call succeeds or throws a PhysicalError, refusals change nothing (${RUNS} runs)`, () => {
    fc.assert(publicApiProperty, { seed: 15, numRuns: RUNS });
  }, 120_000);
});
