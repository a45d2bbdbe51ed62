import { existsSync, mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Browser, BrowserContext, Page } from 'playwright-core';
import { serveStatic, type AppServer } from '../newton/app-server.ts';
import { PHONE, waitReady } from '../newton/phone.ts';

/** The built gallery (npm run build -w @physical/gallery). */
export const GALLERY_DIST = fileURLToPath(new URL('../../apps/gallery/dist/', import.meta.url));
export const SCREENSHOTS = new URL('../../test-results/gallery/', import.meta.url);

/** A page of the built gallery with every console error and warning collected. */
export interface GalleryPage {
  readonly page: Page;
  readonly context: BrowserContext;
  readonly server: AppServer;
  readonly problems: string[];
}

/** Serves the built gallery and opens `hash` on a phone. Close with {@link closeGallery}. */
export async function openGallery(browser: Browser, hash = ''): Promise<GalleryPage> {
  if (!existsSync(join(GALLERY_DIST, 'index.html'))) {
    throw new Error(
      `the gallery is not built (${GALLERY_DIST} has no index.html): run npm run build -w @physical/gallery`,
    );
  }
  const server = await serveStatic(GALLERY_DIST);
  const context = await browser.newContext(PHONE);
  await context.addInitScript('globalThis.__name = (target) => target;');
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

export async function closeGallery(gallery: GalleryPage): Promise<void> {
  await gallery.context.close();
  await gallery.server.close();
}

export async function screenshot(page: Page, name: string, fullPage = false): Promise<void> {
  mkdirSync(SCREENSHOTS, { recursive: true });
  await page.screenshot({ path: new URL(`${name}.png`, SCREENSHOTS).pathname, fullPage });
}

/** Number of bodies and steps of the world in the sample page's canvas. */
export async function stageWorld(page: Page): Promise<{ bodies: number; steps: number }> {
  return page.evaluate(() => {
    const canvas = document.querySelector('.stage physical-canvas') as unknown as {
      world: { bodies: unknown[]; steps: number };
    };
    return { bodies: canvas.world.bodies.length, steps: canvas.world.steps };
  });
}
