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
