import assert from 'node:assert/strict';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import { phoneOptions } from './fit.ts';
import { assertQuiet, closeApp, numberIn, openApp, readout, screenshot } from './phone.ts';
import {
  assertOneHistory,
  downloadCsv,
  readouts,
  rowAt,
  scrubTo,
  timeOf,
  type Csv,
} from './rewind.ts';

const sleep = (ms: number): Promise<void> => new Promise((resolve) => setTimeout(resolve, ms));

/** Readouts seen while running, at least 0.1 s of simulated time apart, until `count`. */
async function watch(
  page: Page,
  screen: string,
  names: readonly string[],
  count: number,
): Promise<Record<string, string>[]> {
  const seen: Record<string, string>[] = [];
  for (let i = 0; i < 100 && seen.length < count; i++) {
    await sleep(120);
    const shown = await readouts(page, screen, names);
    const last = seen[seen.length - 1];
    if (timeOf(shown) >= (last === undefined ? 0.1 : timeOf(last) + 0.1)) seen.push(shown);
  }
  assert.equal(seen.length, count, `${count} moments seen while running`);
  return seen;
}

/** Step back once from the paused end: the clock goes back one step of 1/60 s. */
async function stepBack(page: Page, screen: string, names: readonly string[]) {
  const end = await readouts(page, screen, names);
  await page.locator(`#${screen} [data-action="step-back"]`).tap();
  await page.waitForFunction(
    ([scope, shown]) =>
      document
        .querySelector(`#${scope} [data-readout="time"]`)
        ?.textContent?.replace(/\u00a0/g, ' ') !== shown,
    [screen, end['time']!] as const,
    { timeout: 5000 },
  );
  const back = await readouts(page, screen, names);
  const dt = timeOf(end) - timeOf(back);
  assert.ok(dt > 0.005 && dt < 0.03, `one step back: ${timeOf(end)} s -> ${timeOf(back)} s`);
  return { end, back };
}

/** Play for a while, then pause: the simulation goes on from where it was scrubbed to. */
async function playOn(page: Page, screen: string, ms: number): Promise<void> {
  await page.locator(`#${screen} [data-action="play"]`).tap();
  await sleep(ms);
  await page.locator(`#${screen} [data-action="play"]`).tap();
}

/** Copy gives the text Download gave, and the status line says how many rows went. */
async function assertCopied(page: Page, screen: string, csv: Csv): Promise<void> {
  await page.locator(`#${screen} [data-action="copy-csv"]`).tap();
  await page.waitForFunction(
    (scope) =>
      /Copied \d+ rows/.test(
        document.querySelector(`#${scope} [data-readout="csv-status"]`)?.textContent ?? '',
      ),
    screen,
  );
  assert.equal(await page.evaluate(() => navigator.clipboard.readText()), csv.text);
  assert.match(await readout(page, 'csv-status', `#${screen}`), new RegExp(`${csv.rows.length}`));
}

const INERTIA = ['time', 'x', 'y', 'speed', 'direction'] as const;

