/* eslint-disable no-console -- a command-line script: its output is the report */
// Consumer test: the libraries as users receive them. Packs every library, installs the
// tarballs (and only registry packages besides) into projects in a temp dir outside the
// workspace: React 19 + Vue 3 + Svelte 5 + plain Vite in one, React 18 with @types/react@18 in
// another (each install must resolve its peers without --legacy-peer-deps). Type-checks them
// under strict tsc, Vue's templates with vue-tsc and Svelte's with svelte-check (and a bad
// template must fail each checker), builds them with Vite, runs the Node scripts, drives the
// pages in Chromium (a body falls, a collision event arrives, a drag moves it), and runs
// publint and attw on every tarball. Any failure exits non-zero.
// Run: `npx tsx consumers/run.ts` (after `npm ci`; CI runs it from .ci/run).
import { execFileSync } from 'node:child_process';
import {
  cpSync,
  mkdirSync,
  mkdtempSync,
  readFileSync,
  rmSync,
  statSync,
  writeFileSync,
} from 'node:fs';
import { createServer, type Server } from 'node:http';
import { tmpdir } from 'node:os';
import { extname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium, type Page } from 'playwright-core';
import { publint } from 'publint';
import { formatMessage } from 'publint/utils';
import { checkDevSourceMaps } from './source-maps.ts';

const root = resolve(fileURLToPath(new URL('..', import.meta.url)));
const libraries = ['engine', 'canvas', 'dom', 'react', 'worker'] as const;
const work = mkdtempSync(join(tmpdir(), 'physical-consumers-'));
const failures: string[] = [];
const started = Date.now();

function run(command: string, args: readonly string[], cwd: string): string {
  const shown = `${command} ${args.join(' ')}`;
  console.log(`$ ${shown}   (in ${cwd})`);
  try {
    return execFileSync(command, args, {
      cwd,
      encoding: 'utf8',
      stdio: ['ignore', 'pipe', 'pipe'],
    });
  } catch (error) {
    const { stdout = '', stderr = '' } = error as { stdout?: string; stderr?: string };
    throw new Error(`${shown} failed:\n${stdout}${stderr}`, { cause: error });
  }
}

/** Runs a command that must fail; returns its output. */
function failing(command: () => unknown, name: string): string {
  try {
    command();
  } catch (error) {
    return error instanceof Error ? error.message : String(error);
  }
  throw new Error(`${name} passed a template it must reject`);
}

async function check(name: string, body: () => unknown): Promise<void> {
  try {
    await body();
    console.log(`ok   ${name}`);
  } catch (error) {
    failures.push(name);
    console.log(`FAIL ${name}\n${error instanceof Error ? error.message : String(error)}`);
  }
}

function kib(bytes: number): string {
  return `${(bytes / 1024).toFixed(1)} kB`;
}

// 1. Pack: build each library once (its `prepack` does the same: `tsc -b`, which skips the
// libraries it builds on when they are up to date, and the CDN bundle), then pack.
for (const name of libraries) run('npm', ['run', 'build', '-w', `@physical/${name}`], root);
const tarballs: Record<string, string> = {};
for (const name of libraries) {
  const [info] = JSON.parse(
    run(
      'npm',
      ['pack', '--json', '--ignore-scripts', '--pack-destination', work],
      join(root, 'packages', name),
    ),
  ) as { filename: string; size: number; unpackedSize: number; entryCount: number }[];
  tarballs[name] = join(work, info!.filename);
  console.log(
    `packed @physical/${name}: ${info!.filename}, ${kib(info!.size)} packed, ${kib(info!.unpackedSize)} unpacked, ${info!.entryCount} files`,
  );
}

