import { build } from 'esbuild';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';

export interface SizeReport {
  minifiedBytes: number;
  gzippedBytes: number;
}

/** Bundles packages/engine/src/index.ts as a library (every export kept), minified ESM. */
export async function measureSize(): Promise<SizeReport> {
  const entry = fileURLToPath(new URL('../../packages/engine/src/index.ts', import.meta.url));
  const result = await build({
    entryPoints: [entry],
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
