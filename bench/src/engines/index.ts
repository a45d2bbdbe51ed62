import type { Engine } from '../types.ts';

/** Engines run only when named with --engines (variants of one engine). */
export const NOT_BY_DEFAULT: ReadonlySet<string> = new Set(['physical-javascript']);

/** Every engine the bench knows, in table order; each loads lazily (only in its own worker). */
export const ENGINES: Record<string, () => Promise<Engine>> = {
  physical: async () => (await import('./physical.ts')).physical,
  'physical-javascript': async () => (await import('./physical.ts')).physicalJavaScript,
  'box2d3-wasm': async () => (await import('./box2d3.ts')).loadBox2d3(),
  'box2d-wasm': async () => (await import('./box2d-wasm.ts')).loadBox2dWasm(),
  '@box2d/core': async () => (await import('./box2d-core.ts')).box2dCore,
  planck: async () => (await import('./planck.ts')).planckEngine,
  'rapier2d-simd': async () => (await import('./rapier.ts')).loadRapier(true),
  rapier2d: async () => (await import('./rapier.ts')).loadRapier(false),
  'p2-es': async () => (await import('./p2.ts')).p2Engine,
  'matter-js': async () => (await import('./matter.ts')).matterEngine,
};
