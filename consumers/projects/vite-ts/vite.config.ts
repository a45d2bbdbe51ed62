import { defineConfig } from 'vite';

// The packages' Vite snippet (see the packages' READMEs): Physical's packages are plain ESM with
// no dependencies, so they need no pre-bundling; left out of it, each module is served with its
// own source map and DevTools shows the TypeScript in the packages' `src`.
export default defineConfig({
  optimizeDeps: {
    exclude: [
      '@physical/engine',
      '@physical/canvas',
      '@physical/dom',
      '@physical/worker',
      '@physical/react',
    ],
  },
});
