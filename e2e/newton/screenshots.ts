// Screenshots of every Newton screen at 375x667, upright and sideways, in English and German,
// each a moment into an experiment, saved to .screens/ (not committed) for a person to look at.
// Usage: npm run build -w @physical/newton && npx tsx e2e/newton/screenshots.ts
import { mkdirSync } from 'node:fs';
import { chromium } from 'playwright-core';
import { startAppServer } from './app-server.ts';
import { SCREENS, chooseLocale, phoneOptions, showScreen } from './fit.ts';

const OUT = new URL('../../.screens/', import.meta.url);
mkdirSync(OUT, { recursive: true });
const server = await startAppServer();
const browser = await chromium.launch({
  executablePath: process.env['CHROMIUM_PATH'] ?? '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--no-first-run'],
});
try {
  for (const landscape of [false, true]) {
    for (const locale of ['en', 'de'] as const) {
      const context = await browser.newContext(phoneOptions(375, 667, landscape));
      const page = await context.newPage();
      await page.goto(`${server.url}/#inertia`);
      await page.waitForFunction(() => document.documentElement.dataset['ready'] === 'true');
      await chooseLocale(page, locale);
      for (const screen of SCREENS) {
        await showScreen(page, screen);
        if (screen === 'inertia') await page.locator('[data-action="toggle-force"]').tap();
        if (screen === 'forces') await page.locator('[data-action="start"]').tap();
        if (screen === 'reactions') {
          for (let i = 0; i < 6; i++) await page.locator('[data-action="add"]').tap();
        }
        await page.waitForTimeout(1200);
        const name = `${screen}-375x667-${landscape ? 'landscape' : 'portrait'}-${locale}.png`;
        await page.screenshot({ path: new URL(name, OUT).pathname });
        process.stdout.write(`.screens/${name}\n`);
      }
      await context.close();
    }
  }
} finally {
  await browser.close();
  await server.close();
}
