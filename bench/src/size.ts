import { build } from 'esbuild';
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

/** An app's bundle: its sizes and the source files it bundles (paths under packages/). */
export interface AppSizeReport extends SizeReport {
  modules: string[];
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

/** `<physical-canvas>` adds at most this to an app beyond the engine (gzipped, issue #33). */
export const CANVAS_BUDGET_BYTES = 10 * 1024;
/** The page side of a worker world, canvas included, ships no solver and stays within this. */
export const WORKER_PAGE_BUDGET_BYTES = 30 * 1024;

const packages = fileURLToPath(new URL('../../packages/', import.meta.url));

/** Bundles an app entry that imports the packages by name, resolved to their sources. */
async function appSize(contents: string): Promise<AppSizeReport> {
  const result = await build({
    stdin: { contents, resolveDir: packages, sourcefile: 'app.ts', loader: 'ts' },
    alias: {
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
    write: false,
    logLevel: 'silent',
    metafile: true,
    outfile: 'app.js',
    // An app's production build: development checks off, as the app's bundler would set.
    define: { 'process.env.NODE_ENV': '"production"' },
  });
  const code = result.outputFiles[0]!.contents;
  const output = Object.values(result.metafile.outputs)[0]!;
  const modules = Object.entries(output.inputs)
    .filter(([, input]) => input.bytesInOutput > 0)
    .map(([path]) => path.replace(/^.*?packages\//, ''));
  return {
    minifiedBytes: code.byteLength,
    gzippedBytes: gzipSync(code, { level: 9 }).byteLength,
    modules,
  };
}

/** The engine's figure, the engine with the canvas, and a worker world's page. */
export async function measureFrontEnd(): Promise<FrontEndSizes> {
  const world = `const world = new World(); world.add(box({ width: 1, height: 1 }));`;
  return {
    engine: await appSize(
      `import { World, box } from '@physical/engine'; ${world} world.step(); console.log(world);`,
    ),
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

/** The report lines `npx tsx bench/src/size.ts` prints. */
export function frontEndLines(sizes: FrontEndSizes): string[] {
  const kb = (bytes: number): string => `${(bytes / 1024).toFixed(1)} KB`;
  const added = sizes.engineWithCanvas.gzippedBytes - sizes.engine.gzippedBytes;
  const verdict = (bytes: number, budget: number): string =>
    `budget ${kb(budget)}: ${bytes <= budget ? 'met' : 'NOT met'}`;
  return [
    'Front-end sizes (esbuild, minified, production define; gzip -9):',
    `- engine, World and box alone: ${kb(sizes.engine.gzippedBytes)} gzipped`,
    `- <physical-canvas> adds: ${kb(added)} (${kb(sizes.engineWithCanvas.gzippedBytes)} with the engine); ${verdict(added, CANVAS_BUDGET_BYTES)}`,
    `- a worker world's page (WorkerWorld + canvas): ${kb(sizes.workerPage.gzippedBytes)}; ${verdict(sizes.workerPage.gzippedBytes, WORKER_PAGE_BUDGET_BYTES)}`,
  ];
}

// `npx tsx bench/src/size.ts` prints the front-end figures.
if (process.argv[1] !== undefined && fileURLToPath(import.meta.url) === process.argv[1]) {
  // eslint-disable-next-line no-console -- a command-line report
  for (const line of frontEndLines(await measureFrontEnd())) console.log(line);
}
