import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';

// Packing the five libraries builds each once: a prepack builds its own package only, and the
// TypeScript build (tsc -b) rebuilds a library it builds on only when that one is out of date
// (project references). Each package also builds its single-file CDN bundle and has keywords,
// and the root `npm run build` builds every library.
const LIBRARIES = ['engine', 'canvas', 'dom', 'react', 'worker'] as const;

interface Manifest {
  keywords?: string[];
  files?: string[];
  scripts: Record<string, string>;
  dependencies?: Record<string, string>;
  peerDependencies?: Record<string, string>;
}

const json = <T>(path: string): T =>
  JSON.parse(readFileSync(new URL(`../../../../${path}`, import.meta.url), 'utf8')) as T;

describe.each(LIBRARIES)('@physical/%s', (name) => {
  const manifest = json<Manifest>(`packages/${name}/package.json`);

  it('prepack builds this package only, and the build makes the CDN bundle', () => {
    expect(manifest.scripts['prepack']).toBe('npm run build');
    expect(manifest.scripts['build']).toBe(
      `tsc -b tsconfig.build.json && tsx ../../scripts/bundle.ts ${name}`,
    );
    expect(manifest.files).toContain('dist');
  });

  it('its TypeScript build references exactly the libraries it depends on', () => {
    const config = json<{ references?: { path: string }[] }>(
      `packages/${name}/tsconfig.build.json`,
    );
    const references = (config.references ?? []).map(({ path }) =>
      path.replace('../', '').replace('/tsconfig.build.json', ''),
    );
    const dependsOn = Object.keys({ ...manifest.dependencies, ...manifest.peerDependencies })
      .filter((dependency) => dependency.startsWith('@physical/'))
      .map((dependency) => dependency.replace('@physical/', ''));
    expect(references.sort()).toEqual(dependsOn.sort());
  });

  it('has keywords', () => {
    expect(manifest.keywords?.length ?? 0).toBeGreaterThanOrEqual(3);
  });

  it('is built by the root `npm run build`', () => {
    const root = json<Manifest>('package.json');
    expect(root.scripts['build']).toContain(`npm run build -w @physical/${name}`);
  });
});
