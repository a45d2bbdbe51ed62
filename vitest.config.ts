import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vitest/config';

// Tests import packages by their public names; these aliases point them at the sources,
// so the specs exercise exactly the surface users get without a build step.
export default defineConfig({
  resolve: {
    alias: {
      // Before '@physical/engine', which would also match its subpath.
      '@physical/engine/javascript-kernel': fileURLToPath(
        new URL('./packages/engine/src/javascript-kernel.ts', import.meta.url),
      ),
      '@physical/engine': fileURLToPath(new URL('./packages/engine/src/index.ts', import.meta.url)),
      '@physical/canvas': fileURLToPath(new URL('./packages/canvas/src/index.ts', import.meta.url)),
      // Before '@physical/react', which would also match its subpath.
      '@physical/react/ui': fileURLToPath(new URL('./packages/react/src/ui.ts', import.meta.url)),
      '@physical/react': fileURLToPath(new URL('./packages/react/src/index.ts', import.meta.url)),
      '@physical/scenes': fileURLToPath(new URL('./packages/scenes/src/index.ts', import.meta.url)),
      '@physical/dom': fileURLToPath(new URL('./packages/dom/src/index.ts', import.meta.url)),
      '@physical/worker': fileURLToPath(new URL('./packages/worker/src/index.ts', import.meta.url)),
    },
  },
  test: {
    // Long simulations (hundreds of steps in both kernel builds) take seconds; on a loaded CI
    // machine several times that. Speed is measured by the bench, never by a test's time limit.
    testTimeout: 30_000,
    include: ['packages/*/test/**/*.test.ts', 'apps/*/test/**/*.test.ts', 'docs/test/**/*.test.ts'],
  },
});
