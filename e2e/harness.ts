import type { Browser, BrowserContextOptions, Page } from 'playwright-core';

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

/** Tests registered by the spec files, in order. */
export const tests: BrowserTest[] = [];

/** Registers a browser test; spec files call it at import. */
export function test(name: string, run: (context: TestContext) => Promise<void>): void {
  tests.push({ name, run });
}
