import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import ts from 'typescript';
import { afterEach, describe, expect, it, vi } from 'vitest';

// The engine README's joints example is type-checked and executed as written, like the root
// README's example (readme-example.test.ts).

const here = dirname(fileURLToPath(import.meta.url));
const readme = readFileSync(join(here, '../../README.md'), 'utf8');

function writeExample(): string {
  const section = readme.split('## Joints')[1];
  const match = section === undefined ? null : /```ts\n([\s\S]*?)```/.exec(section);
  if (match === null)
    throw new Error('packages/engine/README.md has no ```ts block under "## Joints".');
  const folder = join(here, 'generated');
  mkdirSync(folder, { recursive: true });
  const file = join(folder, 'readme-joints.ts');
  writeFileSync(file, match[1]!);
  return file;
}

describe("the engine README's joints example", () => {
  afterEach(() => {
    vi.restoreAllMocks();
  });

  it('type-checks against the public API', () => {
    const program = ts.createProgram([writeExample()], {
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

  it('runs: the rope holds the lamp and the door swings to its limit', async () => {
    const lines: string[] = [];
    vi.spyOn(console, 'log').mockImplementation((line: unknown) => {
      lines.push(String(line));
    });
    await import(/* @vite-ignore */ writeExample());
    const tension = /rope tension = ([\d.]+) N/.exec(lines.join('\n'));
    expect(tension).not.toBeNull();
    // The lamp (a 0.2 m disc of density 1) hangs at rest: the tension is its weight.
    const weight = Math.PI * 0.2 * 0.2 * 9.81;
    expect(Number(tension![1])).toBeCloseTo(weight, 1);
    const angle = /hinge angle = (-?[\d.]+) rad/.exec(lines.join('\n'));
    // Gravity and the motor both turn the door down to its upper limit.
    expect(Number(angle![1])).toBeCloseTo(Math.PI / 2, 1);
  });
});
