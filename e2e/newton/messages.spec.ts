import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import { chooseLocale, phoneOptions } from './fit.ts';
import { closeApp, openApp } from './phone.ts';

test('newton: messages (375x667), one particle is "1 particle" in English and German, and -3 kg is out of range, not "not a number"', async ({
  browser,
}) => {
  const app = await openApp(browser, '#reactions', phoneOptions(375, 667, false));
  const { page } = app;
  const announced = async (pattern: RegExp): Promise<void> => {
    await page.waitForFunction(
      (source) =>
        new RegExp(source).test(
          document.querySelector('[data-announcer="reactions"]')!.textContent ?? '',
        ),
      pattern.source,
      { timeout: 5000, polling: 50 },
    );
  };
  try {
    await page.locator('#reactions [data-action="add"]').tap();
    await announced(/\. 1 particle\.$/);
    await page.locator('#reactions [data-action="add"]').tap();
    await announced(/\. 2 particles\.$/);
    await chooseLocale(page, 'de');
    await page.locator('#reactions [data-action="clear"]').tap();
    await page.locator('#reactions [data-action="add"]').tap();
    await announced(/\. 1 Teilchen\.$/);

    await page.locator('[data-nav="forces"]').tap();
    await page.locator('[data-action="edit-A"]').tap();
    await page.getByRole('dialog').waitFor();
    for (const [field, typed, message] of [
      ['square-mass', '-3', /zwischen 0,5 und 5 kg/],
      ['square-force', '-1', /zwischen 0 und 10 N/],
    ] as const) {
      await page.locator(`#${field}`).fill(typed);
      const helper = (await page.locator(`[data-helper="${field}"]`).textContent()) ?? '';
      assert.match(helper.replace(/\u00a0/g, ' '), message, `"${typed}" in ${field}`);
    }
  } finally {
    await closeApp(app);
  }
});
