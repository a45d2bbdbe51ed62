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

/** How much brighter the grid line at x = 1 m is than the floor half a metre to its right. */
async function gridContrast(page: Page): Promise<number> {
  return page.evaluate(() => {
    const host = document.querySelector('#inertia physical-canvas') as HTMLElement & {
      worldToScreen(point: { x: number; y: number }): { x: number; y: number };
    };
    const source = host.shadowRoot!.querySelector('canvas')!;
    const ratio = source.width / source.clientWidth;
    // A copy to read from: reading the element's own context would warn about readbacks.
    const copy = document.createElement('canvas');
    copy.width = source.width;
    copy.height = source.height;
    const context = copy.getContext('2d', { willReadFrequently: true })!;
    context.drawImage(source, 0, 0);
    const brightness = (x: number, y: number): number => {
      const { data } = context.getImageData(Math.round(x * ratio) - 3, Math.round(y * ratio), 7, 1);
      let best = 0;
      for (let i = 0; i < data.length; i += 4)
        best = Math.max(best, data[i]! + data[i + 1]! + data[i + 2]!);
      return best;
    };
    const line = host.worldToScreen({ x: 1, y: 0.5 });
    const floor = host.worldToScreen({ x: 1.5, y: 0.5 });
    return brightness(line.x, line.y) - brightness(floor.x, floor.y);
  });
}

/** The Inertia canvas' described state. */
async function described(page: Page): Promise<string> {
  return (await page.locator('#inertia physical-canvas').getAttribute('aria-label')) ?? '';
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
      // Waited for by the readout, not by the clock: on a loaded machine 600 ms of wall time
      // held too few frames for the speed to fall by 0.1 m/s.
      await page.locator('[data-surface="wood"]').click();
      const slowedBy = await page
        .waitForFunction(
          (bound) => {
            const text = document.querySelector('#inertia [data-readout="speed"]')?.textContent;
            const speed = Number(/-?\d+(?:\.\d+)?/.exec(text ?? '')?.[0]);
            return speed < bound;
          },
          later - 0.1,
          { timeout: 10_000 },
        )
        .then(
          () => true,
          () => false,
        );
      const slowed = numberIn(await readout(page, 'speed', '#inertia'));
      assert.ok(
        slowedBy && slowed < later - 0.1,
        `wood's friction slows it: ${later} -> ${slowed}`,
      );

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
      // The wall pushes back as hard: the forces on the pinned body sum to zero, and it says so.
      assert.match(
        (await page.locator('#inertia physical-canvas').getAttribute('aria-label')) ?? '',
        /ΣF = 0 N/,
      );
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

for (const [orientation, options] of [
  ['portrait', PHONE],
  ['landscape', LANDSCAPE],
] as const) {
  test(`newton: inertia (${orientation}), a 1 m grid, every force drawn and described with its sum, Return brings the body back to rest`, async ({
    browser,
  }) => {
    const app = await openApp(browser, '#inertia', options);
    const { page } = app;
    try {
      // A reference grid a metre apart, and at rest the forces sum to zero.
      const contrast = await gridContrast(page);
      assert.ok(contrast > 20, `grid line brighter than the floor by ${contrast}`);
      assert.match(await described(page), /ΣF = 0 N/);

      // On wood, pushed right at 5 N: friction 0.05 x 1 kg x 9.81 = 0.49 N against the motion,
      // and the sum 4.51 N, drawn and said.
      await page.locator('[data-surface="wood"]').click();
      await setForce(page, ['Home']);
      await page.locator('#inertia [data-action="toggle-force"]').click();
      await page.waitForFunction(
        () =>
          /ΣF is 4\.51\sN at 0° \(friction 0\.49\sN/.test(
            document.querySelector('#inertia physical-canvas')!.getAttribute('aria-label')!,
          ),
        undefined,
        { timeout: 4000, polling: 50 },
      );
      await screenshot(page, `inertia-forces-${orientation}`);

      // Force off: friction alone acts, so the sum is the friction, pointing back.
      await page.locator('#inertia [data-action="toggle-force"]').click();
      await page.waitForFunction(
        () =>
          /ΣF is 0\.49\sN at 180°/.test(
            document.querySelector('#inertia physical-canvas')!.getAttribute('aria-label')!,
          ),
        undefined,
        { timeout: 4000, polling: 50 },
      );

      // Return: the body is back in the centre, at rest, and that is announced.
      await page.locator('#inertia [data-action="return"]').click();
      await page.waitForFunction(
        () =>
          document
            .querySelector('#inertia [data-readout="speed"]')!
            .textContent!.startsWith('0.000'),
        undefined,
        { timeout: 4000, polling: 50 },
      );
      const offset = await page.evaluate(() => {
        const host = document.querySelector('#inertia physical-canvas') as HTMLElement & {
          world: { bodies: readonly { type: string; position: { x: number; y: number } }[] };
          viewBox: { x: number; y: number; width: number; height: number };
        };
        const body = host.world.bodies.find((item) => item.type === 'dynamic')!;
        const box = host.viewBox;
        return Math.hypot(
          body.position.x - (box.x + box.width / 2),
          body.position.y - (box.y + box.height / 2),
        );
      });
      assert.ok(offset < 1e-9, `back in the centre (${offset} m off)`);
      await page.waitForFunction(
        () =>
          /back in the centre/.test(
            document.querySelector('[data-announcer="inertia"]')!.textContent!,
          ),
        undefined,
        { timeout: 4000 },
      );
      assert.match(await described(page), /at rest/);
      assertQuiet(app);
    } finally {
      await closeApp(app);
    }
  });
}
