// Part of the consumer test: Vite's dev server follows the packages' source maps to the `src`
// they ship, so DevTools shows the TypeScript sources, not `dist`.
//
// Vite 8 pre-bundles dependencies with Rolldown, which does not read its inputs' source maps
// (vitejs/rolldown-vite#510, rolldown/rolldown#5561): a pre-bundled package maps to its `dist`
// files. The packages are plain ESM with no dependencies of their own (React apart, which the app
// imports itself), so the READMEs' Vite snippet excludes them from pre-bundling; Vite then serves
// each `dist` module with its own map, whose sources are the shipped `src` files. This check
// starts the dev server of a project with that config and follows every @physical module the
// page imports to its map and its sources.
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import type * as Vite from 'vite';

interface SourceMap {
  sources: string[];
  sourceRoot?: string;
}

function mapOf(code: string, url: string): Promise<SourceMap> | SourceMap {
  const reference = /\/\/# sourceMappingURL=(\S+)\s*$/.exec(code)?.[1];
  if (reference === undefined) throw new Error(`${url} has no source map`);
  if (reference.startsWith('data:')) {
    const payload = reference.slice(reference.indexOf(',') + 1);
    return JSON.parse(Buffer.from(payload, 'base64').toString('utf8')) as SourceMap;
  }
  return fetch(new URL(reference, url)).then((response) => response.json() as Promise<SourceMap>);
}

/** The @physical modules a served module imports (bare imports rewritten by Vite, or relative). */
function physicalImports(code: string, url: string): string[] {
  const specifiers = [...code.matchAll(/(?:from|import)\s*["']([^"']+)["']/g)].map((m) => m[1]!);
  // Vite rewrites every real bare import to a path; a bare specifier left in the text is in a
  // comment or a string (a doc example such as `import '@physical/canvas/define'`), not an import.
  return specifiers
    .filter((specifier) => /^(?:\.{1,2}\/|\/|https?:)/.test(specifier))
    .map((specifier) => new URL(specifier, url).href)
    .filter((href) => href.includes('/@physical/') || href.includes('/.vite/deps/@physical_'));
}

/**
 * Starts Vite's dev server over the page folder `root` of `project` (with the page's
 * vite.config.ts) and follows each @physical module the page `entry` imports, and the modules
 * those import, to their maps: every source must be a `src/*.ts` file the server serves. Returns
 * one line per module followed.
 */
export async function checkDevSourceMaps(
  project: string,
  root: string,
  entry: string,
): Promise<string[]> {
  const viteEntry = resolve(project, 'node_modules/vite/dist/node/index.js');
  // The project's own Vite (the one its users run), not the workspace's.
  const vite = (await import(pathToFileURL(viteEntry).href)) as typeof Vite;
  const server = await vite.createServer({
    root: resolve(project, root),
    configFile: resolve(project, root, 'vite.config.ts'),
    logLevel: 'error',
    server: { port: 0, strictPort: false },
  });
  await server.listen();
  const address = server.httpServer?.address();
  if (address === null || address === undefined || typeof address === 'string') {
    throw new Error('the dev server has no port');
  }
  const base = `http://localhost:${address.port}`;
  const lines: string[] = [];
  try {
    const pageUrl = `${base}/${entry}`;
    const first = physicalImports(await (await fetch(pageUrl)).text(), pageUrl);
    if (first.length === 0) throw new Error(`${entry} imports no @physical module`);
    const followed = new Set<string>();
    // The page's imports, then theirs (the engine's index, for example, leads to world.js).
    let level = first;
    for (let depth = 0; depth < 2; depth++) {
      const next: string[] = [];
      for (const url of level) {
        const path = new URL(url).pathname;
        if (followed.has(path)) continue;
        followed.add(path);
        if (path.includes('/.vite/deps/')) {
          throw new Error(`${path} is pre-bundled: its map leads to dist, not src`);
        }
        const code = await (await fetch(url)).text();
        // A module of types only compiles to `export {};`: no code to map, and tsc writes no map.
        const statements = code
          .replace(/\/\*[\s\S]*?\*\//g, '')
          .replace(/\/\/.*$/gm, '')
          .trim();
        if (/^(?:export\s*\{\s*\};?)?$/.test(statements)) continue;
        const map = await mapOf(code, url);
        if (map.sources.length === 0) throw new Error(`${path}'s map has no sources`);
        for (const source of map.sources) {
          const sourceUrl = new URL(source, new URL(map.sourceRoot ?? '', url)).href;
          const sourcePath = new URL(sourceUrl).pathname;
          if (!/\/@physical\/[a-z]+\/src\/.+\.ts$/.test(sourcePath)) {
            throw new Error(`${path} maps to ${sourcePath}, not a shipped src/*.ts file`);
          }
          const response = await fetch(sourceUrl);
          if (!response.ok)
            throw new Error(`${sourcePath} (a source of ${path}): ${response.status}`);
          lines.push(`${path} -> ${sourcePath}`);
        }
        next.push(...physicalImports(code, url));
      }
      level = next;
    }
  } finally {
    await server.close();
  }
  return lines;
}
