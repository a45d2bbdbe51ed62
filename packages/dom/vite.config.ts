import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';

// Serves the showcase with the engine, the canvas and this package from their sources.
export default defineConfig({
  root: fileURLToPath(new URL('./examples', import.meta.url)),
  resolve: {
    alias: {
      '@physical/engine': fileURLToPath(new URL('../engine/src/index.ts', import.meta.url)),
      '@physical/canvas': fileURLToPath(new URL('../canvas/src/index.ts', import.meta.url)),
      '@physical/dom': fileURLToPath(new URL('./src/index.ts', import.meta.url)),
    },
  },
  server: { host: '127.0.0.1' },
});
