import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import {
  assertQuiet,
  closeApp,
  LANDSCAPE,
  numberIn,
  openApp,
  PHONE,
  readout,
  screenshot,
} from './phone.ts';

const sleep = (ms: number): Promise<void> => new Promise((resolve) => setTimeout(resolve, ms));

for (const [orientation, options] of [
  ['portrait', PHONE],
  ['landscape', LANDSCAPE],
] as const) {
  test(`newton: inertia (${orientation}), the stopwatch measures simulated time, stops with a pause, and resets`, async ({
    browser,
  }) => {
    const app = await openApp(browser, '#inertia', options);
    const { page } = app;
    try {
      const stopwatch = page.locator('#inertia [data-action="stopwatch"]');
      const value = async (): Promise<number> =>
        numberIn(await readout(page, 'stopwatch', '#inertia'));
      await stopwatch.scrollIntoViewIfNeeded();
      const target = (await stopwatch.boundingBox())!;
      assert.ok(
        target.height >= 48 && target.width >= 48,
        `48 px target: ${JSON.stringify(target)}`,
      );
      assert.equal(await value(), 0);

      // Started from the keyboard, it runs with the simulation's clock.
      await stopwatch.focus();
      await page.keyboard.press('Enter');
      assert.equal(await stopwatch.getAttribute('aria-pressed'), 'true');
      await sleep(1200);
      const running = await value();
      assert.ok(running > 0.3 && running < 3, `about a second measured: ${running} s`);

      // Paused, the simulation's clock stops, and the stopwatch with it.
      await page.locator('[data-action="play"]').first().click();
      await sleep(200);
      const paused = await value();
      await sleep(600);
      assert.equal(await value(), paused, 'no time passes while paused');
      await page.locator('[data-action="play"]').first().click();

      // Stopped, it holds its value; reset, it reads 0.
      await sleep(300);
      await stopwatch.click();
      assert.equal(await stopwatch.getAttribute('aria-pressed'), 'false');
      const stopped = await value();
      assert.ok(stopped > paused, `it ran again after the pause: ${paused} -> ${stopped}`);
      await sleep(500);
      assert.equal(await value(), stopped, 'a stopped stopwatch holds its value');
      await screenshot(page, `inertia-stopwatch-${orientation}`);
      await page.locator('#inertia [data-action="stopwatch-reset"]').click();
      assert.equal(await value(), 0);
      assertQuiet(app);
    } finally {
      await closeApp(app);
    }
  });
}
