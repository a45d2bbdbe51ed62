import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import type { Page } from 'playwright-core';
import {
  assertQuiet,
  closeApp,
  numberIn,
  openApp,
  paintedPixels,
  readout,
  screenshot,
} from './phone.ts';

const sleep = (ms: number): Promise<void> => new Promise((resolve) => setTimeout(resolve, ms));

test('newton: each screen renders a non-blank canvas on a phone', async ({ browser }) => {
  const app = await openApp(browser);
  try {
    for (const screen of ['inertia', 'forces', 'reactions']) {
      await app.page.locator(`[data-nav="${screen}"]`).click();
      await app.page.waitForSelector(`#${screen} physical-canvas`, { state: 'visible' });
      await sleep(300);
      const canvases = await app.page.locator(`#${screen} physical-canvas`).count();
      for (let i = 0; i < canvases; i++) {
        const painted = await paintedPixels(
          app.page,
          `#${screen} physical-canvas:nth-of-type(1), #${screen} physical-canvas`,
        );
        assert.ok(painted > 1000, `${screen} canvas ${i} is blank (${painted} painted pixels)`);
      }
      // On this 3x phone the canvases draw at 2 device pixels per CSS px (4 per CSS px squared,
      // not 9): the frame rate of a busy Reactions screen depends on it.
      const ratios = await app.page.evaluate(
        (id) =>
          [...document.querySelectorAll(`#${id} physical-canvas`)].map((host) => {
            const backing = host.shadowRoot!.querySelector('canvas')!;
            return backing.width / backing.clientWidth;
          }),
        screen,
      );
      assert.equal(await app.page.evaluate(() => window.devicePixelRatio), 3);
      for (const ratio of ratios) assert.ok(Math.abs(ratio - 2) < 0.02, `${screen}: ${ratio}x`);
      await screenshot(app.page, screen);
    }
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: inertia, a force to the right moves the body right; stopped, it glides at constant speed', async ({
  browser,
}) => {
  const app = await openApp(browser, '#inertia');
  const { page } = app;
  try {
    await page.locator('#inertia [data-action="change-force"]').click();
    const dial = page.getByTestId('angle-dial');
    await dial.focus();
    await page.keyboard.press('ArrowUp');
    await page.keyboard.press('Home');
    assert.match(await readout(page, 'dialog-angle'), /^0° \(right\)$/);
    await screenshot(page, 'inertia-force-dialog');
    await page.getByRole('button', { name: 'OK' }).click();
    await page.getByRole('dialog').waitFor({ state: 'detached' });

    assert.equal(numberIn(await readout(page, 'speed', '#inertia')), 0, 'at rest before the force');
    await page.locator('#inertia [data-action="toggle-force"]').click();
    await sleep(700);
    const accelerated = numberIn(await readout(page, 'speed', '#inertia'));
    assert.ok(accelerated > 0.1, `the force sets it moving (speed ${accelerated})`);
    assert.equal(await readout(page, 'direction', '#inertia'), '0°', 'it moves to the right');
    await page.locator('#inertia [data-action="toggle-force"]').click();
    await sleep(250);
    const first = numberIn(await readout(page, 'speed', '#inertia'));
    await sleep(800);
    const second = numberIn(await readout(page, 'speed', '#inertia'));
    assert.ok(first > 0.1, `still moving after the force stopped (${first})`);
    assert.ok(
      Math.abs(second - first) <= 0.01 * first,
      `constant speed without a force: ${first} then ${second}`,
    );
    assert.equal(await readout(page, 'direction', '#inertia'), '0°');
    await screenshot(page, 'inertia-gliding');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

async function setSquare(
  app: Awaited<ReturnType<typeof openApp>>,
  open: () => Promise<void>,
  mass: string,
  force: string,
): Promise<void> {
  const { page } = app;
  await open();
  const dialog = page.getByRole('dialog');
  await dialog.waitFor();
  await page.locator('#square-mass').fill(mass);
  await page.locator('#square-force').fill(force);
  await page.getByRole('button', { name: 'OK' }).click();
  await dialog.waitFor({ state: 'detached' });
}

test('newton: forces, twice the force on twice the mass: both squares move together', async ({
  browser,
}) => {
  const app = await openApp(browser, '#forces');
  const { page } = app;
  try {
    await page.locator('#forces [data-action="play"]').click(); // pause
    // Tapping the first track opens its dialog.
    const box = (await page.locator('#forces physical-canvas').first().boundingBox())!;
    await setSquare(
      app,
      () => page.touchscreen.tap(box.x + box.width * 0.6, box.y + box.height * 0.6),
      '1',
      '2',
    );
    await setSquare(app, () => page.locator('[data-action="edit-B"]').click(), '2', '4');
    assert.equal(await readout(page, 'force-A'), '2 N');
    assert.equal(await readout(page, 'force-B'), '4 N');

    await page.locator('#forces [data-action="start"]').click();
    const step = page.locator('#forces [data-action="step"]');
    for (let i = 0; i < 60; i++) await step.click();
    await sleep(200);
    assert.equal(await readout(page, 'time', '#forces'), 't = 1.00 s');
    const xA = numberIn(await readout(page, 'x-A'));
    const xB = numberIn(await readout(page, 'x-B'));
    assert.ok(xA > 0.9 && xA < 1.1, `x = a t^2 / 2 = 1 m after 1 s (got ${xA})`);
    assert.ok(Math.abs(xA - xB) <= 0.001, `same x within 1 mm: ${xA} and ${xB}`);
    await page.locator('#forces [data-action="play"]').click(); // run on
    await sleep(1200);
    await screenshot(page, 'forces-running');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: reactions, taps spawn particles, tilt pushes them, collisions show two arrows', async ({
  browser,
}) => {
  const app = await openApp(browser, '#reactions');
  const { page } = app;
  try {
    const canvas = page.locator('#reactions physical-canvas');
    await sleep(200);
    const box = (await canvas.boundingBox())!;
    const tap = { x: box.x + box.width * 0.5, y: box.y + box.height * 0.5 };
    await page.touchscreen.tap(tap.x, tap.y);
    await sleep(150);
    assert.equal(await readout(page, 'count'), '1');
    const tapped = await canvas.evaluate(
      (element, point) =>
        (
          element as unknown as { clientToWorld(x: number, y: number): { x: number; y: number } }
        ).clientToWorld(point.x, point.y),
      tap,
    );
    // Tapping the particle selects it and shows its mass, speed, last impulse and position.
    await page.touchscreen.tap(tap.x, tap.y);
    await page.waitForSelector('[data-readout="particle-position"]');
    const [x0, y0] = (await readout(page, 'particle-position')).split(',').map(numberIn) as [
      number,
      number,
    ];
    assert.ok(
      Math.hypot(x0 - tapped.x, y0 - tapped.y) < 0.05,
      `spawned at the tap: ${x0}, ${y0} vs ${tapped.x}, ${tapped.y}`,
    );
    assert.match(await readout(page, 'particle-mass'), /kg$/);
    assert.equal(await readout(page, 'particle-impulse'), 'none yet');

    // Lean the phone to the right: the tray's gravity g sin 45° pulls every particle right.
    await page.evaluate(() =>
      window.dispatchEvent(
        new DeviceOrientationEvent('deviceorientation', { alpha: 0, beta: 0, gamma: 45 }),
      ),
    );
    await sleep(500);
    assert.equal(await readout(page, 'push'), '6.94 m/s², 0°');
    const [x1, y1] = (await readout(page, 'particle-position')).split(',').map(numberIn) as [
      number,
      number,
    ];
    assert.ok(x1 > x0 + 0.02, `moved right: ${x0} -> ${x1}`);
    assert.ok(Math.abs(y1 - y0) < 0.02, `not up or down: ${y0} -> ${y1}`);

    // It reaches the right wall: the collision draws two equal and opposite arrows.
    await waitForCollisionArrows(page);
    await page.waitForFunction(
      () =>
        document
          .querySelector('[data-readout="particle-impulse"]')
          ?.textContent?.endsWith('N·s') === true,
      undefined,
      { timeout: 2000 },
    );
    // More particles for the picture.
    for (const [fx, fy] of [
      [0.3, 0.2],
      [0.7, 0.45],
      [0.25, 0.8],
      [0.8, 0.85],
    ] as const) {
      await page.touchscreen.tap(box.x + box.width * fx, box.y + box.height * fy);
    }
    await sleep(1500);
    await screenshot(page, 'reactions-collisions');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

/** Pixels unlike the background below the box's bottom wall (-1 when no canvas shows there). */
/** Waits until Reactions draws a collision's two equal and opposite arrows. */
async function waitForCollisionArrows(page: Page): Promise<void> {
  await page.waitForFunction(
    () =>
      Number(document.querySelector<HTMLElement>('#reactions [data-arrows]')!.dataset['arrows']) >=
      2,
    undefined,
    { timeout: 8000 },
  );
}

async function paintedBelowBottomWall(page: Page): Promise<number> {
  return page.evaluate(() => {
    const host = document.querySelector('#reactions physical-canvas') as HTMLElement & {
      world: { bodies: { type: string; shapes: { geometry: { y1?: number; y2?: number } }[] }[] };
      worldToScreen(point: { x: number; y: number }): { x: number; y: number };
    };
    let bottom = -Infinity;
    for (const body of host.world.bodies) {
      if (body.type !== 'static') continue;
      for (const shape of body.shapes) {
        bottom = Math.max(bottom, shape.geometry.y1 ?? -Infinity, shape.geometry.y2 ?? -Infinity);
      }
    }
    const source = host.shadowRoot!.querySelector('canvas')!;
    const ratio = source.width / source.clientWidth;
    const wallY = host.worldToScreen({ x: 0, y: bottom }).y;
    const top = Math.ceil((wallY + 3) * ratio);
    if (top >= source.height) return -1;
    const copy = document.createElement('canvas');
    copy.width = source.width;
    copy.height = source.height;
    const context = copy.getContext('2d', { willReadFrequently: true })!;
    context.drawImage(source, 0, 0);
    const { data } = context.getImageData(0, top, copy.width, copy.height - top);
    const [r0, g0, b0] = [data[0]!, data[1]!, data[2]!];
    let count = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (Math.abs(data[i]! - r0) + Math.abs(data[i + 1]! - g0) + Math.abs(data[i + 2]! - b0) > 30)
        count++;
    }
    return count;
  });
}

test('newton: reactions, collision arrows at a wall stay inside the box', async ({ browser }) => {
  const app = await openApp(browser, '#reactions');
  const { page } = app;
  try {
    const canvas = page.locator('#reactions physical-canvas');
    await sleep(200);
    const box = (await canvas.boundingBox())!;
    for (const fx of [0.3, 0.5, 0.7]) {
      await page.touchscreen.tap(box.x + box.width * fx, box.y + box.height * 0.75);
    }
    // Lean the top edge up: the particles fall onto the bottom wall, whose reaction arrows
    // point down, out of the box.
    await page.evaluate(() =>
      window.dispatchEvent(
        new DeviceOrientationEvent('deviceorientation', { alpha: 0, beta: 60, gamma: 0 }),
      ),
    );
    await waitForCollisionArrows(page);
    const outside = await paintedBelowBottomWall(page);
    assert.ok(outside >= 0 && outside < 50, `pixels drawn below the bottom wall: ${outside}`);
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});
