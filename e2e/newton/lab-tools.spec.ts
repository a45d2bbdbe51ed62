import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import { SMALL_PHONE, assertClosedForm, openTab, results, runUntilCollided } from './lab.ts';
import { assertQuiet, closeApp, numberIn, openApp, readout, screenshot } from './phone.ts';

const ELASTIC = '#reactions?mA=1&mB=2&vA=1.5&vB=-0.5&e=1&walls=0&tilt=0';

/** The simulated time the controls show (s). */
async function shownTime(page: Page): Promise<number> {
  return numberIn(await readout(page, 'time'));
}

test('newton: lab tools at 375x667, step back and scrub to the start, and the same collision plays again', async ({
  browser,
}) => {
  const app = await openApp(browser, ELASTIC, SMALL_PHONE);
  const { page } = app;
  try {
    await runUntilCollided(page);
    const first = await results(page);
    assertClosedForm(first, 1, 2, 1.5, -0.5, 1);
    await openTab(page, 'data');
    const t0 = await shownTime(page);
    await page.locator('#reactions [data-action="step-back"]').click();
    const t1 = await shownTime(page);
    assert.ok(t0 - t1 > 0.005 && t0 - t1 < 0.03, `one step back: ${t0} -> ${t1}`);
    // Scrub to the oldest saved moment: the start, before the collision.
    const thumb = page.locator('#reactions [data-control="rewind"] input');
    await thumb.focus();
    await page.keyboard.press('Home');
    assert.equal(await shownTime(page), 0);
    await openTab(page, 'results');
    await page.locator('#reactions [data-lab="waiting"]').waitFor();
    // Play on from there: the same collision, the same numbers.
    await runUntilCollided(page);
    assert.deepEqual(await results(page), first);
    await openTab(page, 'data');
    await screenshot(page, 'lab-data-375x667');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: lab tools, the measurements download and copy as CSV: t, and each particle x, v, p and KE', async ({
  browser,
}) => {
  const app = await openApp(browser, ELASTIC, SMALL_PHONE);
  const { page, context } = app;
  try {
    await context.grantPermissions(['clipboard-read', 'clipboard-write']);
    await runUntilCollided(page);
    // Step back a few steps and play on: the CSV holds one history, no repeated times.
    await openTab(page, 'data');
    for (let i = 0; i < 5; i++) await page.locator('#reactions [data-action="step-back"]').click();
    await page.locator('#reactions [data-action="play"]').click();
    await new Promise((resolve) => setTimeout(resolve, 300));
    await page.locator('#reactions [data-action="play"]').click();
    const [download] = await Promise.all([
      page.waitForEvent('download'),
      page.locator('#reactions [data-action="download-csv"]').click(),
    ]);
    assert.equal(download.suggestedFilename(), 'newton-reactions.csv');
    const csv = readFileSync((await download.path())!, 'utf8');
    const [header, ...lines] = csv.trim().split('\r\n');
    const columns = header!.split(',');
    for (const name of ['t (s)', 'A x (m)', 'A vx (m/s)', 'A px (kg m/s)', 'B KE (J)']) {
      assert.ok(columns.includes(name), `column ${name} in ${header}`);
    }
    const rows = lines.map((line) => line.split(',').map(Number));
    assert.ok(rows.length > 30, `${rows.length} rows`);
    const at = (name: string) => columns.indexOf(name);
    let previous = -Infinity;
    for (const row of rows) {
      assert.ok(row[0]! > previous, `times increase: ${previous} then ${row[0]}`);
      previous = row[0]!;
      // p = m v and KE = m v^2 / 2 with A's 1 kg and B's 2 kg, in every row.
      assert.ok(Math.abs(row[at('A px (kg m/s)')]! - row[at('A vx (m/s)')]!) < 1e-6);
      assert.ok(Math.abs(row[at('B px (kg m/s)')]! - 2 * row[at('B vx (m/s)')]!) < 1e-6);
      const keB = row[at('B vx (m/s)')]! ** 2 + row[at('B vy (m/s)')]! ** 2;
      assert.ok(Math.abs(row[at('B KE (J)')]! - keB) < 1e-6);
      // Momentum is kept through the collision, row by row.
      const total = row[at('A px (kg m/s)')]! + row[at('B px (kg m/s)')]!;
      assert.ok(Math.abs(total - 0.5) < 1e-6, `total momentum ${total} at t = ${row[0]}`);
    }
    // The last row is the time on screen.
    assert.ok(Math.abs(previous - numberIn(await readout(page, 'time'))) < 0.006);
    assert.match(await readout(page, 'csv-status'), /Downloaded \d+ rows/);
    // Copy gives the same text.
    await page.locator('#reactions [data-action="copy-csv"]').click();
    await page.waitForFunction(() =>
      /Copied/.test(document.querySelector('[data-readout="csv-status"]')?.textContent ?? ''),
    );
    const copied = await page.evaluate(() => navigator.clipboard.readText());
    assert.equal(copied, csv);
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: Reset all on Reactions brings back every default', async ({ browser }) => {
  const app = await openApp(
    browser,
    '#reactions?mA=3&vA=1&e=0&walls=0&tilt=0&arrows=force',
    SMALL_PHONE,
  );
  const { page } = app;
  try {
    await openTab(page, 'options');
    assert.equal(await page.locator('#reactions [data-control="walls"]').isChecked(), false);
    await page.locator('#reactions [data-action="reset-all"]').click();
    await page.locator('#reactions [data-tab="tray"][aria-selected="true"]').waitFor();
    assert.equal(await readout(page, 'count'), '0');
    await openTab(page, 'options');
    assert.equal(await page.locator('#reactions [data-control="walls"]').isChecked(), true);
    assert.equal(await page.locator('#reactions [data-control="tilt"]').isChecked(), true);
    assert.match((await page.locator('#reactions-elasticity-label').textContent())!, /80 %/);
    assert.equal(
      await page
        .locator('#reactions [data-control="measure-impulse"]')
        .getAttribute('aria-pressed'),
      'true',
    );
    assert.match(
      (await page.locator('[data-legend="arrows"]').textContent())!,
      /impulse J \(N·s\)/,
    );
    await openTab(page, 'setup');
    await page.locator('#reactions [data-lab-input]').first().waitFor({ state: 'detached' });
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});
