import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import {
  SMALL_PHONE,
  assertClosedForm,
  labValue,
  openTab,
  results,
  runUntilCollided,
} from './lab.ts';
import {
  assertQuiet,
  closeApp,
  numberIn,
  openApp,
  readout,
  screenshot,
  waitReady,
} from './phone.ts';

test('newton: a preset link opens Reactions in exactly that setup, and it runs as the closed form says', async ({
  browser,
}) => {
  const app = await openApp(
    browser,
    '#reactions?mA=0.5&mB=1.5&vA=2&vB=0&e=1&walls=0&tilt=0',
    SMALL_PHONE,
  );
  const { page } = app;
  try {
    // The Lab tab, paused at t = 0, with the link's values.
    await page.locator('#reactions [data-tab="setup"][aria-selected="true"]').waitFor();
    assert.equal(await readout(page, 'time'), 't = 0.00 s');
    assert.equal(await labValue(page, 'A-mass'), 0.5);
    assert.equal(await labValue(page, 'A-vx'), 2);
    assert.equal(await labValue(page, 'B-mass'), 1.5);
    assert.equal(await labValue(page, 'B-vx'), 0);
    await openTab(page, 'options');
    assert.equal(await page.locator('#reactions [data-control="walls"]').isChecked(), false);
    assert.equal(await page.locator('#reactions [data-control="tilt"]').isChecked(), false);
    assert.match((await page.locator('#reactions-elasticity-label').textContent())!, /100 %/);
    await runUntilCollided(page);
    assertClosedForm(await results(page), 0.5, 1.5, 2, 0, 1);
    // A second link followed in the open app sets it up again.
    await page.evaluate(() => {
      location.hash = '#reactions?mA=2&mB=2&vA=1&vB=-1&e=0&walls=0&tilt=0';
    });
    await page.waitForFunction(
      () =>
        (document.querySelector('[data-lab-input="A-mass"]') as HTMLInputElement | null)?.value ===
        '2',
    );
    assert.equal(await labValue(page, 'B-vx'), -1);
    await runUntilCollided(page);
    assertClosedForm(await results(page), 2, 2, 1, -1, 0);
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: preset links open Forces and Inertia in their setup', async ({ browser }) => {
  const forces = await openApp(browser, '#forces?mA=1&mB=2&F=3', SMALL_PHONE);
  try {
    const { page } = forces;
    assert.equal(numberIn(await readout(page, 'mass-A')), 1);
    assert.equal(numberIn(await readout(page, 'mass-B')), 2);
    assert.equal(numberIn(await readout(page, 'force-A')), 3);
    assert.equal(numberIn(await readout(page, 'force-B')), 3);
    assertQuiet(forces);
  } finally {
    await closeApp(forces);
  }
  const inertia = await openApp(browser, '#inertia?F=2&angle=90&surface=wood&e=0.5', SMALL_PHONE);
  try {
    const { page } = inertia;
    assert.equal(await page.locator('[data-surface="wood"]').getAttribute('aria-pressed'), 'true');
    assert.match((await page.locator('#inertia-elasticity-label').textContent())!, /50 %/);
    await page.locator('#inertia [data-action="toggle-force"]').focus();
    await page.keyboard.press('Enter');
    assert.equal(await readout(page, 'force'), '2 N, 90°');
    assertQuiet(inertia);
  } finally {
    await closeApp(inertia);
  }
});

test('newton: the teacher pages load offline in English and German, and print a worksheet with its answer key', async ({
  browser,
}) => {
  const app = await openApp(browser, '#inertia', SMALL_PHONE);
  const { page, context } = app;
  try {
    await page.evaluate(async () => {
      await navigator.serviceWorker.ready;
      if (navigator.serviceWorker.controller === null) {
        await new Promise((resolve) =>
          navigator.serviceWorker.addEventListener('controllerchange', resolve, { once: true }),
        );
      }
    });
    await context.setOffline(true);
    // From the app's hint, in German: the German page.
    await page.locator('[data-locale="de"]').click();
    await page.locator('[data-action="hint"]').first().click();
    await page.locator('[data-action="teacher"]').click();
    await page.waitForURL(/teacher\.de\.html$/);
    assert.equal(await page.title(), 'Newton · Für Lehrkräfte');
    assert.equal(await page.locator('html').getAttribute('lang'), 'de');
    const german = await page.locator('h2').allTextContents();
    for (const heading of [
      'Trägheit (erstes Gesetz)',
      'Lösungen',
      'Arbeitsblatt: Stöße (drittes Gesetz)',
    ]) {
      assert.ok(german.includes(heading), `${heading} in ${JSON.stringify(german)}`);
    }
    assert.equal(await page.locator('h3', { hasText: '20-Minuten-Plan' }).count(), 3);
    await screenshot(page, 'teacher-de-offline');
    // Its language link: the English page, offline too.
    await page.locator('[data-language="en"]').click();
    await page.waitForURL(/teacher\.html$/);
    assert.equal(await page.title(), 'Newton · For teachers');
    const english = await page.locator('h2').allTextContents();
    for (const heading of [
      'Inertia (first law)',
      'Force (second law)',
      'Reaction (third law)',
      'Answer key',
    ]) {
      assert.ok(english.includes(heading), `${heading} in ${JSON.stringify(english)}`);
    }
    assert.equal(await page.locator('h3', { hasText: '20-minute plan' }).count(), 3);
    assert.equal(await page.locator('.predict').count(), 3);
    // Readable on a phone: nothing wider than the screen.
    const overflow = await page.evaluate(
      () => document.documentElement.scrollWidth - document.documentElement.clientWidth,
    );
    assert.ok(overflow <= 0, `no sideways scrolling (${overflow} px)`);
    await screenshot(page, 'teacher-en-offline');
    // Print the worksheet: only it and the answer key, the key on a page of its own.
    await page.evaluate(() => {
      window.print = () => undefined;
    });
    await page.locator('button[data-print="worksheet"]').click();
    await page.emulateMedia({ media: 'print' });
    const printed = await page.evaluate(() => {
      const shown = (selector: string): boolean =>
        getComputedStyle(document.querySelector(selector)!).display !== 'none';
      return {
        worksheet: shown('#worksheet'),
        answers: shown('#answers'),
        plans: shown('#reactions'),
        breakBefore: getComputedStyle(document.querySelector('#answers')!).breakBefore,
        background: getComputedStyle(document.body).backgroundColor,
      };
    });
    assert.deepEqual(printed, {
      worksheet: true,
      answers: true,
      plans: false,
      breakBefore: 'page',
      background: 'rgb(255, 255, 255)',
    });
    await page.emulateMedia({ media: 'screen' });
    // A preset link on the page opens the app offline in that setup.
    await page.evaluate(() => document.body.classList.remove('worksheet-only'));
    await page
      .locator('a[href="./#reactions?mA=1&mB=2&vA=1.5&vB=-0.5&e=1&walls=0&tilt=0"]')
      .first()
      .click();
    await waitReady(page);
    await page.locator('#reactions [data-lab-input="A-vx"]').waitFor();
    assert.equal(await labValue(page, 'A-vx'), 1.5);
    await openTab(page, 'setup');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});
