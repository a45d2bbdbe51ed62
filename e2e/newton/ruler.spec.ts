import assert from 'node:assert/strict';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import { phoneOptions } from './fit.ts';
import { assertQuiet, closeApp, openApp } from './phone.ts';

/** The ruler's two ends in metres on `canvas` (its left edge, middle height, and right edge). */
async function rulerInMetres(page: Page, canvas: string) {
  return page.evaluate((selector) => {
    type Vec = { x: number; y: number };
    const element = document.querySelector(selector) as HTMLElement & {
      clientToWorld(x: number, y: number): Vec;
    };
    const box = document.querySelector('[data-ruler]')!.getBoundingClientRect();
    const y = box.top + box.height / 2;
    return {
      left: element.clientToWorld(box.left, y),
      right: element.clientToWorld(box.right, y),
      box: { x: box.left, y: box.top, width: box.width, height: box.height },
    };
  }, canvas);
}

test('newton: ruler at 375x667 on Inertia, a student shows it, it reads 2 m at the canvas scale, drags it with a finger and moves it by keyboard', async ({
  browser,
}) => {
  const app = await openApp(browser, '#inertia', phoneOptions(375, 667, false));
  const { page } = app;
  const canvas = '#inertia physical-canvas';
  try {
    await page.locator('#inertia [data-control="show-ruler"]').check();
    const ruler = page.locator('[data-ruler]');
    await ruler.waitFor({ state: 'visible' });
    const first = await rulerInMetres(page, canvas);
    const length = first.right.x - first.left.x;
    assert.ok(Math.abs(length - 2) <= 0.02, `the ruler is 2 m long on the canvas (${length} m)`);
    assert.match((await ruler.getAttribute('aria-label')) ?? '', /Ruler, 2 m long/);
    assert.equal(await ruler.locator('[data-mark="2"]').textContent(), '2 m');

    // A finger drags it 40 px right and 30 px down.
    const cdp = await page.context().newCDPSession(page);
    const from = { x: first.box.x + first.box.width / 2, y: first.box.y + first.box.height / 2 };
    await cdp.send('Input.dispatchTouchEvent', {
      type: 'touchStart',
      touchPoints: [{ ...from, id: 1 }],
    });
    for (let i = 1; i <= 5; i++) {
      await cdp.send('Input.dispatchTouchEvent', {
        type: 'touchMove',
        touchPoints: [{ x: from.x + 8 * i, y: from.y + 6 * i, id: 1 }],
      });
    }
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    await page.waitForTimeout(100);
    const dragged = await rulerInMetres(page, canvas);
    assert.ok(Math.abs(dragged.box.x - first.box.x - 40) <= 1, 'dragged 40 px right');
    assert.ok(Math.abs(dragged.box.y - first.box.y - 30) <= 1, 'dragged 30 px down');

    // Keyboard: four presses of the right arrow move it 20 cm; Shift and up, 50 cm up.
    await ruler.focus();
    for (let i = 0; i < 4; i++) await page.keyboard.press('ArrowRight');
    await page.keyboard.press('Shift+ArrowUp');
    await page.waitForTimeout(100);
    const moved = await rulerInMetres(page, canvas);
    const dx = moved.left.x - dragged.left.x;
    const dy = moved.left.y - dragged.left.y;
    assert.ok(Math.abs(dx - 0.2) <= 0.005, `four right arrows move it 0.2 m (${dx} m)`);
    assert.ok(Math.abs(dy + 0.5) <= 0.005, `Shift and up moves it 0.5 m up (${dy} m)`);
    assert.ok(Math.abs(moved.right.x - moved.left.x - 2) <= 0.02, 'still 2 m long');

    // Reset all puts it away.
    await page.locator('#inertia [data-action="reset-all"]').tap();
    await ruler.waitFor({ state: 'detached' });
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: ruler at 375x667 on Forces, shown from the panel, reads 2 m at the tracks scale', async ({
  browser,
}) => {
  const app = await openApp(browser, '#forces', phoneOptions(375, 667, false));
  const { page } = app;
  try {
    await page.locator('#forces [data-control="show-ruler"]').check();
    await page.locator('[data-ruler]').waitFor({ state: 'visible' });
    const { left, right } = await rulerInMetres(page, '#forces physical-canvas');
    const length = right.x - left.x;
    assert.ok(Math.abs(length - 2) <= 0.02, `the ruler is 2 m long on the track (${length} m)`);
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});
