import { createHash } from 'node:crypto';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import react from '@vitejs/plugin-react';
import { defineConfig, type Plugin } from 'vite';
import type { OutputBundle, OutputChunk } from 'rolldown';
import { tokenCss } from './src/app/theme-tokens.ts';
import { brotliAssets } from './scripts/brotli-assets.ts';
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
 * Fetches the first screen's code as soon as the entry has arrived. A small inline script in the
 * page preloads the entry (`rel=preload`, which the entry's module script then uses) and, when it
 * has loaded, adds `modulepreload` links for the chunks of the screen the address names
 * (#forces...), or of Inertia. Without any preload the screen's chunk and the engine were
 * requested only once React had evaluated and rendered the shell (a second round of downloads
 * after a second of a slow phone's CPU). Requested with the entry, they shared its bandwidth
 * (Slow 4G's 1.6 Mbit/s), so every file arrived at once while the phone's CPU waited idle for
 * all of them. Requested when the entry arrives, they download while the entry (React and the
 * shell, the largest file to evaluate) compiles and runs. The entry's `load` is the signal, not
 * the entry itself: a module runs only once compiled (a quarter of a second of a slow phone's
 * CPU for the entry), and a request made from inside the entry cost DevTools-attached pages
 * (the speed bench, Lighthouse) up to 0.4 s more, collecting the entry's source positions for
 * the request's initiator. The screen ids come from the screens' folders (`src/screens/<id>/`).
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
        // A chunk and every chunk it imports statically, depth first.
        const closure = (name: string, list: string[] = []): string[] => {
          if (list.includes(name)) return list;
          list.push(name);
          for (const next of byName.get(name)?.imports ?? []) closure(next, list);
          return list;
        };
        // The entry and its imports are on their way when the preload runs (the page asks for them).
        const requested = new Set(
          chunks.filter((chunk) => chunk.isEntry).flatMap((chunk) => closure(chunk.fileName)),
        );
        const files: Record<string, string[]> = {};
        for (const chunk of chunks) {
          const match = /\/src\/screens\/(\w+)\/\w+Screen\.tsx$/.exec(chunk.facadeModuleId ?? '');
          if (match === null || !chunk.isDynamicEntry) continue;
          files[match[1]!] = closure(chunk.fileName)
            .filter((name) => !requested.has(name))
            .map((name) => `./${name}`);
        }
        const entry = chunks.find((chunk) => chunk.isEntry)?.fileName;
        if (entry === undefined) return html;
        const script =
          `(function(){var f=${JSON.stringify(files)};` +
          `var id=location.hash.replace(/^#/,'').split('?')[0];` +
          `function add(rel,h,onload){var l=document.createElement('link');l.rel=rel;` +
          `if(rel==='preload')l.as='script';l.crossOrigin='';l.href=h;` +
          `if(onload)l.onload=l.onerror=onload;document.head.appendChild(l);}` +
          `add('preload','./${entry}',function(){` +
          `(f[id]||f.inertia||[]).forEach(function(h){add('modulepreload',h);});});})();`;
        // Before the stylesheet and the entry: an inline script after a stylesheet waits for
        // it to arrive (scripts may read styles), and the entry's request must be the preload's.
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
  plugins: [
    react(),
    themeTokens(),
    teacherPagesPlugin(),
    precacheManifest(),
    firstScreenPreload(),
    brotliAssets(source('dist')),
  ],
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
