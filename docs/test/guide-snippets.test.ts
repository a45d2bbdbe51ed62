import { mkdirSync, rmSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import ts from 'typescript';
import { describe, expect, it, vi } from 'vitest';
import { guideSnippets } from './snippets.ts';

// Every code block in docs/guides is compiled under docs/tsconfig.json (strict, as users'
// projects are) and, unless tagged `browser`, executed: a guide cannot drift from the API.
const generated = new URL('./generated/', import.meta.url);
const snippets = guideSnippets();
rmSync(generated, { recursive: true, force: true });
mkdirSync(generated, { recursive: true });
const files = snippets.map((snippet, index) => {
  const name = `${snippet.guide.replace(/\.md$/, '')}-${String(index).padStart(2, '0')}.${snippet.language}`;
  const path = fileURLToPath(new URL(name, generated));
  // `export {}` makes each block a module, so blocks do not share top-level names.
  writeFileSync(path, `${snippet.code}\n\nexport {};\n`);
  return path;
});

function diagnostics(): Map<string, string[]> {
  const configPath = fileURLToPath(new URL('../tsconfig.json', import.meta.url));
  const config = ts.getParsedCommandLineOfConfigFile(
    configPath,
    {},
    {
      ...ts.sys,
      onUnRecoverableConfigFileDiagnostic: (d) => {
        throw new Error(ts.flattenDiagnosticMessageText(d.messageText, '\n'));
      },
    },
  )!;
  const program = ts.createProgram({ rootNames: files, options: config.options });
  const byFile = new Map<string, string[]>();
  for (const d of ts.getPreEmitDiagnostics(program)) {
    const file = d.file?.fileName ?? '(global)';
    const at =
      d.file && d.start !== undefined ? d.file.getLineAndCharacterOfPosition(d.start) : null;
    const text = `${at ? `line ${at.line + 1}: ` : ''}${ts.flattenDiagnosticMessageText(d.messageText, '\n')}`;
    byFile.set(file, [...(byFile.get(file) ?? []), text]);
  }
  return byFile;
}

describe('guides: every code block type-checks and runs', () => {
  it('finds code blocks in the guides, most of them runnable', () => {
    expect(snippets.length).toBeGreaterThanOrEqual(15);
    expect(snippets.filter((s) => !s.browser).length).toBeGreaterThanOrEqual(10);
  });

  const found = diagnostics();
  snippets.forEach((snippet, index) => {
    const where = `${snippet.guide}:${snippet.line}`;
    const file = files[index]!;
    it(`${where} type-checks${snippet.browser ? ' (browser: not run)' : ''}`, () => {
      expect(found.get(file) ?? [], `tsc errors in the block at ${where}`).toEqual([]);
    });
    if (!snippet.browser) {
      it(`${where} runs without throwing`, async () => {
        const log = vi.spyOn(console, 'log').mockImplementation(() => {});
        try {
          await import(/* @vite-ignore */ file);
          expect(log).toHaveBeenCalled();
        } finally {
          log.mockRestore();
        }
      });
    }
  });

  it('no type errors outside the blocks', () => {
    const outside = [...found.keys()].filter((file) => !files.includes(file));
    expect(outside).toEqual([]);
  });
});
