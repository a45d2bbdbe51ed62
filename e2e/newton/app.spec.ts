import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import {
  PHONE,
  assertQuiet,
  axeViolations,
  closeApp,
  openApp,
  paintedPixels,
  screenshot,
  waitReady,
} from './phone.ts';

const sleep = (ms: number): Promise<void> => new Promise((resolve) => setTimeout(resolve, ms));

test('newton: the language switch changes the texts (English, German)', async ({ browser }) => {
  const app = await openApp(browser, '#inertia');
  const { page } = app;
  try {
    const law = page.locator('#inertia-law');
    assert.match((await law.textContent())!, /^First law/);
    await page.locator('[data-locale="de"]').click();
    assert.match((await law.textContent())!, /^Erstes Gesetz/);
    assert.equal(await page.evaluate(() => document.documentElement.lang), 'de');
    assert.equal((await page.locator('[data-nav="inertia"]').textContent())!.trim(), 'Trägheit');
    assert.equal(
      (await page.locator('#inertia [data-action="change-force"]').textContent())!.trim(),
      'Kraft ändern',
    );
    await screenshot(page, 'inertia-german');
    // The choice survives a reload.
    await page.reload();
    await waitReady(page);
    assert.match((await law.textContent())!, /^Erstes Gesetz/);
    await page.locator('[data-locale="en"]').click();
    assert.match((await law.textContent())!, /^First law/);
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: after one visit the app reloads with the network off (served by npm start)', async ({
  browser,
}) => {
  // vite preview, the server npm start runs: it sends Vary: Origin, which a cache lookup without
  // ignoreVary misses for module scripts.
  const app = await openApp(browser, '#forces', PHONE, 'preview');
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
    await page.reload();
    await waitReady(page);
    assert.match((await page.locator('#forces-law').textContent())!, /^Second law/);
    await sleep(300);
    assert.ok(
      (await paintedPixels(page, '#forces physical-canvas')) > 1000,
      'canvas drawn offline',
    );
    const manifest = await page.evaluate(async () =>
      (await fetch('./manifest.webmanifest')).json(),
    );
    assert.equal((manifest as { short_name: string }).short_name, 'Newton');
    await screenshot(page, 'forces-offline');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: axe-core finds no serious or critical violations on any screen', async ({
  browser,
}) => {
  const app = await openApp(browser);
  const { page } = app;
  try {
    const found: string[] = [];
    for (const screen of ['inertia', 'forces', 'reactions']) {
      await page.locator(`[data-nav="${screen}"]`).click();
      await sleep(200);
      found.push(...(await axeViolations(page)).map((v) => `${screen}: ${v}`));
    }
    // The dialogs too.
    await page.locator('[data-nav="inertia"]').click();
    await page.locator('#inertia [data-action="change-force"]').click();
    await page.getByRole('dialog').waitFor();
    await sleep(500); // past the fade-in: mid-transition colours are not the real contrast
    found.push(...(await axeViolations(page)).map((v) => `force dialog: ${v}`));
    await page.keyboard.press('Escape');
    await page.getByRole('dialog').waitFor({ state: 'detached' });
    await page.locator('[data-nav="forces"]').click();
    await page.locator('[data-action="edit-A"]').click();
    await page.getByRole('dialog').waitFor();
    await sleep(500);
    found.push(...(await axeViolations(page)).map((v) => `square dialog: ${v}`));
    assert.deepEqual(found, []);
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: keyboard only, and a navigation rail on a wide screen', async ({ browser }) => {
  const app = await openApp(browser, '#reactions', {
    ...PHONE,
    viewport: { width: 1280, height: 800 },
    deviceScaleFactor: 1,
    isMobile: false,
    hasTouch: false,
  });
  const { page } = app;
  try {
    assert.equal(await page.locator('nav [data-nav]').count(), 3);
    assert.equal(await page.locator('nav.app-nav--bar').count(), 0, 'rail, not bottom bar');
    // Arrow keys tilt (the desktop's stand-in for the phone): two presses of sin θ = 0.25 lean
    // the tray to sin θ = 0.5, which gives every particle the acceleration g sin θ along it.
    await page.locator('body').press('ArrowRight');
    await page.keyboard.press('ArrowRight');
    const push = (await page.locator('[data-readout="push"]').textContent())!.replace(
      /\u00a0/g,
      ' ',
    );
    const pushMatch = /^([\d.]+) m\/s², (-?\d+)°$/.exec(push);
    assert.ok(pushMatch !== null, `tray acceleration readout: ${push}`);
    const G = 9.81;
    assert.ok(
      Math.abs(Number(pushMatch[1]) - G * 0.5) < 0.01,
      `tray acceleration ${push}, not g sin θ = ${(G * 0.5).toFixed(2)} m/s²`,
    );
    assert.equal(Number(pushMatch[2]), 0, `tray acceleration ${push} points right`);
    // Spawn particles with the mouse, pause with the keyboard.
    const box = (await page.locator('#reactions physical-canvas').boundingBox())!;
    for (const [fx, fy] of [
      [0.3, 0.5],
      [0.5, 0.2],
      [0.6, 0.85],
    ] as const) {
      await page.mouse.click(box.x + box.width * fx, box.y + box.height * fy);
    }
    await page.locator('#reactions [data-action="play"]').focus();
    await page.keyboard.press('Enter');
    assert.equal(await page.locator('#reactions [data-action="step"]').isDisabled(), false);
    await page.keyboard.press('Tab');
    await page.keyboard.press('Enter'); // one step
    await page.locator('[data-nav="inertia"]').focus();
    await page.keyboard.press('Enter');
    await page.locator('#inertia').waitFor({ state: 'visible' });
    await sleep(300);
    await screenshot(page, 'desktop-inertia');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: npm start sends the app in Brotli, which the page decodes', async ({ browser }) => {
  const app = await openApp(browser, '#inertia', PHONE, 'preview');
  const { page } = app;
  try {
    // What the browser received for its entry: the build's .br of that very file.
    const entry = await page.evaluate(() => {
      const item = performance
        .getEntriesByType('resource')
        .map((resource) => resource as PerformanceResourceTiming)
        .find((resource) => /\/assets\/index-[\w-]+\.js$/.test(resource.name))!;
      return {
        path: new URL(item.name).pathname,
        encoded: item.encodedBodySize,
        decoded: item.decodedBodySize,
      };
    });
    const { statSync } = await import('node:fs');
    const { DIST } = await import('./app-server.ts');
    const built = statSync(`${DIST}${entry.path.slice(1)}`).size;
    const brotli = statSync(`${DIST}${entry.path.slice(1)}.br`).size;
    assert.equal(entry.decoded, built, 'the page decoded the whole entry');
    assert.equal(entry.encoded, brotli, `the entry came as its .br (${entry.encoded} bytes)`);
    const response = await page.request.get(`${app.server.url}${entry.path}`, {
      headers: { 'accept-encoding': 'gzip, br' },
    });
    assert.equal(response.headers()['content-encoding'], 'br');
    // The app runs from it: the first screen is on the page (waited for by openApp).
    assert.match((await page.locator('#inertia-law').textContent())!, /^First law/);
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: the first screen is requested as the entry arrives (its preload script comes before the stylesheet)', async ({
  browser,
}) => {
  const app = await openApp(browser, '#inertia');
  try {
    const { page } = app;
    // The page as served, and the requests it made: the script that preloads the entry and then
    // the first screen's chunks runs before the parser meets a stylesheet (a script after one
    // waits for it).
    const html = await (await page.request.get(`${app.server.url}/index.html`)).text();
    const preload = html.indexOf('modulepreload');
    const stylesheet = html.indexOf('rel="stylesheet"');
    const entry = html.indexOf('<script type="module"');
    assert.ok(preload > 0, 'the page preloads the first screen');
    assert.ok(stylesheet > 0 && entry > 0, 'the page has its stylesheet and entry');
    assert.ok(
      preload < stylesheet && preload < entry,
      `the preload script (at ${preload}) comes before the stylesheet (${stylesheet}) and the entry (${entry})`,
    );
    const { preloaded, requests } = await page.evaluate(() => ({
      preloaded: [...document.querySelectorAll<HTMLLinkElement>('link[rel="modulepreload"]')].map(
        (link) => link.href.split('/').pop() ?? '',
      ),
      requests: performance
        .getEntriesByType('resource')
        .map((item) => item as PerformanceResourceTiming)
        .map((item) => ({
          name: item.name.split('/').pop() ?? '',
          start: item.startTime,
          end: item.responseEnd,
        })),
    }));
    assert.ok(
      preloaded.some((name) => /^InertiaScreen-/.test(name)),
      `Inertia's chunk is preloaded (${preloaded.join(', ')})`,
    );
    // The entry is fetched once (the module script takes the preload's response), and the
    // screen's chunks are asked for once it has arrived, not beside it: on Slow 4G they would
    // share its bandwidth and the phone's CPU would wait idle for all of them.
    const entries = requests.filter((item) => /^index-.*\.js$/.test(item.name));
    assert.equal(entries.length, 1, `the entry is requested once (${JSON.stringify(entries)})`);
    const screen = requests.find((item) => /^InertiaScreen-/.test(item.name));
    assert.ok(screen !== undefined, 'the screen chunk was requested');
    assert.ok(
      screen.start >= entries[0]!.end,
      `the screen's chunk is requested (at ${screen.start} ms) once the entry has arrived (${entries[0]!.end} ms)`,
    );
  } finally {
    await closeApp(app);
  }
});
