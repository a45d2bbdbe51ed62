import { execFileSync } from 'node:child_process';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';

// Each fixture uses the tag as its framework would and holds `@ts-expect-error` lines, so it
// fails to compile both when a declaration is missing and when one accepts a wrong value.
// One tsc program checks all four (a program is slow to start); errors are sorted by file.
const fixtures = fileURLToPath(new URL('../../typings-fixtures/', import.meta.url));
const tsc = createRequire(import.meta.url).resolve('typescript/bin/tsc');

let output = '';

beforeAll(() => {
  try {
    execFileSync(process.execPath, [tsc, '-p', `${fixtures}tsconfig.json`], { encoding: 'utf8' });
  } catch (error) {
    output = String((error as { stdout?: string }).stdout ?? error);
  }
}, 300_000);

describe('the tag is typed in each framework', () => {
  it.each([
    ['dom.ts', 'HTMLElementTagNameMap and HTMLElementEventMap from @physical/canvas/define'],
    ['react.tsx', 'React 19 JSX from @physical/canvas/jsx'],
    ['vue.ts', 'Vue templates from @physical/canvas/vue'],
    ['svelte.ts', 'Svelte 5 templates from @physical/canvas/svelte'],
  ])('%s: %s compiles under strict tsc', (fixture) => {
    const errors = output.split('\n').filter((line) => line.includes(fixture));
    expect(errors).toEqual([]);
  });

  it('the declarations themselves compile (no error outside the fixtures either)', () => {
    expect(output).toBe('');
  });
});