// 2. Lint the tarballs: publint (errors and warnings fail) and attw (ESM only by design, so the
// esm-only profile: node10 and CommonJS `import()`-only resolutions are not problems).
for (const name of libraries) {
  await check(`publint @physical/${name}`, async () => {
    const buffer = readFileSync(tarballs[name]!);
    const tarball = buffer.buffer.slice(buffer.byteOffset, buffer.byteOffset + buffer.byteLength);
    const { messages, pkg } = await publint({
      pack: { tarball },
      level: 'suggestion',
      strict: true,
    });
    for (const message of messages) {
      console.log(`  publint ${message.type}: ${formatMessage(message, pkg) ?? message.code}`);
    }
    const bad = messages.filter((message) => message.type !== 'suggestion');
    if (bad.length > 0) throw new Error(`${bad.length} publint errors or warnings`);
  });
  await check(`attw @physical/${name}`, () => {
    const attw = join(root, 'node_modules/@arethetypeswrong/cli/dist/index.js');
    const output = run(
      process.execPath,
      [
        attw,
        tarballs[name]!,
        '--profile',
        'esm-only',
        '--format',
        'table',
        '--no-emoji',
        '--no-color',
      ],
      work,
    );
    console.log(output.replace(/^/gm, '  '));
  });
}

// 3. The consumer projects, outside the workspace, with the tarballs and registry packages only.
const app = join(work, 'app');
cpSync(join(root, 'consumers/projects'), app, { recursive: true });
const dependencies: Record<string, string> = {};
for (const name of libraries) dependencies[`@physical/${name}`] = `file:${tarballs[name]}`;
writeFileSync(
  join(app, 'package.json'),
  JSON.stringify(
    {
      name: 'physical-consumer',
      private: true,
      type: 'module',
      dependencies: {
        ...dependencies,
        react: '^19.0.0',
        'react-dom': '^19.0.0',
        svelte: '^5.0.0',
        vue: '^3.5.0',
      },
      devDependencies: {
        '@types/react': '^19.0.0',
        '@types/react-dom': '^19.0.0',
        '@vitejs/plugin-react': '^6.0.0',
        'svelte-check': '^4.0.0',
        typescript: '^6.0.0',
        vite: '^8.0.0',
        'vue-tsc': '^3.0.0',
      },
    },
    null,
    2,
  ),
);
// React 18 with its own types: the peers of canvas and react must accept @types/react@18
// (a plain `npm install`, no --legacy-peer-deps, fails with ERESOLVE otherwise). Only the
// packages a React page needs: @physical/dom is an optional peer of @physical/react.
const react18 = join(work, 'react18');
cpSync(join(root, 'consumers/projects/react18'), join(react18, 'react18'), { recursive: true });
cpSync(join(root, 'consumers/projects/shared'), join(react18, 'shared'), { recursive: true });
cpSync(join(root, 'consumers/projects/tsconfig.json'), join(react18, 'tsconfig.json'));
writeFileSync(
  join(react18, 'package.json'),
  JSON.stringify(
    {
      name: 'physical-consumer-react18',
      private: true,
      type: 'module',
      dependencies: {
        '@physical/engine': dependencies['@physical/engine'],
        '@physical/canvas': dependencies['@physical/canvas'],
        '@physical/react': dependencies['@physical/react'],
        react: '^18.3.0',
        'react-dom': '^18.3.0',
      },
      devDependencies: {
        '@types/react': '^18.3.0',
        '@types/react-dom': '^18.3.0',
        '@vitejs/plugin-react': '^6.0.0',
        typescript: '^6.0.0',
        vite: '^8.0.0',
      },
    },
    null,
    2,
  ),
);
const install = ['install', '--no-audit', '--no-fund', '--prefer-offline', '--loglevel=error'];
run('npm', install, app);
await check('npm install into React 18 with @types/react@18 (peers resolve)', () =>
  run('npm', install, react18),
);

