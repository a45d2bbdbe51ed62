import { createHash } from 'node:crypto';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import react from '@vitejs/plugin-react';
import { defineConfig, type Plugin } from 'vite';

const source = (path: string): string => fileURLToPath(new URL(path, import.meta.url));

/**
 * Writes `precache-manifest.js` next to the built files: the list of every file the app needs
 * offline and a version that changes with their contents. `public/sw.js` imports it.
 */
function precacheManifest(): Plugin {
  return {
    name: 'newton-precache-manifest',
    apply: 'build',
    generateBundle(_options, bundle) {
      const hash = createHash('sha256');
      const files = ['./', './index.html'];
      for (const [name, item] of Object.entries(bundle).sort(([a], [b]) => a.localeCompare(b))) {
        if (name.endsWith('.map')) continue;
        files.push(`./${name}`);
        hash.update(name);
        hash.update(item.type === 'chunk' ? item.code : item.source);
      }
      for (const name of [
        'manifest.webmanifest',
        'teacher.html',
        'teacher.de.html',
        'teacher.css',
        'teacher-print.js',
        'icons/icon.svg',
        'icons/icon-192.png',
        'icons/icon-512.png',
        'icons/maskable-512.png',
        'icons/apple-touch-icon.png',
      ]) {
        files.push(`./${name}`);
        // Copied from public/ as they are: their contents count too, so a changed teacher page
        // makes a new version (and the service worker fetches it again).
        hash.update(name);
        hash.update(readFileSync(source(`public/${name}`)));
      }
      const version = hash.digest('hex').slice(0, 12);
      this.emitFile({
        type: 'asset',
        fileName: 'precache-manifest.js',
        source: `self.__PRECACHE = ${JSON.stringify({ version, files: [...new Set(files)] })};\n`,
      });
    },
  };
}

export default defineConfig({
  base: './',
  root: source('.'),
  plugins: [react(), precacheManifest()],
  resolve: {
    alias: {
      '@physical/engine': source('../../packages/engine/src/index.ts'),
      '@physical/canvas': source('../../packages/canvas/src/index.ts'),
      '@physical/react': source('../../packages/react/src/index.ts'),
      '@physical/dom': source('../../packages/dom/src/index.ts'),
    },
  },
  build: {
    outDir: source('dist'),
    emptyOutDir: true,
    target: 'es2022',
    // The shell and the first screen load first; each screen is its own chunk, loaded on demand.
    chunkSizeWarningLimit: 800,
  },
  preview: { host: '127.0.0.1', port: 4173 },
});
