import assert from 'node:assert/strict';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import { closeApp, openApp } from './phone.ts';

/** Seconds of random input per screen: short, so CI stays quick; the seed makes it repeatable. */
const SECONDS_PER_SCREEN = 5;
const KEYS = [
  'ArrowLeft',
  'ArrowRight',
  'ArrowUp',
  'ArrowDown',
  'Enter',
  ' ',
  'Tab',
  'Home',
  'End',
];
const TYPED = ['0', '-3', 'abc', '1e9', '0x10', '2,5', '', '4.99', '5', '9999', 'NaN', '.'];

/** A small seeded generator (mulberry32): the same run every time. */
function random(seed: number): () => number {
  let state = seed >>> 0;
  return () => {
    state = (state + 0x6d2b79f5) >>> 0;
    let t = state;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

async function heapUsed(page: Page): Promise<number> {
  const session = await page.context().newCDPSession(page);
  await session.send('HeapProfiler.collectGarbage');
  const { usedSize } = await session.send('Runtime.getHeapUsage');
  await session.detach();
  return usedSize;
}

async function closeDialogs(page: Page): Promise<void> {
  for (let i = 0; i < 3 && (await page.getByRole('dialog').count()) > 0; i++) {
    await page.keyboard.press('Escape');
    await page
      .getByRole('dialog')
      .first()
      .waitFor({ state: 'detached', timeout: 2000 })
      .catch(() => undefined);
  }
}

async function fuzzStep(page: Page, screen: string, next: () => number): Promise<void> {
  const pick = <T>(items: readonly T[]): T => items[Math.floor(next() * items.length)]!;
  const dialog = page.getByRole('dialog');
  if ((await dialog.count()) > 0) {
    const inputs = await dialog.locator('input[type="text"], input:not([type])').all();
    if (inputs.length > 0 && next() < 0.6) {
      await pick(inputs).fill(pick(TYPED));
      return;
    }
    const ok = dialog.getByRole('button', { name: 'OK' });
    if (next() < 0.5 && (await ok.count()) > 0 && (await ok.isEnabled())) await ok.click();
    else await page.keyboard.press('Escape');
    await dialog.waitFor({ state: 'detached', timeout: 3000 }).catch(() => undefined);
    return;
  }
  const roll = next();
  const canvas = page.locator(`#${screen} physical-canvas`).first();
  const box = await canvas.boundingBox();
  if (roll < 0.3 && box !== null) {
    await page.touchscreen.tap(box.x + box.width * next(), box.y + box.height * next());
  } else if (roll < 0.4 && box !== null) {
    await page.mouse.move(box.x + box.width * next(), box.y + box.height * next());
    await page.mouse.down();
    await page.mouse.move(box.x + box.width * next(), box.y + box.height * next(), { steps: 4 });
    await page.mouse.up();
  } else if (roll < 0.65) {
    await page.keyboard.press(pick(KEYS));
  } else {
    // Any control of the screen (not the navigation, not the teacher link).
    const controls = await page
      .locator(`#${screen} [data-action]:not([disabled]), #${screen} input[type="range"]`)
      .all();
    if (controls.length === 0) return;
    const control = pick(controls);
    if (await control.isVisible()) await control.click({ timeout: 2000 }).catch(() => undefined);
  }
}

test('newton: fuzz, random taps, drags, keys and dialog input on every screen: no console error, finite readouts, the heap levels off', async ({
  browser,
}) => {
  const app = await openApp(browser, '#inertia');
  const { page } = app;
  const next = random(16);
  try {
    const heaps: number[] = [];
    for (const round of [0, 1]) {
      for (const screen of ['inertia', 'forces', 'reactions']) {
        await closeDialogs(page);
        await page.locator(`[data-nav="${screen}"]`).click();
        await page.locator(`#${screen}`).waitFor({ state: 'visible' });
        const end = Date.now() + (SECONDS_PER_SCREEN * 1000) / 2;
        while (Date.now() < end) await fuzzStep(page, screen, next);
        const bad = await page.evaluate(() =>
          [...document.querySelectorAll('[data-readout]')]
            .map((element) => element.textContent ?? '')
            .filter((text) => /NaN|Infinity|undefined/.test(text)),
        );
        assert.deepEqual(bad, [], `${screen}: readouts that are not numbers`);
      }
      await closeDialogs(page);
      heaps.push(await heapUsed(page));
      void round;
    }
    // The second round of the same input keeps the heap within 30 % (+ 2 MB) of the first.
    assert.ok(
      heaps[1]! <= heaps[0]! * 1.3 + 2e6,
      `heap grew from ${(heaps[0]! / 1e6).toFixed(1)} MB to ${(heaps[1]! / 1e6).toFixed(1)} MB`,
    );
    assert.deepEqual(app.problems, [], 'the console stays free of errors and warnings');
  } finally {
    await closeApp(app);
  }
});
