import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import { closeApp, openApp } from './phone.ts';

// A frame of the tray should cost the physics and the canvas only: an animation that never ends
// (MUI's focus ripple, pulsing on a button focused from the keyboard) restyled the whole page in
// every frame, a few milliseconds each on a slow phone with 50 particles.
test('newton: reactions, a button focused from the keyboard runs no endless animation beside the tray', async ({
  browser,
}) => {
  const app = await openApp(browser, '#reactions');
  try {
    const { page } = app;
    const add = page.locator('#reactions [data-action="add"]');
    await add.focus();
    for (let i = 0; i < 5; i++) await page.keyboard.press('Enter');
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
