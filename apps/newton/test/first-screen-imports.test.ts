import { existsSync, readFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

const SRC = fileURLToPath(new URL('../src/', import.meta.url));

/** The modules a file imports statically (`import ... from`, `import '...'`), not `import()`. */
function staticImports(file: string): string[] {
  const text = readFileSync(file, 'utf8');
  return [
    ...text.matchAll(/^\s*(?:import|export)\s[^'"]*?from\s+'([^']+)'|^\s*import\s+'([^']+)'/gm),
  ]
    .filter(
      (match) => !/^\s*import\s+type\s/.test(match[0]) && !/^\s*export\s+type\s/.test(match[0]),
    )
    .map((match) => (match[1] ?? match[2])!);
}

/**
 * Every package the first screen loads before its first tap: what the entry and the first
 * screen's chunk import statically, followed through the app's own files (a lazy `import()` is
 * a later chunk, and is not followed).
 */
function packagesOf(entries: readonly string[]): Map<string, string> {
  const packages = new Map<string, string>();
  const seen = new Set<string>();
  const visit = (file: string): void => {
    if (seen.has(file)) return;
    seen.add(file);
    for (const name of staticImports(file)) {
      if (name.startsWith('.')) {
        const path = resolve(dirname(file), name);
        if (existsSync(path) && /\.(tsx?)$/.test(path)) visit(path);
      } else if (!packages.has(name)) packages.set(name, file);
    }
  };
  for (const entry of entries) visit(resolve(SRC, entry));
  return packages;
}

describe('the first screen', () => {
  it('loads no MUI and no Emotion: the shell and Inertia are plain elements and a static stylesheet', () => {
    const packages = packagesOf(['main.tsx', 'screens/inertia/InertiaScreen.tsx']);
    expect(packages.has('react')).toBe(true);
    expect(packages.has('@physical/react')).toBe(true);
    const styled = [...packages]
      .filter(([name]) => name.startsWith('@mui/') || name.startsWith('@emotion/'))
      .map(([name, file]) => `${name} (from ${file.slice(SRC.length)})`);
    expect(styled).toEqual([]);
  });

  it('is what the check follows: Forces, which draws with MUI, is found to load it', () => {
    const packages = packagesOf(['screens/forces/ForcesScreen.tsx']);
    expect(packages.has('@mui/material')).toBe(true);
  });
});
