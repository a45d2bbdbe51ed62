import { createHash } from 'node:crypto';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import react from '@vitejs/plugin-react';
import { defineConfig, type Plugin } from 'vite';
import type { OutputBundle, OutputChunk } from 'rolldown';
import { tokenCss } from './src/app/theme-tokens.ts';
import { teacherPagesPlugin } from './scripts/teacher-pages.ts';

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
        // makes a new version (and the service worker fetches it again). The teacher pages
        // themselves are made by teacherPagesPlugin, which runs first: they are in the bundle.
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

/**
 * Puts the design tokens (src/app/theme-tokens.ts) into the page as CSS custom properties, first
 * in its head: the shell painted from the HTML and the first screen's stylesheets read them, and
 * the MUI theme of the later parts is made from the same file.
 */
function themeTokens(): Plugin {
  return {
    name: 'newton-theme-tokens',
    transformIndexHtml: () => [
      {
        tag: 'style',
        attrs: { 'data-tokens': '' },
        children: tokenCss(),
        injectTo: 'head-prepend',
      },
    ],
  };
}

/**
 * Fetches the first screen's code while the shell's loads: a small inline script in the page
 * adds `modulepreload` links for the chunks of the screen the address names (#forces...), or of
 * Inertia. Without it the screen's chunk and the engine were requested only once React had
 * evaluated and rendered the shell (a second round of downloads after a second of a slow
 * phone's CPU). The screen ids come from the screens' folders (`src/screens/<id>/`).
 */
function firstScreenPreload(): Plugin {
  return {
    name: 'newton-first-screen-preload',
    apply: 'build',
    transformIndexHtml: {
      order: 'post',
      handler(html, context) {
        const bundle = context.bundle as OutputBundle | undefined;
        if (bundle === undefined) return html;
        const chunks = Object.values(bundle).filter(
          (item): item is OutputChunk => item.type === 'chunk',
        );
        const byName = new Map(chunks.map((chunk) => [chunk.fileName, chunk]));
        // Per screen, two lists: the screen's chunk and what it imports statically (its
        // controls), then its engine part (`src/screens/<id>/<id>-engine.ts`, which the screen
        // imports once its controls are on the page) with its chunks, at low priority. Slow 4G
        // shares its 1.6 Mbit/s among the files in flight: fetched beside the entry, the engine's
        // 80 KB held the entry (React, the shell) back until about when the engine came, and
        // the controls with it; at low priority they wait for one of the six connections
        // (HTTP/1.1) to come free, after the entry's and the controls' requests.
        const files: Record<string, [string[], string[]]> = {};
        for (const chunk of chunks) {
          const match = /\/src\/screens\/(\w+)\/\w+Screen\.tsx$/.exec(chunk.facadeModuleId ?? '');
          if (match === null || !chunk.isDynamicEntry) continue;
          const list: string[] = [];
          const visit = (name: string): void => {
            if (list.includes(name)) return;
            list.push(name);
            for (const next of byName.get(name)?.imports ?? []) visit(next);
          };
          visit(chunk.fileName);
          const first = list.length;
          for (const name of chunk.dynamicImports) {
            const facade = byName.get(name)?.facadeModuleId ?? '';
            if (/\/src\/screens\/\w+\/[\w-]+-engine\.ts$/.test(facade)) visit(name);
          }
          const paths = list.map((name) => `./${name}`);
          files[match[1]!] = [paths.slice(0, first), paths.slice(first)];
        }
        const script =
          `(function(){var f=${JSON.stringify(files)};` +
          `var id=location.hash.replace(/^#/,'').split('?')[0];var w=f[id]||f.inertia;if(!w)return;` +
          `function add(h,low){var l=document.createElement('link');l.rel='modulepreload';` +
          `l.crossOrigin='';l.href=h;if(low)l.fetchPriority='low';document.head.appendChild(l);}` +
          `w[0].forEach(function(h){add(h);});w[1].forEach(function(h){add(h,1);});})();`;
        // Before the stylesheet and the entry: an inline script after a stylesheet waits for
        // it to arrive (scripts may read styles), and on Slow 4G that held the screen's chunks
        // back by most of a second (requested at 1.8 s, with the entry at 0.95 s).
        const tag = `<script>${script}</script>\n    `;
        const at = html.search(/<script type="module"|<link rel="stylesheet"/);
        return at < 0
          ? html.replace('</head>', `${tag}</head>`)
          : html.slice(0, at) + tag + html.slice(at);
      },
    },
  };
}

export default defineConfig({
  base: './',
  root: source('.'),
  plugins: [react(), themeTokens(), teacherPagesPlugin(), precacheManifest(), firstScreenPreload()],
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
    rolldownOptions: {
      output: {
        // The engine (with its WebAssembly kernel) in a chunk of its own: left to itself the
        // bundler put it in the chunk of the lab's code that Inertia imports statically, and the
        // screen's controls waited for the engine's bytes (inertia-engine.ts).
        codeSplitting: {
          groups: [{ name: 'engine', test: /[\\/]packages[\\/]engine[\\/]src[\\/]/ }],
        },
      },
    },
  },
  preview: { host: '127.0.0.1', port: 4173 },
});
