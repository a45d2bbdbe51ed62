import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import ts from 'typescript';
import { afterEach, describe, expect, it, vi } from 'vitest';

// The root README's example is type-checked and executed as written: extracted, saved as a module,
// checked with the compiler against the engine's sources, and imported (the test runner resolves
// '@physical/engine' to the sources), so it can never rot.

const here = dirname(fileURLToPath(import.meta.url));
const readme = readFileSync(join(here, '../../../../README.md'), 'utf8');

function extractExample(markdown: string): string {
  const section = markdown.split('## Example')[1];
  const match = section === undefined ? null : /```ts\n([\s\S]*?)```/.exec(section);
  if (match === null) throw new Error('README.md has no ```ts block under "## Example".');
  return match[1]!;
}

function writeExample(): string {
  const folder = join(here, 'generated');
  mkdirSync(folder, { recursive: true });
  const file = join(folder, 'readme-example.ts');
  writeFileSync(file, extractExample(readme));
  return file;
}

describe('the README example', () => {
  afterEach(() => {
    vi.restoreAllMocks();
  });

  it('type-checks against the public API', () => {
    const file = writeExample();
    const program = ts.createProgram([file], {
      strict: true,
      noEmit: true,
      target: ts.ScriptTarget.ES2022,
      module: ts.ModuleKind.ESNext,
      moduleResolution: ts.ModuleResolutionKind.Bundler,
      allowImportingTsExtensions: true,
      skipLibCheck: true,
      types: [],
      paths: { '@physical/engine': [join(here, '../../src/index.ts')] },
    });
    const diagnostics = ts
      .getPreEmitDiagnostics(program)
      .map((d) => ts.flattenDiagnosticMessageText(d.messageText, '\n'));
    expect(diagnostics).toEqual([]);
  }, 30_000);

  it('runs and prints what its comments promise', async () => {
    const lines: string[] = [];
    vi.spyOn(console, 'log').mockImplementation((line: unknown) => {
      lines.push(String(line));
    });
    await import(/* @vite-ignore */ writeExample());

    const rest = lines.find((line) => line.startsWith('ball rests at y = '));
    expect(rest).toBeDefined();
    // Floor at y = 10, radius 0.5: the ball's centre rests at 9.5 m (within the contact slop).
    expect(Number(rest!.split('= ')[1]!.split(' ')[0])).toBeCloseTo(9.5, 1);
    const crate = lines.find((line) => line.startsWith('crate slid to x = '));
    expect(Number(crate!.split('= ')[1]!.split(' ')[0])).toBeGreaterThan(3);
    // The ball hit the floor at about sqrt(2 g h) = 13.4 m/s and bounced at least once.
    const bounces = lines.filter((line) => line.startsWith('bounce at '));
    expect(bounces.length).toBeGreaterThanOrEqual(2);
    expect(Number(bounces[0]!.split(' ')[2])).toBeCloseTo(Math.sqrt(2 * 9.81 * 9.5), 0);
  });
});