test('newton: inertia rewind (375x667), a student applies 1 N, steps back, scrubs to moments seen while running (same t, x, y, speed), plays on, and exports t, x, v, a, p, KE as CSV', async ({
  browser,
}) => {
  const app = await openApp(browser, '#inertia', phoneOptions(375, 667, false));
  const { page, context } = app;
  try {
    await context.grantPermissions(['clipboard-read', 'clipboard-write']);
    // 1 N to the right on 1 kg: the body reaches the right wall (2.5 m away) after 2.2 s.
    await page.locator('#inertia [data-action="toggle-force"]').tap();
    const seen = await watch(page, 'inertia', INERTIA, 4);
    await page.locator('#inertia [data-action="play"]').tap();
    const { end, back } = await stepBack(page, 'inertia', INERTIA);
    assert.ok(timeOf(end) < 2.2, `paused before the wall (${end['time']})`);
    assert.ok(numberIn(back['x']!) <= numberIn(end['x']!), 'a step back moves the body back');

    // Scrubbed to each moment seen while running: the readouts show exactly what they showed.
    for (const moment of seen) {
      await scrubTo(page, 'inertia', Math.round(timeOf(moment) * 60));
      assert.deepEqual(await readouts(page, 'inertia', INERTIA), moment);
    }
    assert.equal(
      await page.locator('#inertia [data-action="toggle-force"]').getAttribute('aria-pressed'),
      'true',
      'the force that acted then is on',
    );

    // Running again goes on from the last of them, and the CSV holds that one history.
    await playOn(page, 'inertia', 400);
    const now = await readouts(page, 'inertia', INERTIA);
    assert.ok(timeOf(now) > timeOf(seen[seen.length - 1]!), 'time went on from there');
    const csv = await downloadCsv(page, 'inertia');
    for (const name of ['t (s)', 'x (m)', 'y (m)', 'vx (m/s)', 'vy (m/s)', 'ax (m/s^2)']) {
      assert.ok(csv.columns.includes(name), `column ${name} in ${csv.columns.join(',')}`);
    }
    for (const name of ['ay (m/s^2)', 'px (kg m/s)', 'py (kg m/s)', 'KE (J)']) {
      assert.ok(csv.columns.includes(name), `column ${name} in ${csv.columns.join(',')}`);
    }
    assertOneHistory(csv, timeOf(now));
    // The row of the time on screen says what the readouts say.
    const row = rowAt(csv, timeOf(now));
    assert.ok(Math.abs(csv.at(row, 'x (m)') - numberIn(now['x']!)) <= 0.005, 'x as shown');
    assert.ok(Math.abs(csv.at(row, 'y (m)') - numberIn(now['y']!)) <= 0.005, 'y as shown');
    const speed = Math.hypot(csv.at(row, 'vx (m/s)'), csv.at(row, 'vy (m/s)'));
    assert.ok(Math.abs(speed - numberIn(now['speed']!)) <= 0.0005, 'speed as shown');
    // F = m a: 1 N on 1 kg gives 1 m/s^2 in every step it acted; p = m v, KE = m v^2 / 2.
    for (const item of csv.rows.slice(1)) {
      const vx = csv.at(item, 'vx (m/s)');
      if (vx > 0) assert.ok(Math.abs(csv.at(item, 'ax (m/s^2)') - 1) < 1e-6, `a at ${item[0]}`);
      assert.ok(Math.abs(csv.at(item, 'ay (m/s^2)')) < 1e-6);
      assert.ok(Math.abs(csv.at(item, 'px (kg m/s)') - vx) < 1e-6);
      assert.ok(Math.abs(csv.at(item, 'KE (J)') - (vx * vx) / 2) < 1e-6);
    }
    await assertCopied(page, 'inertia', csv);
    await page.locator('#inertia [data-lab="data"]').scrollIntoViewIfNeeded();
    await screenshot(page, 'inertia-data-375x667');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

const FORCES = ['time', 'x-A', 'x-B', 'motion-A', 'motion-B'] as const;

test('newton: forces rewind (375x667), a student starts, steps back, scrubs to moments seen while running (same t, x, v, a), exports the CSV, and a run stepped back before the stop finishes again alike', async ({
  browser,
}) => {
  const app = await openApp(browser, '#forces', phoneOptions(375, 667, false));
  const { page, context } = app;
  try {
    await context.grantPermissions(['clipboard-read', 'clipboard-write']);
    // 2 N on 1 kg (A) and on 2 kg (B): a = 2 and 1 m/s^2.
    await page.locator('#forces [data-action="start"]').tap();
    const seen = await watch(page, 'forces', FORCES, 4);
    await page.locator('#forces [data-action="play"]').tap();
    const { end, back } = await stepBack(page, 'forces', FORCES);
    assert.ok(numberIn(back['x-A']!) <= numberIn(end['x-A']!), 'a step back moves A back');

    for (const moment of seen) {
      await scrubTo(page, 'forces', Math.round(timeOf(moment) * 60));
      assert.deepEqual(await readouts(page, 'forces', FORCES), moment);
    }

    await playOn(page, 'forces', 400);
    const now = await readouts(page, 'forces', FORCES);
    assert.ok(timeOf(now) > timeOf(seen[seen.length - 1]!), 'time went on from there');
    const csv = await downloadCsv(page, 'forces');
    for (const square of ['A', 'B']) {
      for (const name of ['x (m)', 'v (m/s)', 'a (m/s^2)', 'F (N)', 'p (kg m/s)', 'KE (J)']) {
        const column = `${square} ${name}`;
        assert.ok(csv.columns.includes(column), `column ${column} in ${csv.columns.join(',')}`);
      }
    }
    assert.equal(csv.columns[0], 't (s)');
    assertOneHistory(csv, timeOf(now));
    const row = rowAt(csv, timeOf(now));
    for (const [square, mass, a] of [
      ['A', 1, 2],
      ['B', 2, 1],
    ] as const) {
      const shownX = numberIn(now[`x-${square}`]!);
      assert.ok(Math.abs(csv.at(row, `${square} x (m)`) - shownX) <= 0.005, `${square} x`);
      // "x = 1.23 m · v = 1.50 m/s · a = 2.000 m/s²": the velocity is the second number.
      const shownV = numberIn(now[`motion-${square}`]!.split('·')[1]!);
      assert.ok(Math.abs(csv.at(row, `${square} v (m/s)`) - shownV) <= 0.005, `${square} v`);
      for (const item of csv.rows.slice(1)) {
        const v = csv.at(item, `${square} v (m/s)`);
        assert.ok(Math.abs(csv.at(item, `${square} a (m/s^2)`) - a) < 1e-6, `a = F / m`);
        assert.equal(csv.at(item, `${square} F (N)`), 2);
        assert.ok(Math.abs(csv.at(item, `${square} p (kg m/s)`) - mass * v) < 1e-6);
        assert.ok(Math.abs(csv.at(item, `${square} KE (J)`) - (mass * v * v) / 2) < 1e-6);
      }
    }
    await assertCopied(page, 'forces', csv);

    // Run to the stops, then step back before them and run again: the same finish.
    const start = page.locator('#forces [data-action="start"]');
    await page.locator('#forces [data-action="play"]').tap();
    await page.waitForFunction(
      () => document.querySelector('#forces [data-action="start"]')?.textContent === 'Run over',
      undefined,
      { timeout: 30_000 },
    );
    // Where the squares stopped (the clock itself runs on until both canvases come to rest).
    const finish = await readouts(page, 'forces', FORCES.slice(1));
    await page.locator('#forces [data-action="play"]').tap();
    await scrubTo(page, 'forces', 60);
    assert.equal(await readout(page, 'time', '#forces'), 't = 1.00 s');
    assert.equal(await start.textContent(), 'Forces acting');
    await page.locator('#forces [data-action="play"]').tap();
    await page.waitForFunction(
      () => document.querySelector('#forces [data-action="start"]')?.textContent === 'Run over',
      undefined,
      { timeout: 30_000 },
    );
    assert.deepEqual(await readouts(page, 'forces', FORCES.slice(1)), finish);
    await page.locator('#forces [data-lab="data"]').scrollIntoViewIfNeeded();
    await screenshot(page, 'forces-data-375x667');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});
