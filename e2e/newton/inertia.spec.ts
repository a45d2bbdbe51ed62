import assert from 'node:assert/strict';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import {
  LANDSCAPE,
  PHONE,
  assertQuiet,
  closeApp,
  numberIn,
  openApp,
  readout,
  screenshot,
} from './phone.ts';

const sleep = (ms: number): Promise<void> => new Promise((resolve) => setTimeout(resolve, ms));

/** Sets the force in the dialog: `angleKey` presses on the dial (Home = 0°), magnitude to max. */
async function setForce(page: Page, angleKeys: string[]): Promise<void> {
  await page.locator('#inertia [data-action="change-force"]').click();
  const dial = page.getByTestId('angle-dial');
  await dial.focus();
  for (const key of angleKeys) await page.keyboard.press(key);
  await page
    .getByRole('dialog')
    .getByRole('slider', { name: /Magnitude/ })
    .focus();
  await page.keyboard.press('End');
  await page.getByRole('button', { name: 'OK' }).click();
  await page.getByRole('dialog').waitFor({ state: 'detached' });
}

/** Device pixels painted in the strip between the canvas's top edge and the top wall. */
async function paintedAboveTopWall(page: Page): Promise<number> {
  return page.evaluate(() => {
    const host = document.querySelector('#inertia physical-canvas') as HTMLElement & {
      worldToScreen(point: { x: number; y: number }): { x: number; y: number };
    };
    const source = host.shadowRoot!.querySelector('canvas')!;
    const ratio = source.width / source.clientWidth;
    const wallY = host.worldToScreen({ x: 0, y: 0 }).y;
    const left = host.worldToScreen({ x: 0, y: 0 }).x;
    const right = host.worldToScreen({ x: 1000, y: 0 }).x;
    const copy = document.createElement('canvas');
    copy.width = source.width;
    copy.height = source.height;
    const context = copy.getContext('2d', { willReadFrequently: true })!;
    context.drawImage(source, 0, 0);
    const rows = Math.max(0, Math.floor((wallY - 3) * ratio));
    if (rows === 0) return -1;
    const x0 = Math.max(0, Math.floor(left * ratio));
    const x1 = Math.min(copy.width, Math.ceil(right * ratio));
    const { data } = context.getImageData(x0, 0, x1 - x0, rows);
    const [r0, g0, b0] = [data[0]!, data[1]!, data[2]!];
    let count = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (Math.abs(data[i]! - r0) + Math.abs(data[i + 1]! - g0) + Math.abs(data[i + 2]! - b0) > 30)
        count++;
    }
    return count;
  });
}

for (const [orientation, options] of [
  ['portrait', PHONE],
  ['landscape', LANDSCAPE],
] as const) {
  test(`newton: inertia (${orientation}), elastic walls keep the speed, bounciness and surface are visible controls, a pinned body reads at rest, arrows stay inside`, async ({
    browser,
  }) => {
    const app = await openApp(browser, '#inertia', options);
    const { page } = app;
    try {
      // The walls' bounciness and the surface are on screen: perfectly elastic, on ice.
      const bounciness = page.getByRole('slider', { name: /Wall bounciness/ });
      assert.equal(await bounciness.getAttribute('aria-valuenow'), '100');
      assert.equal(await page.locator('[data-surface="ice"]').getAttribute('aria-pressed'), 'true');

      await setForce(page, ['Home']);
      await page.locator('#inertia [data-action="toggle-force"]').click();
      await sleep(350);
      await page.locator('#inertia [data-action="toggle-force"]').click();
      await sleep(200);
      const first = numberIn(await readout(page, 'speed', '#inertia'));
      assert.ok(first > 0.5, `moving after the push (${first} m/s)`);
      // Bounces off the side walls for 4 s: the speed stays (no hidden bounciness or friction).
      await page.waitForFunction(
        () =>
          /hit the (right|left) wall/.test(
            document.querySelector('[data-announcer="inertia"]')!.textContent!,
          ),
        undefined,
        { timeout: 8000 },
      );
      await sleep(1500);
      const later = numberIn(await readout(page, 'speed', '#inertia'));
      assert.ok(
        Math.abs(later - first) <= 0.02 * first,
        `speed kept through wall bounces: ${first} then ${later} m/s`,
      );

      // Wood slows it down; back on ice it glides at its new speed.
      await page.locator('[data-surface="wood"]').click();
      await sleep(600);
      const slowed = numberIn(await readout(page, 'speed', '#inertia'));
      assert.ok(slowed < later - 0.1, `wood's friction slows it: ${later} -> ${slowed}`);

      // Bounciness 0, force up: it ends pressed on the top wall and reads as at rest.
      await page.locator('#inertia [data-action="reset"]').click();
      await bounciness.focus();
      await page.keyboard.press('Home');
      assert.equal(await bounciness.getAttribute('aria-valuenow'), '0');
      await setForce(page, ['Home', 'PageUp', 'PageUp']);
      await page.locator('#inertia [data-action="toggle-force"]').click();
      await page.waitForFunction(
        () => document.querySelector('#inertia [data-readout="direction"]')!.textContent === '90°',
        undefined,
        { timeout: 4000, polling: 50 },
      );
      await page.waitForFunction(
        () =>
          document.querySelector('#inertia [data-readout="direction"]')!.textContent === '–' &&
          document
            .querySelector('#inertia [data-readout="speed"]')!
            .textContent!.startsWith('0.000'),
        undefined,
        { timeout: 8000, polling: 100 },
      );
      await sleep(400);
      assert.equal(await readout(page, 'speed', '#inertia'), '0.000 m/s');
      assert.equal(await readout(page, 'direction', '#inertia'), '–');
      assert.equal(await readout(page, 'force', '#inertia'), '5 N, 90°');
      // The 2 m force arrow points up out of the box: it is clipped at the wall.
      const outside = await paintedAboveTopWall(page);
      assert.ok(outside >= 0 && outside < 50, `pixels drawn above the top wall: ${outside}`);
      await screenshot(page, `inertia-pinned-${orientation}`);
      assertQuiet(app);
    } finally {
      await closeApp(app);
    }
  });
}