await check('node ESM import', () => console.log(run(process.execPath, ['node/esm.mjs'], app)));
await check('node CommonJS require (require of ESM)', () =>
  console.log(run(process.execPath, ['node/require.cjs'], app)),
);
// The Vite page on its own: a program with the React page would see the tag's typings through
// its import of the main entry, and miss a `/define` that carries none.
await check('strict tsc over the Vite + TypeScript project (only @physical/canvas/define)', () =>
  run(process.execPath, ['node_modules/typescript/bin/tsc', '-p', 'vite-ts/tsconfig.json'], app),
);
await check('strict tsc over the React and Vue projects', () =>
  run(process.execPath, ['node_modules/typescript/bin/tsc', '-p', 'tsconfig.json'], app),
);
await check('strict tsc over the React 18 project (@types/react@18)', () =>
  run(
    process.execPath,
    ['node_modules/typescript/bin/tsc', '-p', 'react18/tsconfig.json'],
    react18,
  ),
);
// The templates, with each framework's own checker, in one run each (a run takes a while): the
// good template (Stage) passes and the bad one (Bad: `fit="sideways"`) is the only error, so the
// checker does see the tag's typings rather than an unknown element.
function onlyTheBadTemplate(checker: string, args: readonly string[], bad: RegExp): void {
  const output = failing(() => run(process.execPath, args, app), checker);
  const errors = output
    .split('\n')
    .filter((line) => /error/i.test(line) && /\.(vue|svelte)\b/.test(line));
  if (
    errors.length === 0 ||
    !errors.every((line) => bad.test(line)) ||
    !output.includes('sideways')
  ) {
    throw new Error(
      `${checker}: expected errors only in the bad template, about "sideways":\n${output}`,
    );
  }
}
await check('vue-tsc over Vue SFC templates (@physical/canvas/vue): good passes, bad fails', () =>
  onlyTheBadTemplate(
    'vue-tsc',
    ['node_modules/vue-tsc/bin/vue-tsc.js', '-p', 'vue/tsconfig.json'],
    /Bad\.vue/,
  ),
);
await check(
  'svelte-check over Svelte 5 templates (@physical/canvas/svelte): good passes, bad fails',
  () =>
    onlyTheBadTemplate(
      'svelte-check',
      [
        'node_modules/svelte-check/bin/svelte-check',
        '--workspace',
        join(app, 'svelte'),
        '--tsconfig',
        join(app, 'svelte/tsconfig.json'),
        '--fail-on-warnings',
        '--output',
        'machine',
      ],
      /Bad\.svelte/,
    ),
);
const pages = ['vite-ts', 'react', 'vue'] as const;
for (const page of pages) {
  await check(`vite build ${page}`, () =>
    run(
      process.execPath,
      ['node_modules/vite/bin/vite.js', 'build', page, '--base', './', '--logLevel', 'warn'],
      app,
    ),
  );
}
// Vite's dev server with the READMEs' config (vite-ts/vite.config.ts): every @physical module the
// page loads, and the modules those import, map to the `src/*.ts` shipped in the tarballs.
await check('vite dev server follows source maps to the shipped src (vite-ts)', async () => {
  const lines = await checkDevSourceMaps(app, 'vite-ts', 'main.ts');
  console.log(
    `     ${lines.length} modules, for example ${lines.find((l) => l.includes('world'))}`,
  );
});
await check('vite build react18', () =>
  run(
    process.execPath,
    ['node_modules/vite/bin/vite.js', 'build', 'react18', '--base', './', '--logLevel', 'warn'],
    react18,
  ),
);

// 4. The pages in Chromium.
const types: Record<string, string> = {
  '.html': 'text/html',
  '.js': 'text/javascript',
  '.css': 'text/css',
  '.json': 'application/json',
  '.map': 'application/json',
};
const server: Server = createServer((request, response) => {
  const pathname = decodeURIComponent(new URL(request.url ?? '/', 'http://x').pathname);
  const path = pathname.startsWith('/react18/') ? join(react18, pathname) : join(app, pathname);
  try {
    const file = statSync(path).isDirectory() ? join(path, 'index.html') : path;
    response.writeHead(200, { 'content-type': types[extname(file)] ?? 'application/octet-stream' });
    response.end(readFileSync(file));
  } catch {
    response.writeHead(404).end();
  }
});
await new Promise<void>((done) => server.listen(0, '127.0.0.1', done));
const address = server.address();
const origin = `http://127.0.0.1:${typeof address === 'object' && address !== null ? address.port : 0}`;
const browser = await chromium.launch({
  executablePath: process.env['CHROMIUM_PATH'] ?? '/usr/bin/chromium',
  args: [
    '--no-sandbox',
    '--disable-gpu',
    '--disable-background-networking',
    '--disable-component-update',
    '--disable-sync',
    '--no-first-run',
  ],
});

