// The browser tests' API, unchanged since the hand-written runner: a spec calls
// `test(name, async ({ browser, baseUrl, open }) => { ... })` and asserts with node:assert.
// Underneath, each call registers a @playwright/test test (per-test timeout, retries, traces and
// screenshots on failure, parallel workers: see playwright.config.ts). The spec's function is
// wrapped, not handed to Playwright, so it may take its context in any form it likes.
import { test as base } from '@playwright/test';
import type { Browser, BrowserContext, BrowserContextOptions, Page } from 'playwright-core';

/** The variable that carries the test server's address from global-setup.ts to the workers. */
export const BASE_URL_VARIABLE = 'PHYSICAL_E2E_BASE_URL';

/** What a browser test gets: the browser, the test server's address and a page opener. */
export interface TestContext {
  readonly browser: Browser;
  /** Base address of the test server, without a trailing slash. */
  readonly baseUrl: string;
  /**
   * Opens `path` (for example `/canvas/fixture.html`) in a new context with the given options
   * (viewport, deviceScaleFactor, reducedMotion...), after running `initScript` (source text) in
   * it before any page script. Closed after the test.
   */
  open(path: string, options?: BrowserContextOptions, initScript?: string): Promise<Page>;
}

/** A registered browser test. */
export interface BrowserTest {
  readonly name: string;
  readonly run: (context: TestContext) => Promise<void>;
}

/**
 * Playwright's test with the harness's fixtures: `browser` is Playwright's own (one Chromium per
 * worker, launched as the config says), `baseUrl` the server of global-setup.ts, `open` a page
 * opener whose contexts close after the test.
 */
export const browserTest = base.extend<{ baseUrl: string; open: TestContext['open'] }>({
  // Playwright reads a fixture's dependencies from its first parameter: it must be a pattern.
  // eslint-disable-next-line no-empty-pattern
  baseUrl: async ({}, use) => {
    const url = process.env[BASE_URL_VARIABLE];
    if (url === undefined) throw new Error(`${BASE_URL_VARIABLE} is unset: run the global setup`);
    await use(url);
  },
  open: async ({ browser, baseUrl }, use) => {
    const contexts: BrowserContext[] = [];
    await use(async (path, options = {}, initScript) => {
      const context = await browser.newContext(options);
      contexts.push(context);
      // Specs compiled with esbuild's keepNames (tsx, the bench scripts) wrap functions passed to
      // page.evaluate in a __name(...) helper the page does not have: harmless here, kept so
      // helpers shared with those scripts behave the same.
      await context.addInitScript('globalThis.__name = (target) => target;');
      if (initScript !== undefined) await context.addInitScript(initScript);
      const page = await context.newPage();
      const errors: string[] = [];
      page.on('pageerror', (error) => errors.push(error.message));
      await page.goto(baseUrl + path);
      await page.waitForFunction(
        () => document.documentElement.dataset['ready'] === 'true',
        undefined,
        { timeout: 10_000 },
      );
      if (errors.length > 0) throw new Error(`page error: ${errors.join('; ')}`);
      return page;
    });
    for (const context of contexts) await context.close();
  },
});

/** Titles registered so far, by spec file: Playwright refuses a repeated title in one file. */
const registered = new Map<string, number>();

/** Registers a browser test; spec files call it at import. */
export function test(name: string, run: (context: TestContext) => Promise<void>): void {
  // The old runner accepted a title twice in one file; number the repeats instead of failing.
  const key = `${callerFile()}\n${name}`;
  const count = (registered.get(key) ?? 0) + 1;
  registered.set(key, count);
  browserTest(count === 1 ? name : `${name} (${count})`, async ({ browser, baseUrl, open }) => {
    await run({ browser, baseUrl, open });
  });
}

/** The file of the function that called `test` (the spec), from the stack. */
function callerFile(): string {
  // Lines: the message, callerFile, test, then the spec's call.
  const line = new Error().stack?.split('\n')[3] ?? '';
  return /\(?([^\s()]+?):\d+:\d+\)?$/.exec(line.trim())?.[1] ?? line;
}
