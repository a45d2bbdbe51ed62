import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';

const source = (path: string): string => fileURLToPath(new URL(path, import.meta.url));

export default defineConfig({
  base: './',
  root: source('.'),
  resolve: {
    alias: {
      '@physical/engine': source('../../packages/engine/src/index.ts'),
      '@physical/canvas': source('../../packages/canvas/src/index.ts'),
      '@physical/scenes': source('../../packages/scenes/src/index.ts'),
      '@physical/dom': source('../../packages/dom/src/index.ts'),
      '@physical/worker': source('../../packages/worker/src/index.ts'),
    },
  },
  worker: { format: 'es' },
  build: { outDir: source('dist'), emptyOutDir: true, target: 'es2022' },
  preview: { host: '127.0.0.1', port: 4174 },
});