async function probe<T>(page: Page, read: string): Promise<T> {
  return (await page.evaluate(`window.probe.${read}`)) as T;
}

async function drivePage(name: string): Promise<void> {
  const page = await browser.newPage({ viewport: { width: 900, height: 400 } });
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  try {
    await page.goto(`${origin}/${name}/dist/index.html`);
    await page.waitForFunction('window.probe !== undefined', undefined, { timeout: 30_000 });
    const startY = await probe<number>(page, 'startY');
    // The box starts at y = 1 m and rests on the wall at y = 5 m (its centre at 4.5 m).
    await page.waitForFunction('window.probe.y() > 4.3', undefined, { timeout: 30_000 });
    await page.waitForFunction('window.probe.collisions() > 0', undefined, { timeout: 30_000 });
    const fallen = await probe<number>(page, 'y()');
    if (!(fallen > startY + 3)) throw new Error(`did not fall: y ${startY} -> ${fallen}`);
    // Drag it 3 m (150 px at 50 px/m) to the right.
    const startX = await probe<number>(page, 'x()');
    const grab = await probe<{ x: number; y: number }>(page, 'screenPoint()');
    await page.mouse.move(grab.x, grab.y);
    await page.mouse.down();
    for (let i = 1; i <= 10; i++) await page.mouse.move(grab.x + 15 * i, grab.y - 2 * i);
    await page.waitForFunction(`window.probe.x() > ${startX + 2}`, undefined, {
      timeout: 15_000,
    });
    // Hold still before letting go: a release within the canvas's 80 ms velocity window would
    // throw the box, possibly off the end of the wall, and the tap below would miss it.
    await page.waitForTimeout(250);
    await page.mouse.up();
    // A tap (press and release without moving) reaches the typed bodytap listener.
    await page.waitForFunction('window.probe.y() > 4.3', undefined, { timeout: 30_000 });
    const tap = await probe<{ x: number; y: number }>(page, 'screenPoint()');
    await page.mouse.click(tap.x, tap.y);
    await page.waitForFunction('window.probe.screenPoint().taps > 0', undefined, {
      timeout: 15_000,
    });
    if (errors.length > 0) throw new Error(`page errors: ${errors.join('; ')}`);
  } finally {
    await page.close();
  }
}

// The READMEs' CDN snippets, as written, with the CDN's address pointed at the installed
// tarballs' files: one ES module file per package, loaded by <script type="module">.
const cdn = /https:\/\/cdn\.jsdelivr\.net\/npm\/@physical\/(\w+)@[\d.]+\//g;
// React's own builds are CommonJS: one ES module of React and react-dom/client stands in for the
// import map's CDN addresses (the binding and the page share one React).
const reactNames = (module: string): string[] =>
  (
    JSON.parse(
      run(
        process.execPath,
        ['-e', `console.log(JSON.stringify(Object.keys(require('${module}'))))`],
        app,
      ),
    ) as string[]
  ).filter((key) => /^[A-Za-z_$][\w$]*$/.test(key) && key !== 'default');
