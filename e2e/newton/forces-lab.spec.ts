import assert from 'node:assert/strict';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import { phoneOptions } from './fit.ts';
import { assertQuiet, closeApp, numberIn, openApp, readout, screenshot } from './phone.ts';

/** Sets a square's mass and force in its dialog, as a student types them. */
async function setSquare(page: Page, name: string, mass: string, force: string): Promise<void> {
  await page.locator(`[data-action="edit-${name}"]`).tap();
  const dialog = page.getByRole('dialog');
  await dialog.waitFor();
  // The cause is the input: a mass and a force; no "desired acceleration" to type.
  assert.doesNotMatch((await dialog.textContent()) ?? '', /acceleration/i);
  await page.locator('#square-mass').fill(mass);
  await page.locator('#square-force').fill(force);
  await dialog.getByRole('button', { name: 'OK' }).tap();
  await dialog.waitFor({ state: 'detached' });
}

test('newton: forces lab (375x667), a student applies F to m and reads a = F / m to 1e-3 from the first readout, with a(t) and F(t) graphed', async ({
  browser,
}) => {
  const app = await openApp(browser, '#forces', phoneOptions(375, 667, false));
  const { page } = app;
  try {
    // 2 N on 1.5 kg: a = 1.333 m/s^2; B keeps 2 N on 2 kg: a = 1 m/s^2.
    await setSquare(page, 'A', '1.5', '2');
    assert.equal(await readout(page, 'force-A'), '2 N');
    assert.equal(await readout(page, 'a-A'), '–', 'no acceleration before the force acts');
    // Paused, Start, then one step at a time: the readout after the very first step (1/60 s).
    await page.locator('#forces [data-action="play"]').tap();
    await page.locator('#forces [data-action="start"]').tap();
    const seen: { t: number; a: number; b: number }[] = [];
    const read = async (): Promise<void> => {
      const [time, a, b] = await Promise.all([
        readout(page, 'time', '#forces'),
        readout(page, 'a-A'),
        readout(page, 'a-B'),
      ]);
      seen.push({ t: numberIn(time), a: numberIn(a), b: numberIn(b) });
    };
    for (let step = 0; step < 5; step++) {
      await page.locator('#forces [data-action="step"]').tap();
      await read();
    }
    assert.deepEqual(
      seen.map(({ t }) => t),
      [0.02, 0.03, 0.05, 0.07, 0.08],
      'one step of 1/60 s each',
    );
    // Then running, at whatever moments the readout is read.
    await page.locator('#forces [data-action="play"]').tap();
    for (let sample = 0; sample < 5; sample++) {
      await page.waitForTimeout(150);
      await read();
    }
    for (const { t, a, b } of seen) {
      assert.ok(Math.abs(a - 2 / 1.5) <= 1e-3, `A at t = ${t} s: a = ${a}, F / m = 1.333`);
      assert.ok(Math.abs(b - 2 / 2) <= 1e-3, `B at t = ${t} s: a = ${b}, F / m = 1`);
    }
    // Graphs of x, v, a and F against time, side by side.
    const titles = await page.locator('#forces [data-graphs] figcaption').allTextContents();
    assert.equal(titles.length, 4);
    for (const title of ['Position', 'Velocity', 'Acceleration', 'Force']) {
      assert.ok(
        titles.some((text) => text.startsWith(title)),
        `a graph of ${title}: ${titles.join(' | ')}`,
      );
    }
    const summary = async (title: string): Promise<string> =>
      (
        (await page
          .locator(`#forces [data-graphs] canvas[aria-label^="${title}"]`)
          .getAttribute('aria-label')) ?? ''
      ).replace(/\u00a0/g, ' ');
    await page.waitForTimeout(300);
    assert.match(await summary('Acceleration'), /A: 1\.33 m\/s², B: 1 m\/s²/);
    assert.match(await summary('Force'), /A: 2 N, B: 2 N/);
    await screenshot(page, 'forces-lab-running');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: forces lab (375x667), a track opens its editor on Enter and on Space', async ({
  browser,
}) => {
  const app = await openApp(browser, '#forces', phoneOptions(375, 667, false));
  const { page } = app;
  try {
    for (const key of ['Enter', ' ']) {
      await page.locator('#forces [data-track="A"] physical-canvas').focus();
      await page.keyboard.press(key);
      const dialog = page.getByRole('dialog');
      await dialog.waitFor({ timeout: 2000 });
      assert.match((await dialog.textContent()) ?? '', /Square A/);
      await page.keyboard.press('Escape');
      await dialog.waitFor({ state: 'detached' });
    }
    // Space opened the editor and did not pause the track instead.
    assert.equal(
      await page.locator('#forces [data-action="play"]').getAttribute('aria-label'),
      'Pause',
    );
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});
