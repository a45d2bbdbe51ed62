import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import { PHONE, closeApp, openApp, readout } from './phone.ts';

// Holding Enter on the Add button repeats it about 30 times a second. An overfull box pushed
// particles through its walls at hundreds of m/s; the box now stops taking particles at
// MAX_FILL of its area and says so.
test('newton: reactions, holding Add fills the box to its limit, says it is full, and adds no more', async ({
  browser,
}) => {
  const app = await openApp(browser, '#reactions', PHONE);
  const { page } = app;
  try {
    // Every text the announcer shows (collisions are announced too, so a message may not last).
    await page.evaluate(() => {
      const region = document.querySelector('[data-announcer="reactions"]')!;
      const log: string[] = [];
      (window as unknown as { announced: string[] }).announced = log;
      new MutationObserver(() => log.push(region.textContent ?? '')).observe(region, {
        childList: true,
        characterData: true,
        subtree: true,
      });
    });
    await page.locator('#reactions [data-action="add"]').focus();
    let count = '';
    for (let i = 0; i < 400; i++) {
      await page.keyboard.press('Enter');
      if (i % 20 === 19) {
        count = await readout(page, 'count');
        if (count.endsWith('full')) break;
      }
    }
    assert.match(count, /^\d+, full$/, `count readout: ${count}`);
    const full = Number(count.split(',')[0]);
    assert.ok(full > 20, `only ${full} particles before full`);
    // More presses add nothing, and the announcer says why.
    for (let i = 0; i < 5; i++) await page.keyboard.press('Enter');
    assert.equal(await readout(page, 'count'), `${full}, full`);
    await page.waitForFunction(
      () =>
        (window as unknown as { announced: string[] }).announced.includes(
          'The box is full: remove particles to add more.',
        ),
      undefined,
      { timeout: 10_000 },
    );
  } finally {
    await closeApp(app);
  }
});
