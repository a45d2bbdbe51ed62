import assert from 'node:assert/strict';
import type { Locator, Page } from 'playwright-core';
import { test } from '../harness.ts';
import { closeApp, openApp } from './phone.ts';

/** Adds `count` particles as a keyboard user does (Enter on Add); returns the Add button. */
async function addFromKeyboard(page: Page, count: number): Promise<Locator> {
  const add = page.locator('#reactions [data-action="add"]');
  await add.focus();
  for (let i = 0; i < count; i++) await page.keyboard.press('Enter');
  return add;
}

// A frame of the tray should cost the physics and the canvas only: an animation that never ends
// (MUI's focus ripple, pulsing on a button focused from the keyboard) restyled the whole page in
// every frame, a few milliseconds each on a slow phone with 50 particles.
test('newton: reactions, a button focused from the keyboard runs no endless animation beside the tray', async ({
  browser,
}) => {
  const app = await openApp(browser, '#reactions');
  try {
    const { page } = app;
    const add = await addFromKeyboard(page, 5);
    await page.locator('#reactions [data-action="tilt-right"]').focus();
    await page.keyboard.press('Enter');
    await add.focus();
    // Two frames: any animation the focus started is running by then.
    await page.evaluate(
      () =>
        new Promise<void>((resolve) =>
          requestAnimationFrame(() => requestAnimationFrame(() => resolve())),
        ),
    );
    const endless = await page.evaluate(() =>
      document
        .getAnimations()
        .filter((animation) => animation.effect?.getComputedTiming().iterations === Infinity)
        .map((animation) => {
          const target = (animation.effect as KeyframeEffect | null)?.target;
          return `${animation.constructor.name} on <${target?.tagName.toLowerCase()} class="${String(target?.className).slice(0, 50)}">`;
        }),
    );
    assert.deepEqual(endless, [], 'no animation without end runs while the tray does');
    assert.equal(
      await page.evaluate(() => document.activeElement?.getAttribute('data-action')),
      'add',
      'the add button has the focus',
    );
  } finally {
    await closeApp(app);
  }
});

// A pile of 50 particles crossing a tilted tray collides in some 130 pairs at a time: all their
// arrows covered the particles, and filling them took most of a slow phone's frame. The tray
// shows the strongest pairs (collision-arrows.ts, MAX_SHOWN_PAIRS = 24), and still shows some.
test('newton: reactions, a crowd crossing the tray shows its 24 strongest collisions, not all', async ({
  browser,
}) => {
  const app = await openApp(browser, '#reactions');
  try {
    const { page } = app;
    await addFromKeyboard(page, 50);
    assert.equal(await page.locator('[data-readout="count"]').textContent(), '50');
    const counts: number[] = [];
    // Each press leans the tray a quarter further (TILT_STEP): right, then as far left, and back.
    for (const [direction, presses] of [
      ['tilt-right', 3],
      ['tilt-left', 6],
      ['tilt-right', 6],
    ] as const) {
      const button = page.locator(`#reactions [data-action="${direction}"]`);
      for (let i = 0; i < presses; i++) await button.click();
      for (let i = 0; i < 6; i++) {
        await page.waitForTimeout(250);
        counts.push(
          Number(await page.locator('#reactions [data-arrows]').getAttribute('data-arrows')),
        );
      }
    }
    const most = Math.max(...counts);
    assert.ok(most >= 8, `the crowd's collisions show arrows (at most ${most} at a time)`);
    assert.ok(most <= 48, `at most 24 pairs of arrows at a time, not ${most} arrows`);
  } finally {
    await closeApp(app);
  }
});
