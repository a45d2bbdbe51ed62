import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import { closeApp, openApp } from './phone.ts';
import {
  PHONES,
  SCREENS,
  RECORD_CANVAS_TEXT,
  TILT_PERMISSION,
  chooseLocale,
  fitProblems,
  phoneOptions,
  showScreen,
  trackTexts,
  type CanvasText,
} from './fit.ts';

const sleep = (ms: number): Promise<void> => new Promise((resolve) => setTimeout(resolve, ms));

// Every screen on every phone, both ways up, in both languages: the page never scrolls, and
// every control one can see can be tapped at its centre (no navigation bar, graph or long German
// label lies over it, none is pushed off the screen, the main actions need no scrolling).
for (const [width, height] of PHONES) {
  for (const landscape of [false, true]) {
    const name = landscape ? `${height}x${width}` : `${width}x${height}`;
    test(`newton: fit, ${name}: every screen fits and every control can be tapped, in English and German`, async ({
      browser,
    }) => {
      const app = await openApp(
        browser,
        '#inertia',
        phoneOptions(width, height, landscape),
        'static',
        TILT_PERMISSION,
      );
      try {
        const problems: string[] = [];
        for (const locale of ['en', 'de'] as const) {
          await chooseLocale(app.page, locale);
          for (const screen of SCREENS) {
            await showScreen(app.page, screen);
            // The layout settles (fonts, the canvases' first size) within a frame or two.
            await sleep(150);
            for (const problem of await fitProblems(app.page)) {
              problems.push(`${locale} ${screen}: ${problem}`);
            }
          }
        }
        assert.deepEqual(problems, [], `at ${name}:\n${problems.join('\n')}`);
      } finally {
        await closeApp(app);
      }
    });
  }
}

test('newton: fit (375x667), a tap leaves no tooltip on the screen', async ({ browser }) => {
  const app = await openApp(browser, '#inertia', phoneOptions(375, 667, false));
  try {
    const { page } = app;
    // Touch taps, and the mouse events a phone makes up for a tap (the pointer then rests on
    // the button, as a hover that never leaves).
    for (const action of ['slow', 'reset', 'hint']) {
      const button = page.locator(`[data-action="${action}"]:visible`).first();
      for (const press of [() => button.tap(), () => button.click()]) {
        await press();
        if (action === 'hint') {
          const dialog = page.getByRole('dialog');
          await dialog.waitFor();
          await dialog.getByRole('button').last().tap();
          await dialog.waitFor({ state: 'detached' });
        }
      }
    }
    // Past MUI's touch leave delay (1.5 s): a tooltip a tap opened is gone by now.
    await sleep(2500);
    const tooltips = await page.locator('[role="tooltip"]:visible').allTextContents();
    assert.deepEqual(tooltips, [], 'no tooltip is left on the screen after taps');
  } finally {
    await closeApp(app);
  }
});

// A small phone leaves each Forces track a short canvas: the force label ("F = ΣF = 2 N") the
// square carries must not be drawn over the ruler's numbers ("2 m", "4 m"...) as it passes them.
for (const [width, height] of [
  [320, 568],
  [360, 640],
] as const) {
  test(`newton: fit, ${width}x${height}: a Forces track's force label never covers the ruler's numbers`, async ({
    browser,
  }) => {
    const app = await openApp(
      browser,
      '#forces',
      phoneOptions(width, height, false),
      'static',
      RECORD_CANVAS_TEXT,
    );
    try {
      const { page } = app;
      for (const locale of ['en', 'de'] as const) {
        await chooseLocale(page, locale);
        await page.locator('[data-action="reset"]:visible').first().click();
        await page.locator('#forces [data-action="start"]').click();
        const overlaps: string[] = [];
        let numbers = 0;
        let labels = 0;
        // The squares pass the 2, 4 and 6 m marks within the samples (x = F t² / 2m).
        for (let sample = 0; sample < 25; sample++) {
          await sleep(100);
          for (const [track, texts] of Object.entries(await trackTexts(page))) {
            const ruler = texts.filter((text) => /^\d+ m$/.test(text.text));
            // Neither a ruler number nor the track's name on its square: the force label.
            const forceLabels = texts.filter(
              (text) => !/^\d+ m$/.test(text.text) && text.text !== track,
            );
            numbers += ruler.length;
            labels += forceLabels.length;
            for (const label of forceLabels) {
              for (const number of ruler) {
                if (intersects(label, number)) {
                  overlaps.push(`${locale} ${track}: "${label.text}" covers "${number.text}"`);
                }
              }
            }
          }
        }
        assert.ok(labels > 0, `${locale}: the tracks draw their force labels`);
        assert.ok(numbers > 0, `${locale}: the tracks draw their ruler's numbers`);
        assert.deepEqual([...new Set(overlaps)], [], `at ${width}x${height}`);
      }
    } finally {
      await closeApp(app);
    }
  });
}

/** True when two text boxes share any pixel. */
function intersects(a: CanvasText, b: CanvasText): boolean {
  return a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
}
