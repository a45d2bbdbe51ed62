import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { createRequire } from 'node:module';
import type { Browser, BrowserContext, BrowserContextOptions, Page } from 'playwright-core';
import { startAppServer, startPreviewServer, type AppServer } from './app-server.ts';

/** The same phone turned sideways: landscape. */
export const LANDSCAPE: BrowserContextOptions = {
  viewport: { width: 844, height: 390 },
  deviceScaleFactor: 3,
  isMobile: true,
  hasTouch: true,
  locale: 'en-US',
  serviceWorkers: 'allow',
};

/** A phone: portrait, touch, three device pixels per CSS pixel. */
export const PHONE: BrowserContextOptions = {
  viewport: { width: 390, height: 844 },
  deviceScaleFactor: 3,
  isMobile: true,
  hasTouch: true,
  locale: 'en-US',
  serviceWorkers: 'allow',
};

export const SCREENSHOTS = new URL('../../test-results/newton/', import.meta.url);

/** A page of the built app, with every console error and warning collected. */
export interface AppPage {
  readonly page: Page;
  readonly context: BrowserContext;
  readonly server: AppServer;
  /** Console errors and warnings, and uncaught errors. */
  readonly problems: string[];
}

/**
 * Serves the built app, opens `hash` (for example `#forces`) in a new context and waits until
 * the app has rendered. Call {@link closeApp} in a finally.
 */
export async function openApp(
  browser: Browser,
  hash = '',
  options: BrowserContextOptions = PHONE,
  /** 'preview': the server `npm start` runs (vite preview); 'static': a plain file server. */
  serverKind: 'static' | 'preview' = 'static',
  /** Source text run in the page before any page script. */
  initScript?: string,
): Promise<AppPage> {
  const server = serverKind === 'preview' ? await startPreviewServer() : await startAppServer();
  const context = await browser.newContext(options);
  // tsx compiles specs with keepNames: functions passed to page.evaluate call __name.
  await context.addInitScript('globalThis.__name = (target) => target;');
  if (initScript !== undefined) await context.addInitScript(initScript);
  const page = await context.newPage();
  const problems: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error' || message.type() === 'warning') {
      problems.push(`${message.type()}: ${message.text()}`);
    }
  });
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  await page.goto(`${server.url}/${hash}`);
  await waitReady(page);
  return { page, context, server, problems };
}

export async function waitReady(page: Page): Promise<void> {
  await page.waitForFunction(
    () => document.documentElement.dataset['ready'] === 'true',
    undefined,
    {
      timeout: 10_000,
    },
  );
}

export async function closeApp(app: AppPage): Promise<void> {
  await app.context.close();
  await app.server.close();
}

/** Fails on any console error or warning. */
export function assertQuiet(app: AppPage): void {
  assert.deepEqual(app.problems, [], 'the console must stay free of errors and warnings');
}

export async function screenshot(page: Page, name: string): Promise<void> {
  mkdirSync(SCREENSHOTS, { recursive: true });
  await page.screenshot({ path: new URL(`${name}.png`, SCREENSHOTS).pathname });
}

/** Text of a readout (`data-readout`) inside `scope`, with no-break spaces as spaces. */
export async function readout(page: Page, name: string, scope = 'body'): Promise<string> {
  const text = await page.locator(`${scope} [data-readout="${name}"]`).first().textContent();
  return (text ?? '').replace(/\u00a0/g, ' ').trim();
}

/** The first number in a text ("0.734 m/s" -> 0.734; German commas accepted). */
export function numberIn(text: string): number {
  const match = /-?\d+(?:[.,]\d+)?/.exec(text);
  assert.ok(match !== null, `no number in "${text}"`);
  return Number(match[0].replace(',', '.'));
}

/**
 * How many of the visible canvas's device pixels differ from its background: a blank canvas
 * gives 0.
 */
export async function paintedPixels(page: Page, selector: string): Promise<number> {
  return differingPixels(page, selector, 'background');
}

/**
 * How many of the canvas' pixels changed since the last call for the same selector (the first
 * call records the canvas and returns 0). Unlike a count of painted pixels this sees a drawing laid
 * over another one, such as an arrow over its body.
 */
export async function changedPixels(page: Page, selector: string): Promise<number> {
  return differingPixels(page, selector, 'last');
}

/** Pixels of the canvas that differ from its background colour, or from its last recorded copy. */
async function differingPixels(
  page: Page,
  selector: string,
  against: 'background' | 'last',
): Promise<number> {
  return page.evaluate(
    ([css, reference]) => {
      const host = document.querySelector(css)!;
      const source = host.shadowRoot!.querySelector('canvas')!;
      // A fresh copy read once: no repeated read-back from the app's canvas (a console warning).
      const copy = document.createElement('canvas');
      copy.width = source.width;
      copy.height = source.height;
      const context = copy.getContext('2d', { willReadFrequently: true })!;
      context.drawImage(source, 0, 0);
      const { data } = context.getImageData(0, 0, copy.width, copy.height);
      let other: ArrayLike<number>;
      if (reference === 'last') {
        const store = window as unknown as { __lastPixels?: Record<string, Uint8ClampedArray> };
        const last = (store.__lastPixels ??= {})[css];
        store.__lastPixels[css] = data;
        if (last === undefined || last.length !== data.length) return 0;
        other = last;
      } else {
        // The background: the first pixel's colour, at every pixel.
        other = { length: 4, 0: data[0]!, 1: data[1]!, 2: data[2]!, 3: data[3]! };
      }
      const stride = other.length === data.length ? 1 : 0;
      let count = 0;
      for (let i = 0; i < data.length; i += 4) {
        const j = i * stride;
        if (
          Math.abs(data[i]! - other[j]!) +
            Math.abs(data[i + 1]! - other[j + 1]!) +
            Math.abs(data[i + 2]! - other[j + 2]!) >
          30
        ) {
          count++;
        }
      }
      return count;
    },
    [selector, against] as const,
  );
}

/** Runs axe-core on the page; returns the serious and critical violations. */
export async function axeViolations(page: Page): Promise<string[]> {
  const path = createRequire(import.meta.url).resolve('axe-core/axe.min.js');
  await page.addScriptTag({ path });
  const violations = await page.evaluate(async () => {
    const axe = (
      window as unknown as {
        axe: {
          run: (context?: unknown) => Promise<{
            violations: { id: string; impact: string | null; nodes: { target: unknown[] }[] }[];
          }>;
        };
      }
    ).axe;
    const result = await axe.run(document);
    return result.violations.map((violation) => ({
      id: violation.id,
      impact: violation.impact,
      targets: violation.nodes.map((node) => JSON.stringify(node.target)).slice(0, 3),
    }));
  });
  return violations
    .filter((violation) => violation.impact === 'serious' || violation.impact === 'critical')
    .map((violation) => `${violation.impact} ${violation.id}: ${violation.targets.join(', ')}`);
}
