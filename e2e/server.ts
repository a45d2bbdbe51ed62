import { dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { createServer, type Plugin } from 'vite';

const here = dirname(fileURLToPath(import.meta.url));

/** A running test server. */
export interface TestServer {
  /** Base address, for example `http://127.0.0.1:41234`. */
  readonly url: string;
  close(): Promise<void>;
}

/**
 * A page opened with `?coi` in its address is cross-origin isolated (SharedArrayBuffer): it and
 * what it loads (its workers) get COOP and COEP headers.
 */
function crossOriginIsolation(): Plugin {
  return {
    name: 'cross-origin-isolation',
    configureServer(server) {
      server.middlewares.use((request, response, next) => {
        const referer = request.headers.referer ?? '';
        if (/[?&]coi\b/.test(request.url ?? '') || /[?&]coi\b/.test(referer)) {
          response.setHeader('Cross-Origin-Opener-Policy', 'same-origin');
          response.setHeader('Cross-Origin-Embedder-Policy', 'require-corp');
        }
        next();
      });
    },
  };
}

/**
 * Serves e2e/ with Vite on 127.0.0.1 and a free port; `@physical/*` resolve to the packages'
 * sources, so the tests need no build.
 */
export async function startServer(): Promise<TestServer> {
  const server = await createServer({
    configFile: false,
    root: here,
    logLevel: 'error',
    clearScreen: false,
    resolve: {
      alias: {
        // Before '@physical/engine', which would also match its subpath.
        '@physical/engine/javascript-kernel': fileURLToPath(
          new URL('../packages/engine/src/javascript-kernel.ts', import.meta.url),
        ),
        // PHYSICAL_ENGINE_ENTRY tests against another engine checkout (for example a release).
        '@physical/engine':
          process.env['PHYSICAL_ENGINE_ENTRY'] ??
          fileURLToPath(new URL('../packages/engine/src/index.ts', import.meta.url)),
        '@physical/canvas': fileURLToPath(
          new URL('../packages/canvas/src/index.ts', import.meta.url),
        ),
        '@physical/react': fileURLToPath(
          new URL('../packages/react/src/index.ts', import.meta.url),
        ),
        '@physical/dom': fileURLToPath(new URL('../packages/dom/src/index.ts', import.meta.url)),
        '@physical/worker': fileURLToPath(
          new URL('../packages/worker/src/index.ts', import.meta.url),
        ),
      },
    },
    plugins: [crossOriginIsolation()],
    server: {
      host: '127.0.0.1',
      port: 0,
      strictPort: false,
      hmr: false,
      watch: null,
      fs: { strict: false },
    },
    // React is CommonJS: pre-bundle it (and nothing else, so start-up stays quick).
    optimizeDeps: {
      noDiscovery: true,
      include: ['react', 'react-dom/client', 'react/jsx-runtime', 'react/jsx-dev-runtime'],
    },
  });
  await server.listen();
  const address = server.httpServer?.address();
  if (address === null || address === undefined || typeof address === 'string') {
    await server.close();
    throw new Error('the test server has no TCP address');
  }
  return { url: `http://127.0.0.1:${address.port}`, close: () => server.close() };
}