await check('a local ES module build of React for the React snippet', async () => {
  const ownNames = reactNames('react');
  const clientNames = reactNames('react-dom/client').filter((key) => !ownNames.includes(key));
  const { build } = await import('esbuild');
  await build({
    stdin: {
      contents: [
        `import React from 'react'; import * as client from 'react-dom/client';`,
        `export default React;`,
        `export const { ${ownNames.join(', ')} } = React;`,
        `export const { ${clientNames.join(', ')} } = client;`,
      ].join('\n'),
      resolveDir: app,
    },
    bundle: true,
    format: 'esm',
    outfile: join(app, 'cdn/react.js'),
    define: { 'process.env.NODE_ENV': '"production"' },
    logLevel: 'error',
  });
});
async function runSnippet(name: string): Promise<void> {
  const readme = readFileSync(join(root, 'packages', name, 'README.md'), 'utf8');
  const section = readme.split('## From a CDN, without a build')[1] ?? '';
  const snippet = /```html\n([\s\S]*?)```/.exec(section)?.[1];
  if (snippet === undefined) throw new Error(`no CDN snippet in packages/${name}/README.md`);
  const html = snippet
    .replace(cdn, `${origin}/node_modules/@physical/$1/`)
    .replace(/https:\/\/esm\.sh\/react(-dom)?@\d+(\/client)?/g, `${origin}/cdn/react.js`);
  if (/https?:\/\/(?!127\.0\.0\.1)/.test(html))
    throw new Error(`snippet loads from outside:\n${html}`);
  writeFileSync(
    join(app, `cdn/${name}.html`),
    `<!doctype html>\n<meta charset="utf-8" />\n${html}`,
  );
  const page = await browser.newPage({ viewport: { width: 900, height: 400 } });
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  page.on('requestfailed', (request) => errors.push(`failed: ${request.url()}`));
  page.on('response', (response) => {
    if (response.status() >= 400) errors.push(`${response.status()}: ${response.url()}`);
  });
  try {
    await page.goto(`${origin}/cdn/${name}.html`);
    if (name === 'engine') {
      await page.waitForFunction('document.body.textContent.includes("rests at")');
      const text = await page.evaluate('document.body.textContent');
      const y = Number(/y = (-?[\d.]+) m/.exec(String(text))?.[1]);
      // 1 m box on a wall at y = 0: its centre rests half a metre above (within the slop).
      if (!(Math.abs(y + 0.5) < 0.02)) throw new Error(`engine snippet: ${String(text)}`);
    } else if (name === 'dom') {
      // The released buttons fall: their transforms move them down.
      await page.waitForFunction(
        `[...document.querySelectorAll('.chips button')].every((b) => /matrix|translate/.test(b.style.transform))`,
        undefined,
        { timeout: 15_000 },
      );
    } else {
      // The element runs the world: 60 steps (1 s) taken and frames drawn.
      await page.waitForFunction(
        `(() => { const c = document.querySelector('physical-canvas'); return c !== null && c.world !== null && c.stepCount > 60 && c.frameCount > 10; })()`,
        undefined,
        { timeout: 15_000 },
      );
    }
    if (errors.length > 0) throw new Error(errors.join('; '));
  } finally {
    await page.close();
  }
}
mkdirSync(join(app, 'cdn'), { recursive: true });
for (const name of libraries) {
  await check(
    `README CDN snippet of @physical/${name} in Chromium (dist/physical-${name}.bundle.js)`,
    () => runSnippet(name),
  );
}

for (const name of [...pages, 'react18']) {
  await check(`${name} page in Chromium: falls, collides, drags`, async () => {
    // One retry, as the browser tests have: pointer input on a 2-core CI machine can miss a
    // frame. A page that fails twice fails the test; the first failure is printed either way.
    try {
      await drivePage(name);
    } catch (error) {
      console.log(`retry ${name} page after: ${error instanceof Error ? error.message : error}`);
      await drivePage(name);
    }
  });
}
await browser.close();
server.close();

if (failures.length === 0) rmSync(work, { recursive: true, force: true });
else console.log(`Kept ${work} for inspection.`);
console.log(
  `consumer test: ${failures.length === 0 ? 'passed' : `FAILED (${failures.join(', ')})`} in ${((Date.now() - started) / 1000).toFixed(0)} s`,
);
process.exitCode = failures.length === 0 ? 0 : 1;
