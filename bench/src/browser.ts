// `npm run bench -- --browser`: bundles browser/page.ts with esbuild, serves it from a tiny
// node:http server on 127.0.0.1 (random free port) and runs it in Debian's Chromium via playwright-core.
import { build } from 'esbuild';
import { readFileSync } from 'node:fs';
import { createServer } from 'node:http';
import type { AddressInfo } from 'node:net';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { CHROMIUM_LAUNCH } from '../../e2e/chromium.ts';

export interface BrowserResult {
  steps: number;
  medianMs: number;
  meanMs: number;
  minMs: number;
  nan: number;
  userAgent: string;
}

export async function runBrowser(): Promise<BrowserResult> {
  const page = fileURLToPath(new URL('../browser/page.ts', import.meta.url));
  const html = readFileSync(new URL('../browser/index.html', import.meta.url));
  const bundle = await build({
    entryPoints: [page],
    bundle: true,
    format: 'esm',
    platform: 'browser',
    target: 'es2022',
    minify: false,
    write: false,
    logLevel: 'silent',
  });
  const script = bundle.outputFiles[0]!.contents;
  const server = createServer((req, res) => {
    if (req.url === '/' || req.url === '/index.html') {
      res.writeHead(200, { 'content-type': 'text/html; charset=utf-8' });
      res.end(html);
    } else if (req.url === '/page.js') {
      res.writeHead(200, { 'content-type': 'text/javascript; charset=utf-8' });
      res.end(script);
    } else {
      res.writeHead(404);
      res.end();
    }
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address() as AddressInfo;
  const browser = await chromium.launch(CHROMIUM_LAUNCH);
  try {
    const tab = await browser.newPage();
    await tab.goto(`http://127.0.0.1:${port}/`);
    await tab.waitForFunction(
      () => {
        const w = window as unknown as { benchResult?: unknown; benchError?: unknown };
        return w.benchResult !== undefined || w.benchError !== undefined;
      },
      undefined,
      { timeout: 180_000, polling: 250 },
    );
    const outcome = await tab.evaluate(() => {
      const w = window as unknown as { benchResult?: BrowserResult; benchError?: string };
      return { result: w.benchResult, error: w.benchError };
    });
    if (!outcome.result) throw new Error(outcome.error ?? 'no result');
    return outcome.result;
  } finally {
    await browser.close();
    server.close();
  }
}
