import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import { assertQuiet, closeApp, openApp, PHONE, readout, screenshot } from './phone.ts';

const sleep = (ms: number): Promise<void> => new Promise((resolve) => setTimeout(resolve, ms));

test('newton: sound is off by default, the toggle turns event tones on, and the choice is kept', async ({
  browser,
}) => {
  const app = await openApp(browser, '#reactions');
  const { page } = app;
  try {
    const toggle = page.locator('[data-action="sound"]').first();
    assert.equal(await toggle.getAttribute('aria-pressed'), 'false');
    const add = page.locator('#reactions [data-action="add"]');
    const tones = (): Promise<number> =>
      page.evaluate(() => Number(document.documentElement.dataset['tones'] ?? 0));

    // Off: an event is announced, and no tone plays.
    await add.click();
    await sleep(400);
    assert.equal(await readout(page, 'count'), '1');
    assert.equal(await tones(), 0, 'no tone while sound is off');

    // On: the next event plays one.
    await toggle.click();
    assert.equal(await toggle.getAttribute('aria-pressed'), 'true');
    await add.click();
    await page.waitForFunction(() => Number(document.documentElement.dataset['tones'] ?? 0) >= 1);

    // Reloaded, the app remembers; turned off again, it stays quiet.
    await page.reload();
    await page.waitForFunction(() => document.documentElement.dataset['ready'] === 'true');
    const again = page.locator('[data-action="sound"]').first();
    assert.equal(await again.getAttribute('aria-pressed'), 'true', 'sound stays on after reload');
    await again.click();
    assert.equal(await again.getAttribute('aria-pressed'), 'false');
    await page.locator('#reactions [data-action="add"]').click();
    await sleep(400);
    assert.equal(await tones(), 0, 'no tone once turned off (a fresh page counts from 0)');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: with prefers-reduced-motion, controls have no transitions; without it they do', async ({
  browser,
}) => {
  // The elasticity slider (a native range input) animates its states (Material's transitions)
  // unless the learner asked for less motion.
  const durations: Record<string, string> = {};
  for (const reducedMotion of ['no-preference', 'reduce'] as const) {
    const app = await openApp(browser, '#reactions', { ...PHONE, reducedMotion });
    try {
      await app.page.locator('#reactions [data-tab="options"]').click();
      durations[reducedMotion] = await app.page
        .locator('#reactions [data-control="elasticity"] input')
        .evaluate((slider) => getComputedStyle(slider).transitionDuration);
      assertQuiet(app);
    } finally {
      await closeApp(app);
    }
  }
  const longest = (list: string): number =>
    Math.max(...list.split(',').map((item) => Number.parseFloat(item)));
  assert.ok(longest(durations['no-preference']!) > 0, `animated: ${durations['no-preference']}`);
  assert.equal(longest(durations['reduce']!), 0, `reduced: ${durations['reduce']}`);
});

test('newton: the teacher page opens from the hint, covers the three laws, and leads back', async ({
  browser,
}) => {
  const app = await openApp(browser, '#inertia');
  const { page } = app;
  try {
    await page.locator('[data-action="hint"]').first().click();
    await page.locator('[data-action="teacher"]').click();
    await page.waitForURL(/teacher\.html$/);
    assert.equal(await page.title(), 'Newton · For teachers');
    const headings = await page.locator('h2').allTextContents();
    for (const law of ['Inertia (first law)', 'Force (second law)', 'Reaction (third law)']) {
      assert.ok(headings.includes(law), `a section on ${law}: ${JSON.stringify(headings)}`);
    }
    // Readable on a phone: nothing wider than the screen.
    const overflow = await page.evaluate(
      () => document.documentElement.scrollWidth - document.documentElement.clientWidth,
    );
    assert.ok(overflow <= 0, `no sideways scrolling (${overflow} px)`);
    await screenshot(page, 'teacher');
    await page.locator('a', { hasText: 'Back to Newton' }).click();
    await page.waitForFunction(() => document.documentElement.dataset['ready'] === 'true');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});
