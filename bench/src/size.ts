import { build, type Plugin } from 'esbuild';
import { readFile } from 'node:fs/promises';
import { relative } from 'node:path';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';

export interface SizeReport {
  minifiedBytes: number;
  gzippedBytes: number;
}

/** Both figures: the whole library, and an app that imports neither joints nor snapshots. */
export interface SizeReports {
  /** packages/engine/src/index.ts as a library, every export kept. */
  library: SizeReport;
  /** {@link APP_ENTRY}: what an app without joints or snapshots ships. */
  appWithoutJointsOrSnapshots: SizeReport;
}

/**
 * An app using bodies, walls and forces but no joints or snapshots (the same imports as
 * packages/engine/test/api/tree-shaking.test.ts, which checks that neither is bundled).
 */
export const APP_ENTRY = `
import { Force, World, box, particle, polygon, wall } from './index.ts';
const world = new World({ gravity: { x: 0, y: 9.81 } });
world.add(wall({ from: { x: -10, y: 0 }, to: { x: 10, y: 0 } }));
const crate = world.add(box({ position: { x: 0, y: -1 }, width: 1, height: 1 }));
world.add(particle({ position: { x: 1, y: -3 }, radius: 0.25 }));
world.add(polygon({ vertices: [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 1 }] }));
crate.applyForce({ x: 5, y: 0 }, { duration: 0.5 });
world.step();
console.log(crate.position, Force);
`;

const source = fileURLToPath(new URL('../../packages/engine/src/', import.meta.url));

/** Bundles an entry whose relative imports resolve in packages/engine/src: minified ESM. */
async function bundleSize(contents: string): Promise<SizeReport> {
  const result = await build({
    stdin: { contents, resolveDir: source, sourcefile: 'entry.ts', loader: 'ts' },
    bundle: true,
    minify: true,
    treeShaking: true,
    format: 'esm',
    platform: 'neutral',
    target: 'es2022',
    write: false,
    logLevel: 'silent',
  });
  const code = result.outputFiles[0]!.contents;
  return { minifiedBytes: code.byteLength, gzippedBytes: gzipSync(code, { level: 9 }).byteLength };
}

/** The library (every export kept) and an app without joints or snapshots, minified ESM. */
export async function measureSize(): Promise<SizeReports> {
  return {
    library: await bundleSize(`export * from './index.ts';`),
    appWithoutJointsOrSnapshots: await bundleSize(APP_ENTRY),
  };
}

/** One source file's share of an app's bundle (minified bytes, before gzip; esbuild's metafile). */
export interface ModuleCost {
  /** The file, as a path under packages/. */
  path: string;
  /** Its minified bytes in the bundle. */
  bytes: number;
}

/**
 * An app's bundle as its page loads it up front (the entry chunk and its static imports): its
 * sizes and the source files in it (paths under packages/). Code behind `import()` is apart.
 */
export interface AppSizeReport extends SizeReport {
  modules: string[];
  /** Every bundled file's minified bytes, largest first: what a module costs. */
  costs: ModuleCost[];
  /** The chunks behind `import()`, loaded when the code that imports them runs (gzip -9 each). */
  lazyGzippedBytes: number;
  /** The source files only in those chunks. */
  lazyModules: string[];
  /** Their minified bytes in those chunks, largest first. */
  lazyCosts: ModuleCost[];
}

/** What the front-end packages add, each against its budget (gzipped bytes, gzip -9). */
export interface FrontEndSizes {
  /** `World` and `box` alone: the engine's own figure, the base of the others. */
  engine: AppSizeReport;
  /** The same app with `<physical-canvas>` drawing it (`@physical/canvas/define`). */
  engineWithCanvas: AppSizeReport;
  /** The page side of a worker world: `WorkerWorld` and the canvas (the worker's file apart). */
  workerPage: AppSizeReport;
}

