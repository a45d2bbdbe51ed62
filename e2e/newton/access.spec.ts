import assert from 'node:assert/strict';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import { LANDSCAPE, PHONE, assertQuiet, closeApp, openApp, readout, screenshot } from './phone.ts';

const sleep = (ms: number): Promise<void> => new Promise((resolve) => setTimeout(resolve, ms));
const SCREENS = ['inertia', 'forces', 'reactions'] as const;

/** Records the times (ms) the announcer `name` changed its text. */
async function recordAnnouncements(page: Page, name: string): Promise<void> {
  await page.evaluate((id) => {
    const region = document.querySelector(`[data-announcer="${id}"]`)!;
    const log: { at: number; text: string }[] = [];
    (window as unknown as { announced: typeof log }).announced = log;
    new MutationObserver(() =>
      log.push({ at: performance.now(), text: region.textContent ?? '' }),
    ).observe(region, { childList: true, characterData: true, subtree: true });
  }, name);
}

for (const [orientation, options] of [
  ['portrait', PHONE],
  ['landscape', LANDSCAPE],
] as const) {
  test(`newton: reactions (${orientation}), the keyboard adds particles, the tilt's acceleration is capped at g with angles 0-359°, events are announced at a human pace`, async ({
    browser,
  }) => {
    const app = await openApp(browser, '#reactions', options);
    const { page } = app;
    try {
      await recordAnnouncements(page, 'reactions');
      const add = page.locator('#reactions [data-action="add"]');
      await add.focus();
      for (let i = 0; i < 6; i++) await page.keyboard.press('Enter');
      assert.equal(await readout(page, 'count'), '6');
      // A diagonal full tilt: g sin θ at most g (not 1.41 g), at 315° (down and right), as
      // Inertia counts.
      await page.evaluate(() =>
        window.dispatchEvent(
          new DeviceOrientationEvent('deviceorientation', { alpha: 0, beta: 90, gamma: 90 }),
        ),
      );
      await sleep(300);
      // Portrait: right and down the screen. Landscape turns the axes with the screen.
      if (orientation === 'portrait') assert.equal(await readout(page, 'push'), '9.81 m/s², 315°');
      else assert.match(await readout(page, 'push'), /^9\.81 m\/s², (45|135|225|315)°$/);
      await page.evaluate(() =>
        window.dispatchEvent(
          new DeviceOrientationEvent('deviceorientation', { alpha: 0, beta: -90, gamma: 0 }),
        ),
      );
      await sleep(300);
      if (orientation === 'portrait') {
        assert.equal(await readout(page, 'push'), '9.81 m/s², 90°', 'up is 90°, never -90°');
      } else assert.match(await readout(page, 'push'), /^9\.81 m\/s², (0|90|180|270)°$/);
      await sleep(4000);
      const log = await page.evaluate(
        () => (window as unknown as { announced: { at: number; text: string }[] }).announced,
      );
      const spoken = log.filter((entry) => entry.text !== '');
      assert.ok(spoken.length >= 2, `announced: ${JSON.stringify(spoken)}`);
      assert.match(spoken[0]!.text, /Particle added/);
      for (let i = 1; i < spoken.length; i++) {
        const gap = spoken[i]!.at - spoken[i - 1]!.at;
        assert.ok(gap >= 1400, `two announcements ${Math.round(gap)} ms apart`);
      }
      // Every control is on screen in this orientation.
      const viewport = page.viewportSize()!;
      for (const control of await page.locator('#reactions [data-action]').all()) {
        const box = (await control.boundingBox())!;
        assert.ok(
          box.y >= 0 && box.y + box.height <= viewport.height + 1,
          `${await control.getAttribute('data-action')} is off screen`,
        );
      }
      await screenshot(page, `reactions-keyboard-${orientation}`);
      await page.locator('#reactions [data-tab="options"]').click();
      assert.match((await page.locator('[data-legend="arrows"]').textContent())!, /acts on/);
      assertQuiet(app);
    } finally {
      await closeApp(app);
    }
  });
}

