import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import { phoneOptions } from './fit.ts';
import { assertQuiet, changedPixels, closeApp, openApp, paintedPixels, readout } from './phone.ts';

const CANVAS = '#inertia physical-canvas';

test('newton: inertia lab (375x667), a student hides and shows arrows and values, and resets all', async ({
  browser,
}) => {
  const app = await openApp(browser, '#inertia', phoneOptions(375, 667, false));
  const { page } = app;
  try {
    // A force on, paused: the arrows and their values are drawn; hidden, they are gone (the
    // canvas changes, and nothing new is painted: an arrow may lie over its body).
    await page.locator('#inertia [data-action="toggle-force"]').tap();
    await page.waitForTimeout(300);
    await page.locator('#inertia [data-action="play"]').tap();
    await page.waitForTimeout(200);
    const all = await paintedPixels(page, CANVAS);
    await changedPixels(page, CANVAS);
    await page.locator('[data-control="show-vectors"]').uncheck();
    await page.waitForTimeout(200);
    const noArrows = await paintedPixels(page, CANVAS);
    const arrowPixels = await changedPixels(page, CANVAS);
    await page.locator('[data-control="show-values"]').uncheck();
    await page.waitForTimeout(200);
    const bare = await paintedPixels(page, CANVAS);
    const valuePixels = await changedPixels(page, CANVAS);
    assert.ok(arrowPixels > 20, `hiding the arrows changes the drawing (${arrowPixels} pixels)`);
    assert.ok(noArrows <= all, `hiding the arrows paints nothing new (${noArrows} <= ${all})`);
    assert.ok(valuePixels > 20, `hiding the values changes the drawing (${valuePixels} pixels)`);
    assert.ok(bare < noArrows, `hiding the values draws less (${bare} < ${noArrows})`);

    // Reset all: both shown again, the force off, the clock back to zero.
    await page.locator('#inertia [data-action="reset-all"]').tap();
    await page.waitForTimeout(200);
    assert.equal(await page.locator('[data-control="show-vectors"]').isChecked(), true);
    assert.equal(await page.locator('[data-control="show-values"]').isChecked(), true);
    assert.equal(
      await page.locator('#inertia [data-action="toggle-force"]').getAttribute('aria-pressed'),
      'false',
    );
    assert.equal(await readout(page, 'time', '#inertia'), 't = 0.00 s');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});