/** An app that uses `World` and `box` only ships at most this of engine (issue #30, target 5). */
export const ENGINE_TARGET_BYTES = 40 * 1024;
/** `<physical-canvas>` adds at most this to an app beyond the engine (gzipped, issue #33). */
export const CANVAS_BUDGET_BYTES = 10 * 1024;
/** The page side of a worker world, canvas included, ships no solver and stays within this. */
export const WORKER_PAGE_BUDGET_BYTES = 30 * 1024;

const packages = fileURLToPath(new URL('../../packages/', import.meta.url));

/**
 * The contact kernel's two generated builds, which {@link measureKernelShares} leaves out. The
 * JavaScript one is bundled only by the entry `@physical/engine/javascript-kernel`, so an app's
 * engine figure holds the WebAssembly bytes alone.
 */
export const KERNEL_BUILDS = {
  javascript: 'engine/src/dynamics/contact-kernel-javascript.ts',
  webAssembly: 'engine/src/dynamics/contact-kernel-binary.ts',
} as const;

/**
 * Bundles an app entry that imports the packages by name, resolved to their sources. `stubbed`
 * files are replaced by an empty module exporting the same names (as `undefined`): the app's size
 * without them, to see what a file costs after gzip.
 */
export async function appSize(
  contents: string,
  stubbed: readonly string[] = [],
): Promise<AppSizeReport> {
  const result = await build({
    // The entry is a virtual module, so that esbuild can split it (stdin cannot be split).
    entryPoints: ['app-entry'],
    alias: {
      '@physical/engine/javascript-kernel': `${packages}engine/src/javascript-kernel.ts`,
      '@physical/engine': `${packages}engine/src/index.ts`,
      '@physical/canvas/define': `${packages}canvas/src/define.ts`,
      '@physical/canvas': `${packages}canvas/src/index.ts`,
      '@physical/worker': `${packages}worker/src/index.ts`,
    },
    bundle: true,
    minify: true,
    treeShaking: true,
    format: 'esm',
    platform: 'browser',
    target: 'es2022',
    // As an app's bundler does: each `import()` becomes a chunk loaded when it runs.
    splitting: true,
    outdir: 'out',
    write: false,
    logLevel: 'silent',
    metafile: true,
    // An app's production build: development checks off, as the app's bundler would set.
    define: { 'process.env.NODE_ENV': '"production"' },
    plugins: [entryPlugin(contents), ...(stubbed.length === 0 ? [] : [stubPlugin(stubbed)])],
  });
  const outputs = result.metafile.outputs;
  const entry = Object.keys(outputs).find((path) => outputs[path]!.entryPoint !== undefined)!;
  // What the page loads up front: the entry and the chunks it imports statically.
  const firstLoad = new Set<string>();
  const visit = (path: string): void => {
    if (firstLoad.has(path)) return;
    firstLoad.add(path);
    for (const imported of outputs[path]!.imports) {
      if (imported.kind === 'import-statement' && !imported.external) visit(imported.path);
    }
  };
  visit(entry);
  const files = new Map(
    result.outputFiles.map((file) => [relative(process.cwd(), file.path), file]),
  );
  const bytesOf = (paths: string[], zip: boolean): number =>
    paths.reduce((sum, path) => {
      const code = files.get(path)!.contents;
      return sum + (zip ? gzipSync(code, { level: 9 }).byteLength : code.byteLength);
    }, 0);
  const chunks = Object.keys(outputs).filter((path) => path.endsWith('.js'));
  const first = chunks.filter((path) => firstLoad.has(path));
  const lazy = chunks.filter((path) => !firstLoad.has(path));
  const costOf = (paths: string[]): ModuleCost[] => {
    const bytes = new Map<string, number>();
    for (const path of paths) {
      for (const [input, { bytesInOutput }] of Object.entries(outputs[path]!.inputs)) {
        if (bytesInOutput === 0) continue;
        const name = input.replace(/^.*?packages\//, '');
        bytes.set(name, (bytes.get(name) ?? 0) + bytesInOutput);
      }
    }
    return [...bytes]
      .map(([path, size]) => ({ path, bytes: size }))
      .sort((x, y) => y.bytes - x.bytes);
  };
  const costs = costOf(first);
  const lazyCosts = costOf(lazy);
  return {
    minifiedBytes: bytesOf(first, false),
    gzippedBytes: bytesOf(first, true),
    lazyGzippedBytes: bytesOf(lazy, true),
    modules: costs.map((cost) => cost.path),
    costs,
    lazyModules: lazyCosts.map((cost) => cost.path),
    lazyCosts,
  };
}

/** The app's entry, `contents`, as a module resolved in packages/. */
function entryPlugin(contents: string): Plugin {
  return {
    name: 'app-entry',
    setup(plugin) {
      plugin.onResolve({ filter: /^app-entry$/ }, () => ({ path: 'app-entry', namespace: 'app' }));
      plugin.onLoad({ filter: /.*/, namespace: 'app' }, () => ({
        contents,
        loader: 'ts',
        resolveDir: packages,
      }));
    },
  };
}

/** Replaces each of `paths` (under packages/) by a module exporting its names as `undefined`. */
function stubPlugin(paths: readonly string[]): Plugin {
  return {
    name: 'stub',
    setup(plugin) {
      plugin.onLoad({ filter: /\.ts$/ }, async (args) => {
        const path = args.path.replace(/\\/g, '/');
        if (!paths.some((stub) => path.endsWith(`packages/${stub}`))) return undefined;
        const text = await readFile(args.path, 'utf8');
        const names = [...text.matchAll(/^export (?:const|function|class|let) (\w+)/gm)];
        return {
          contents: names.map(([, name]) => `export const ${name} = undefined;`).join('\n'),
          loader: 'ts',
        };
      });
    },
  };
}

const WORLD_AND_BOX = `import { World, box } from '@physical/engine';
  const world = new World(); world.add(box({ width: 1, height: 1 })); world.step(); console.log(world);`;

/** The engine's figure, the engine with the canvas, and a worker world's page. */
export async function measureFrontEnd(): Promise<FrontEndSizes> {
  const world = `const world = new World(); world.add(box({ width: 1, height: 1 }));`;
  return {
    engine: await appSize(WORLD_AND_BOX),
    engineWithCanvas: await appSize(
      `import { World, box } from '@physical/engine'; import '@physical/canvas/define'; ${world}
       document.querySelector('physical-canvas')!.world = world;`,
    ),
    workerPage: await appSize(
      `import { WorkerWorld } from '@physical/worker'; import '@physical/canvas/define';
       const world = new WorkerWorld(new Worker(new URL('./physics.worker.js', import.meta.url), { type: 'module' }));
       world.add({ kind: 'box', width: 1, height: 1 });
       document.querySelector('physical-canvas')!.world = world;`,
    ),
  };
}

/** The `World` and `box` app's gzipped bytes without the kernel's builds (what each costs). */
export interface KernelShares {
  withoutJavaScript: number;
  withoutWebAssembly: number;
  withoutBoth: number;
}

/** What the contact kernel's JavaScript build and its WebAssembly bytes cost the engine's figure. */
export async function measureKernelShares(): Promise<KernelShares> {
  return {
    withoutJavaScript: (await appSize(WORLD_AND_BOX, [KERNEL_BUILDS.javascript])).gzippedBytes,
    withoutWebAssembly: (await appSize(WORLD_AND_BOX, [KERNEL_BUILDS.webAssembly])).gzippedBytes,
    withoutBoth: (await appSize(WORLD_AND_BOX, Object.values(KERNEL_BUILDS))).gzippedBytes,
  };
}

const kb = (bytes: number): string => `${(bytes / 1024).toFixed(1)} KB`;

/** The report lines `npx tsx bench/src/size.ts` prints. */
export function frontEndLines(sizes: FrontEndSizes): string[] {
  const added = sizes.engineWithCanvas.gzippedBytes - sizes.engine.gzippedBytes;
  const verdict = (bytes: number, budget: number, what = 'budget'): string =>
    `${what} ${kb(budget)}: ${bytes <= budget ? 'met' : 'NOT met'}`;
  return [
    'Front-end sizes (esbuild, minified, production define; gzip -9):',
    `- engine, World and box alone: ${kb(sizes.engine.gzippedBytes)} gzipped; ${verdict(sizes.engine.gzippedBytes, ENGINE_TARGET_BYTES, 'target')}`,
    `- <physical-canvas> adds: ${kb(added)} (${kb(sizes.engineWithCanvas.gzippedBytes)} with the engine); ${verdict(added, CANVAS_BUDGET_BYTES)}`,
    `- a worker world's page (WorkerWorld + canvas): ${kb(sizes.workerPage.gzippedBytes)}; ${verdict(sizes.workerPage.gzippedBytes, WORKER_PAGE_BUDGET_BYTES)}`,
  ];
}

/**
 * The `--modules` lines: each bundle's files by minified bytes (the largest `top`; for the canvas,
 * what each file adds to the engine app's), and what the kernel's builds cost gzipped.
 */
export function moduleLines(sizes: FrontEndSizes, shares: KernelShares, top = 25): string[] {
  const list = (report: AppSizeReport, base: AppSizeReport | null): string[] => {
    const before = new Map(base?.costs.map((cost) => [cost.path, cost.bytes]));
    return report.costs
      .map((cost) => ({ path: cost.path, bytes: cost.bytes - (before.get(cost.path) ?? 0) }))
      .filter((cost) => cost.bytes > 0)
      .sort((a, b) => b.bytes - a.bytes)
      .slice(0, top)
      .map((cost) => `  ${String(cost.bytes).padStart(7)}  ${cost.path}`);
  };
  const full = sizes.engine.gzippedBytes;
  return [
    `Files by minified bytes (esbuild metafile; the largest ${top}):`,
    '- engine, World and box alone:',
    ...list(sizes.engine, null),
    "- what <physical-canvas> adds to it (bytes beyond the engine app's, file by file):",
    ...list(sizes.engineWithCanvas, sizes.engine),
    `- loaded apart, when first used (not in the figures; ${kb(sizes.engineWithCanvas.lazyGzippedBytes)} gzipped in all):`,
    ...sizes.engineWithCanvas.lazyCosts.map(
      (cost) => `  ${String(cost.bytes).padStart(7)}  ${cost.path}`,
    ),
    "- a worker world's page:",
    ...list(sizes.workerPage, null),
    'The contact kernel in the engine figure (gzipped; each build replaced by an empty module):',
    `- without its JavaScript build (${KERNEL_BUILDS.javascript}): ${kb(shares.withoutJavaScript)} (it costs ${kb(full - shares.withoutJavaScript)}: only @physical/engine/javascript-kernel bundles it)`,
    `- without its WebAssembly bytes (${KERNEL_BUILDS.webAssembly}): ${kb(shares.withoutWebAssembly)} (they cost ${kb(full - shares.withoutWebAssembly)})`,
    `- without both: ${kb(shares.withoutBoth)}`,
  ];
}

// `npx tsx bench/src/size.ts` prints the front-end figures; `--modules` adds what each file costs.
if (process.argv[1] !== undefined && fileURLToPath(import.meta.url) === process.argv[1]) {
  const sizes = await measureFrontEnd();
  const lines = frontEndLines(sizes);
  if (process.argv.includes('--modules'))
    lines.push(...moduleLines(sizes, await measureKernelShares()));
  // eslint-disable-next-line no-console -- a command-line report
  for (const line of lines) console.log(line);
}
