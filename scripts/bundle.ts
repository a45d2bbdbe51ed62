// The single-file ESM build of a package, for a `<script type="module">` from a CDN:
// dist/physical-<name>.bundle.js, minified, with a source map whose sources are inlined (the
// map works from any CDN path). Each bundle holds its package and the @physical packages it
// builds on, and re-exports their APIs too, so a page imports everything from one file and never
// loads two copies of the engine:
//   engine: the engine; canvas: engine + canvas, and registers <physical-canvas>;
//   dom: engine + Physical UI; worker: engine + canvas (registered) + worker, for the page and
//   the worker alike; react: engine + canvas + the React binding, with `react` left as an import
//   (the page maps it, for example with an import map).
// Each holds the engine whole, the JavaScript build of its contact passes included
// (@physical/engine/javascript-kernel, registered): a page without a build step works under any
// Content-Security-Policy, as before that build became an entry of its own.
// Run by each package's `npm run build`: `tsx ../../scripts/bundle.ts <name>`.
import { build } from 'esbuild';
import { fileURLToPath } from 'node:url';

const kernel = `import '@physical/engine/javascript-kernel';\n`;
const entries: Record<string, string> = {
  engine: `export * from '@physical/engine';`,
  canvas: `export * from '@physical/engine';\nexport * from '@physical/canvas';\nimport '@physical/canvas/define';`,
  dom: `export * from '@physical/engine';\nexport * from '@physical/dom';`,
  worker: `export * from '@physical/engine';\nexport * from '@physical/canvas';\nexport * from '@physical/worker';\nimport '@physical/canvas/define';`,
  react: `export * from '@physical/engine';\nexport * from '@physical/canvas';\nexport * from '@physical/react';`,
};

const name = process.argv[2] ?? '';
const contents = entries[name] === undefined ? undefined : kernel + entries[name];
if (contents === undefined) {
  throw new Error(`bundle: expected one of ${Object.keys(entries).join(', ')}, got "${name}"`);
}
const packages = fileURLToPath(new URL('../packages/', import.meta.url));
const source = (path: string): string => `${packages}${path}`;

await build({
  stdin: { contents, resolveDir: source(name), sourcefile: `physical-${name}.bundle.ts` },
  // From the sources: the bundle needs no other package's dist, so each package builds once.
  alias: {
    '@physical/engine/javascript-kernel': source('engine/src/javascript-kernel.ts'),
    '@physical/engine': source('engine/src/index.ts'),
    '@physical/canvas/define': source('canvas/src/define.ts'),
    '@physical/canvas': source('canvas/src/index.ts'),
    '@physical/dom': source('dom/src/index.ts'),
    '@physical/worker': source('worker/src/index.ts'),
    '@physical/react': source('react/src/index.ts'),
  },
  external: ['react', 'react/*', 'react-dom', 'react-dom/*'],
  outfile: source(`${name}/dist/physical-${name}.bundle.js`),
  bundle: true,
  minify: true,
  format: 'esm',
  platform: 'browser',
  target: 'es2022',
  sourcemap: 'linked',
  sourcesContent: true,
  legalComments: 'none',
  logLevel: 'warning',
  // The bundle runs as-is in a browser: the development checks (`process.env.NODE_ENV`) are off.
  define: { 'process.env.NODE_ENV': '"production"' },
});
