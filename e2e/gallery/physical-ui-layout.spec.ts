import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import { assertQuiet } from '../newton/phone.ts';
import { closeGallery, openGallery, screenshot } from './gallery-page.ts';

test('gallery: the Physical UI buttons are styled 48 px touch targets', async ({ browser }) => {
  const gallery = await openGallery(browser, '#/physical-ui');
  const { page } = gallery;
  try {
    await page.waitForSelector('.physical-ui nav button');
    for (const id of ['drop', 'home']) {
      const button = page.locator(`.physical-ui #${id}`);
      const box = (await button.boundingBox())!;
      assert.ok(
        box.width >= 48 && box.height >= 48,
        `#${id} is ${box.width.toFixed(0)} x ${box.height.toFixed(0)} px`,
      );
      // Styled by the page, not the browser's square default button.
      const radius = await button.evaluate((element) =>
        parseFloat(getComputedStyle(element).borderTopLeftRadius),
      );
      assert.ok(radius >= 8, `#${id} has rounded corners (${radius} px)`);
    }
    await screenshot(page, 'physical-ui-buttons-phone');
    assertQuiet(gallery);
  } finally {
    await closeGallery(gallery);
  }
});

test('gallery: the Physical UI card on the list keeps a gap to the grid below it', async ({
  browser,
}) => {
  const gallery = await openGallery(browser);
  const { page } = gallery;
  try {
    const card = (await page.locator('[data-page="physical-ui"]').boundingBox())!;
    const grid = (await page.locator('ul.grid').boundingBox())!;
    const gap = grid.y - (card.y + card.height);
    assert.ok(gap >= 12, `${gap.toFixed(1)} px between the card and the grid`);
    assertQuiet(gallery);
  } finally {
    await closeGallery(gallery);
  }
});

test('gallery: the list links the worker page, and its card keeps a gap to the next', async ({
  browser,
}) => {
  const gallery = await openGallery(browser);
  const { page } = gallery;
  try {
    const worker = (await page.locator('[data-page="worker"]').boundingBox())!;
    const next = (await page.locator('[data-page="physical-ui"]').boundingBox())!;
    const gap = next.y - (worker.y + worker.height);
    assert.ok(gap >= 12, `${gap.toFixed(1)} px between the worker card and the next one`);
    await page.locator('[data-page="worker"]').click();
    await page.waitForFunction(() => location.hash === '#/worker');
    // The page renders after the hash changes: wait for its heading rather than read it at once
    // (read at once, it was still the list's heading in one CI run).
    await page.waitForFunction(
      () => document.querySelector('h1')?.textContent?.trim() === '2,000 bodies in a worker',
      undefined,
      { timeout: 10_000 },
    );
    assert.equal(
      (await page.locator('h1').first().textContent())?.trim(),
      '2,000 bodies in a worker',
    );
    assertQuiet(gallery);
  } finally {
    await closeGallery(gallery);
  }
});
