import assert from 'node:assert/strict';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import { phoneOptions } from './fit.ts';
import { openTab } from './lab.ts';
import { assertQuiet, closeApp, numberIn, openApp, readout } from './phone.ts';
import { downloadCsv, scrubTo, type Csv } from './rewind.ts';

/** The collision lab's pair, paused at t = 0, tilt and walls on. */
const LAB = '#reactions?mA=1&mB=2&vA=1.5&vB=-0.5';

/** Steps `count` times with the Step button and waits for the clock to show `steps` steps. */
async function step(page: Page, count: number, steps: number): Promise<void> {
  for (let i = 0; i < count; i++) await page.locator('#reactions [data-action="step"]').tap();
  const shown = `t = ${(steps / 60).toFixed(2)} s`;
  await page.waitForFunction(
    (text) =>
      document
        .querySelector('#reactions [data-readout="time"]')
        ?.textContent?.replace(/\u00a0/g, ' ')
        .trim() === text,
    shown,
    { timeout: 5000 },
  );
}

test('newton: reactions rewind (375x667), changes made between steps (a particle added, the tray tilted, the walls switched off) are in the moment stepped back to: its particle count, and the step from it gives the very row recorded while running', async ({
  browser,
}) => {
  const app = await openApp(browser, LAB, phoneOptions(375, 667, false));
  const { page } = app;
  try {
    assert.equal(await readout(page, 'time', '#reactions'), 't = 0.00 s');
    await step(page, 5, 5);
    // After step 5: a third particle (C), by the tray's add button.
    await openTab(page, 'tray');
    await page.locator('#reactions [data-action="add"]').tap();
    await page.waitForFunction(() =>
      document.querySelector('#reactions [data-readout="count"]')?.textContent?.includes('3'),
    );
    await step(page, 2, 7);
    // After step 7: the tray tilted right and down (arrow keys), so gravity pulls along it.
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('ArrowDown');
    assert.ok(numberIn(await readout(page, 'push', '#reactions')) > 0, 'the tray is tilted');
    await step(page, 2, 9);
    // After step 9: the walls off.
    await openTab(page, 'options');
    await page.locator('#reactions [data-control="walls"]').click();
    await step(page, 4, 13);

    await openTab(page, 'data');
    const ran = await downloadCsv(page, 'reactions');
    const timeOfLast = (csv: Csv): number => csv.rows[csv.rows.length - 1]![0]!;
    assert.ok(Math.abs(timeOfLast(ran) - 13 / 60) < 1e-6, 'the last row is step 13');
    for (const name of ['C x (m)', 'C y (m)', 'C px (kg m/s)', 'C KE (J)']) {
      assert.ok(ran.columns.includes(name), `column ${name} in ${ran.columns.join(',')}`);
    }
    // Step 11 (after every change): all three particles are there, at the time stepped back to.
    await scrubTo(page, 'reactions', 11);
    assert.equal(await readout(page, 'time', '#reactions'), `t = ${(11 / 60).toFixed(2)} s`);
    await openTab(page, 'tray');
    assert.equal(await readout(page, 'count', '#reactions'), '3', 'particles at step 11');
    // One step on from it: exactly the row recorded while running (each particle's x, y, v, p
    // and KE to the CSV's 9 digits), so the restored world was the one that ran (C there, the
    // tilt's gravity, no walls); the rows before it are kept as they were, the old future gone.
    await openTab(page, 'data');
    await step(page, 1, 12);
    const again = await downloadCsv(page, 'reactions');
    assert.ok(Math.abs(timeOfLast(again) - 12 / 60) < 1e-6, 'the last row is step 12');
    assert.equal(again.rows.length, ran.rows.length - 1);
    const lines = (csv: Csv): string[] => csv.text.trim().split('\r\n');
    assert.deepEqual(lines(again), lines(ran).slice(0, lines(again).length));
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

// A phone in the hand sends a new lean with almost every frame. The tray takes it at the next
// step and the step's saved moment keeps it (no world snapshot for each, which cost a slow phone
// 5 ms a frame at 4x CPU): stepping back replays each step with the lean it had.
test('newton: reactions rewind (375x667), a lean that changes before every step (a phone in the hand) is replayed: the step from a moment stepped back to gives the very row recorded while running', async ({
  browser,
}) => {
  const app = await openApp(browser, LAB, phoneOptions(375, 667, false));
  const { page } = app;
  try {
    const lean = (i: number) =>
      page.evaluate(
        ([beta, gamma]) =>
          window.dispatchEvent(
            new DeviceOrientationEvent('deviceorientation', { alpha: 0, beta, gamma }),
          ),
        [8 + 3 * Math.sin(i), 20 + 4 * Math.cos(1.7 * i)],
      );
    for (let i = 1; i <= 14; i++) {
      await lean(i);
      await step(page, 1, i);
    }
    await openTab(page, 'data');
    const ran = await downloadCsv(page, 'reactions');
    assert.equal(ran.rows.length, 15, 'rows of t = 0 and 14 steps');
    // The leans pushed: B (at rest at first, 2 kg) moved down the tray.
    const column = (csv: Csv, name: string): number[] =>
      csv.rows.map((row) => row[csv.columns.indexOf(name)]!);
    const vy = column(ran, 'B vy (m/s)');
    assert.ok(vy[14]! > vy[1]! + 0.1, `B sped up along the lean: ${vy.join(', ')}`);
    // Back to step 6 (its world replayed from the snapshot at t = 0 with leans 1 to 6), then
    // step 7 again with the lean it had: exactly the row recorded while running.
    await scrubTo(page, 'reactions', 6);
    assert.equal(await readout(page, 'time', '#reactions'), `t = ${(6 / 60).toFixed(2)} s`);
    await lean(7);
    await step(page, 1, 7);
    const again = await downloadCsv(page, 'reactions');
    const lines = (csv: Csv): string[] => csv.text.trim().split('\r\n');
    assert.equal(again.rows.length, 8, 'rows up to step 7, the old future gone');
    assert.deepEqual(lines(again), lines(ran).slice(0, 9));
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});
