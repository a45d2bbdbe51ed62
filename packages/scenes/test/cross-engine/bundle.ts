import { readFile } from 'node:fs/promises';
import { fileURLToPath } from 'node:url';
import { build, type Plugin } from 'esbuild';

const here = (path: string) => fileURLToPath(new URL(path, import.meta.url));

/** The global name the bundle's exports live under (`crossEngine.run(...)`). */
export const GLOBAL_NAME = 'crossEngine';

// Math functions whose last bit each engine's library decides, as a sample might call them.
const APP_MATH = /\bMath\.(sin|cos|tan|atan2|hypot)\b/g;

/** Sends the samples' own Math calls (files of packages/scenes/src) to portable-math.ts. */
const portableSampleMath: Plugin = {
  name: 'portable-sample-math',
  setup(context) {
    const scenesSource = here('../../src/');
    const portable = here('./portable-math.ts');
    context.onLoad({ filter: /\.ts$/ }, async (args) => {
      if (!args.path.startsWith(scenesSource)) return undefined;
      const source = await readFile(args.path, 'utf8');
      if (!APP_MATH.test(source)) return undefined;
      const rewritten = source.replace(APP_MATH, 'portableMath.$1');
      return {
        contents: `import { portableMath } from ${JSON.stringify(portable)};\n${rewritten}`,
        loader: 'ts',
      };
    });
  },
};

/**
 * Bundles entry.ts (the engine from source and every sample) into one classic script that
 * defines `crossEngine` and needs nothing from its host: not WebAssembly, not a console.
 */
export async function bundleCrossEngineProgram(): Promise<string> {
  const result = await build({
    entryPoints: [here('./entry.ts')],
    bundle: true,
    write: false,
    format: 'iife',
    globalName: GLOBAL_NAME,
    platform: 'neutral',
    target: 'es2020',
    alias: {
      '@physical/engine/javascript-kernel': here('../../../engine/src/javascript-kernel.ts'),
      '@physical/engine': here('../../../engine/src/index.ts'),
      '@physical/scenes': here('../../src/index.ts'),
    },
    plugins: [portableSampleMath],
    logLevel: 'silent',
  });
  return result.outputFiles[0]!.text;
}
