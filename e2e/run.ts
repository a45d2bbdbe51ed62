// Browser tests of @physical/canvas: serves e2e/ with Vite on 127.0.0.1 (sources aliased, no
// build), drives Debian's Chromium with playwright-core, and prints "N passed, N failed".
// Usage: tsx e2e/run.ts [name filter]
import { readdirSync } from 'node:fs';
import { dirname, join, relative } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { chromium, type BrowserContext } from 'playwright-core';
import { startServer } from './server.ts';
import { tests } from './harness.ts';

const here = dirname(fileURLToPath(import.meta.url));
const filter = process.argv[2] ?? '';

function specFiles(folder: string): string[] {
  return readdirSync(folder, { withFileTypes: true }).flatMap((entry) => {
    const path = join(folder, entry.name);
    if (entry.isDirectory()) return entry.name === 'node_modules' ? [] : specFiles(path);
    return entry.name.endsWith('.spec.ts') ? [path] : [];
  });
}

const server = await startServer();
const browser = await chromium.launch({
  executablePath: process.env['CHROMIUM_PATH'] ?? '/usr/bin/chromium',
  args: [
    '--no-sandbox',
    '--disable-gpu',
    '--disable-background-networking',
    '--disable-component-update',
    '--disable-sync',
    '--no-first-run',
  ],
});
let passed = 0;
let failed = 0;
try {
  for (const file of specFiles(here).sort()) await import(pathToFileURL(file).href);
  for (const { name, run } of tests) {
    if (!name.includes(filter)) continue;
    const contexts: BrowserContext[] = [];
    const started = performance.now();
    try {
      await run({
        browser,
        baseUrl: server.url,
        open: async (path, options = {}, initScript) => {
          const context = await browser.newContext(options);
          contexts.push(context);
          // tsx compiles the specs with esbuild's keepNames, which wraps functions passed to
          // page.evaluate in a __name(...) helper the page does not have.
          await context.addInitScript('globalThis.__name = (target) => target;');
          if (initScript !== undefined) await context.addInitScript(initScript);
          const page = await context.newPage();
          const errors: string[] = [];
          page.on('pageerror', (error) => errors.push(error.message));
          await page.goto(server.url + path);
          await page.waitForFunction(
            () => document.documentElement.dataset['ready'] === 'true',
            undefined,
            {
              timeout: 10_000,
            },
          );
          if (errors.length > 0) throw new Error(`page error: ${errors.join('; ')}`);
          return page;
        },
      });
      passed++;
      process.stdout.write(`  ok   ${name} (${Math.round(performance.now() - started)} ms)\n`);
    } catch (error) {
      failed++;
      const message = error instanceof Error ? (error.stack ?? error.message) : String(error);
      process.stdout.write(`  FAIL ${name}\n${message.replace(/^/gm, '       ')}\n`);
    } finally {
      for (const context of contexts) await context.close();
    }
  }
} finally {
  await browser.close();
  await server.close();
}
process.stdout.write(
  `\n${relative(process.cwd(), here) || '.'}: ${passed} passed, ${failed} failed\n`,
);
process.exitCode = failed > 0 || passed === 0 ? 1 : 0;
