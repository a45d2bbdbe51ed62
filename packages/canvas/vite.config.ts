import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';

// Serves example/ with the engine and the element from their sources (no build needed).
export default defineConfig({
  root: fileURLToPath(new URL('./example', import.meta.url)),
  resolve: {
    alias: {
      '@physical/engine': fileURLToPath(new URL('../engine/src/index.ts', import.meta.url)),
      '@physical/canvas': fileURLToPath(new URL('./src/index.ts', import.meta.url)),
    },
  },
  server: { host: '127.0.0.1' },
});
