import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import { closeApp, openApp } from './phone.ts';
import {
  PHONES,
  SCREENS,
  TILT_PERMISSION,
  chooseLocale,
  fitProblems,
  phoneOptions,
  showScreen,
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
