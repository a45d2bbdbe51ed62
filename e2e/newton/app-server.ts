import { existsSync, readFileSync, statSync } from 'node:fs';
import { createServer } from 'node:http';
import { extname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';

/** The built Newton app (npm run build -w @physical/newton). */
export const DIST = fileURLToPath(new URL('../../apps/newton/dist/', import.meta.url));

const TYPES: Record<string, string> = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json',
  '.webmanifest': 'application/manifest+json',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
};

/** A running static server over the built app. */
export interface AppServer {
  readonly url: string;
  close(): Promise<void>;
}

/** True when the app has been built. */
export function hasBuild(): boolean {
  return existsSync(join(DIST, 'index.html')) && existsSync(join(DIST, 'sw.js'));
}

/**
 * Serves apps/newton/dist on 127.0.0.1 and a free port, like any static host (a secure context,
 * so the service worker registers).
 */
export async function startAppServer(): Promise<AppServer> {
  if (!hasBuild()) {
    throw new Error(
      `the Newton app is not built (${DIST} has no index.html): run npm run build -w @physical/newton`,
    );
  }
  return serveStatic(DIST);
}

/** Serves the folder `root` (ending in a slash) on 127.0.0.1 and a free port. */
export async function serveStatic(root: string): Promise<AppServer> {
  const server = createServer((request, response) => {
    const path = decodeURIComponent(new URL(request.url ?? '/', 'http://x').pathname);
    let file = normalize(join(root, path));
    if (!file.startsWith(root)) {
      response.writeHead(403).end();
      return;
    }
    if (existsSync(file) && statSync(file).isDirectory()) file = join(file, 'index.html');
    if (!existsSync(file)) {
      response.writeHead(404, { 'content-type': 'text/plain' }).end('not found');
      return;
    }
    response.writeHead(200, {
      'content-type': TYPES[extname(file)] ?? 'application/octet-stream',
      'cache-control': 'no-cache',
    });
    response.end(readFileSync(file));
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const address = server.address();
  if (address === null || typeof address === 'string') throw new Error('no TCP address');
  return {
    url: `http://127.0.0.1:${address.port}`,
    close: () =>
      new Promise<void>((resolve) => {
        server.closeAllConnections();
        server.close(() => resolve());
      }),
  };
}

/**
 * Serves the built app with `vite preview`, the server `npm start` runs (it sends `Vary: Origin`
 * and its own caching headers), on 127.0.0.1 and a free port.
 */
export async function startPreviewServer(): Promise<AppServer> {
  if (!hasBuild()) {
    throw new Error(`the Newton app is not built: run npm run build -w @physical/newton`);
  }
  const { preview } = await import('vite');
  const config = fileURLToPath(new URL('../../apps/newton/vite.config.ts', import.meta.url));
  const server = await preview({
    configFile: config,
    logLevel: 'error',
    preview: { host: '127.0.0.1', port: 0, strictPort: false, open: false },
  });
  const address = server.httpServer.address();
  if (address === null || typeof address === 'string') throw new Error('no TCP address');
  return {
    url: `http://127.0.0.1:${address.port}`,
    close: () => server.close(),
  };
}