test('newton: touch targets are 48 px, text is 13 px or more, the German title fits, no device-tilt button on a desktop', async ({
  browser,
}) => {
  const app = await openApp(browser, '#inertia');
  const { page } = app;
  try {
    await page.locator('[data-locale="de"]').click();
    for (const screen of SCREENS) {
      await page.locator(`[data-nav="${screen}"]`).click();
      await page.locator(`#${screen}`).waitFor({ state: 'visible' });
      await sleep(150);
      const small = await page.evaluate(() => {
        const found: string[] = [];
        for (const element of document.querySelectorAll<HTMLElement>(
          'button, a[href], [role="button"]',
        )) {
          const box = element.getBoundingClientRect();
          if (box.width === 0 || element.closest('[aria-hidden="true"]') !== null) continue;
          if (box.width < 47.5 || box.height < 47.5) {
            found.push(
              `${element.dataset['action'] ?? element.getAttribute('aria-label') ?? element.textContent} ${Math.round(box.width)}x${Math.round(box.height)}`,
            );
          }
        }
        for (const element of document.querySelectorAll<HTMLElement>('body *')) {
          const own = [...element.childNodes].some(
            (node) => node.nodeType === 3 && node.textContent!.trim() !== '',
          );
          if (!own || element.getBoundingClientRect().width === 0) continue;
          const size = parseFloat(getComputedStyle(element).fontSize);
          if (size < 13) found.push(`text "${element.textContent!.slice(0, 20)}" ${size}px`);
        }
        const title = document.querySelector('h1')!;
        if (title.scrollWidth > title.clientWidth + 1)
          found.push(`title cut: ${title.textContent}`);
        return found;
      });
      assert.deepEqual(small, [], `${screen}: small targets or text`);
    }
    await screenshot(page, 'reactions-german');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
  const desktop = await openApp(browser, '#reactions', {
    ...PHONE,
    viewport: { width: 1280, height: 800 },
    deviceScaleFactor: 1,
    isMobile: false,
    hasTouch: false,
  });
  try {
    // Chromium on a desktop has the permission API but no sensor: the button would do nothing.
    assert.equal(await desktop.page.getByRole('button', { name: 'Use device tilt' }).count(), 0);
  } finally {
    await closeApp(desktop);
  }
});

test('newton: rotating the phone rebuilds each world to the new shape (no letterbox)', async ({
  browser,
}) => {
  const app = await openApp(browser, '#reactions', LANDSCAPE);
  const { page } = app;
  try {
    for (const screen of ['reactions', 'inertia'] as const) {
      await page.locator(`[data-nav="${screen}"]`).click();
      await sleep(300);
      await page.setViewportSize(PHONE.viewport!);
      await sleep(600);
      const { view, host } = await page.evaluate((id) => {
        const canvas = document.querySelector(`#${id} physical-canvas`) as HTMLElement & {
          viewBox: { width: number; height: number };
        };
        return {
          view: canvas.viewBox.width / canvas.viewBox.height,
          host: canvas.clientWidth / canvas.clientHeight,
        };
      }, screen);
      assert.ok(
        Math.abs(view / host - 1) < 0.25,
        `${screen}: world aspect ${view.toFixed(2)} in a host of ${host.toFixed(2)}`,
      );
      await page.setViewportSize(LANDSCAPE.viewport!);
      await sleep(300);
    }
    await screenshot(page, 'rotated-inertia');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

// Counts every animation frame the page asks for.
const COUNT_FRAMES = `
  window.__frames = 0;
  const request = window.requestAnimationFrame.bind(window);
  window.requestAnimationFrame = (callback) => { window.__frames++; return request(callback); };
`;

test('newton: idle, nothing draws while nothing changes, on the shown screen or the hidden ones', async ({
  browser,
}) => {
  const app = await openApp(browser, '#inertia', PHONE, 'static', COUNT_FRAMES);
  const { page } = app;
  const framesIn = async (ms: number): Promise<number> => {
    const before = await page.evaluate(() => (window as unknown as { __frames: number }).__frames);
    await sleep(ms);
    const after = await page.evaluate(() => (window as unknown as { __frames: number }).__frames);
    return after - before;
  };
  try {
    await sleep(800);
    const results: string[] = [];
    for (const screen of SCREENS) {
      await page.locator(`[data-nav="${screen}"]`).click();
      await sleep(800); // transitions and the first frames
      const frames = await framesIn(1500);
      if (frames > 2) results.push(`${screen}: ${frames} frames in 1.5 s at rest`);
    }
    assert.deepEqual(results, []);
    // Something moving draws; back at rest it stops again.
    await page.locator('[data-nav="reactions"]').click();
    await page.locator('#reactions [data-action="add"]').click();
    await page.evaluate(() =>
      window.dispatchEvent(
        new DeviceOrientationEvent('deviceorientation', { alpha: 0, beta: 0, gamma: 30 }),
      ),
    );
    await page.waitForFunction(
      () =>
        (document.querySelector('#reactions physical-canvas') as unknown as { isRunning: boolean })
          .isRunning,
      undefined,
      { timeout: 5000 },
    );
    const drawn = await framesIn(1000);
    assert.ok(drawn > 5, `a moving particle is drawn (${drawn} frames in 1 s)`);
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});
