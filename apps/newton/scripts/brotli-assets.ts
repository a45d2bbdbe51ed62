// Brotli for the built app: the build writes a `.br` beside every text file (quality 11, once),
// and `vite preview` (npm start) answers a browser that accepts Brotli with it. On a school
// phone's Slow 4G (1.6 Mbit/s) the first screen's files are 14 % smaller than with the gzip
// `vite preview` makes on the fly (163 KB against 189 KB): about 130 ms sooner. Static hosts
// serve such `.br` files as they are (nginx's brotli_static, most CDNs compress the same way).
import { brotliCompressSync, constants } from 'node:zlib';
import { existsSync, readdirSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { extname, join, normalize, sep } from 'node:path';
import type { Plugin } from 'vite';

/** What each compressible file is served as. */
export const TEXT_TYPES: Readonly<Record<string, string>> = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json',
  '.svg': 'image/svg+xml',
  '.webmanifest': 'application/manifest+json',
};

/** Smaller files go as they are: Brotli's few bytes saved are less than a header's. */
const MIN_BYTES = 1024;

/** `data` compressed at Brotli's best quality (a text file: the text mode). */
export function brotli(data: Uint8Array): Buffer {
  return brotliCompressSync(data, {
    params: {
      [constants.BROTLI_PARAM_QUALITY]: constants.BROTLI_MAX_QUALITY,
      [constants.BROTLI_PARAM_MODE]: constants.BROTLI_MODE_TEXT,
      [constants.BROTLI_PARAM_SIZE_HINT]: data.byteLength,
    },
  });
}

/** Writes `<file>.br` beside each text file of `folder` (recursively); returns how many. */
export function writeBrotliFiles(folder: string): number {
  let written = 0;
  for (const name of readdirSync(folder)) {
    const path = join(folder, name);
    if (statSync(path).isDirectory()) {
      written += writeBrotliFiles(path);
      continue;
    }
    if (TEXT_TYPES[extname(name)] === undefined) continue;
    const data = readFileSync(path);
    if (data.byteLength < MIN_BYTES) continue;
    writeFileSync(`${path}.br`, brotli(data));
    written++;
  }
  return written;
}

/**
 * The `.br` file that answers a request for `url` in `root` (the built app), or null: the
 * request accepts Brotli, names a text file inside `root` (`/` is `/index.html`), and the build
 * wrote its `.br`.
 */
export function brotliFileFor(root: string, url: string, acceptEncoding: string): string | null {
  if (!/\bbr\b/.test(acceptEncoding)) return null;
  let path: string;
  try {
    path = decodeURIComponent(new URL(url, 'http://x').pathname);
  } catch {
    return null;
  }
  if (path.endsWith('/')) path += 'index.html';
  const file = normalize(join(root, path));
  if (!file.startsWith(root.endsWith(sep) ? root : root + sep)) return null;
  if (TEXT_TYPES[extname(file)] === undefined) return null;
  return existsSync(`${file}.br`) ? `${file}.br` : null;
}

/** The plugins: `.br` files after the build, and `vite preview` serving them. */
export function brotliAssets(outDir: string): Plugin[] {
  return [
    {
      name: 'newton-brotli-files',
      apply: 'build',
      // The last hook of a build: every file (the bundle's, public/'s) is written by now.
      closeBundle() {
        writeBrotliFiles(outDir);
      },
    },
    {
      name: 'newton-brotli-preview',
      configurePreviewServer(server) {
        server.middlewares.use((request, response, next) => {
          if (request.method !== 'GET' && request.method !== 'HEAD') return next();
          const accept = String(request.headers['accept-encoding'] ?? '');
          const file = brotliFileFor(outDir, request.url ?? '/', accept);
          if (file === null) return next();
          const data = readFileSync(file);
          response.statusCode = 200;
          response.setHeader('Content-Type', TEXT_TYPES[extname(file.slice(0, -3))]!);
          response.setHeader('Content-Encoding', 'br');
          response.setHeader('Content-Length', data.byteLength);
          response.setHeader('Cache-Control', 'no-cache');
          // Beside the Origin the CORS middleware may have named: a cache keeps both answers.
          const vary = response.getHeader('Vary');
          response.setHeader(
            'Vary',
            vary === undefined ? 'Accept-Encoding' : `${String(vary)}, Accept-Encoding`,
          );
          response.end(request.method === 'HEAD' ? undefined : data);
        });
      },
    },
  ];
}
