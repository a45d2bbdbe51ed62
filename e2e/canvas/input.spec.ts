import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import type {} from './fixture-api.ts';
import { waitFrames } from './page-helpers.ts';

// A paused world at 40 px/m with origin (0, 0): the box centred at (3, 2) m sits at CSS px
// (120, 80) of the element, itself at the page's top-left corner.
async function setUp(open: Parameters<Parameters<typeof test>[1]>[0]['open'], hasTouch = false) {
  const page = await open('/canvas/fixture.html', {
    viewport: { width: 400, height: 300 },
    hasTouch,
  });
  await page.evaluate(() => {
    const { World, box } = window.physical;
    const canvas = document.querySelector('physical-canvas')!;
    canvas.pixelsPerMeter = 40;
    canvas.paused = true;
    const world = new World();
    world.add(box({ type: 'static', position: { x: 8, y: 6 }, width: 1, height: 1 }));
    world.add(box({ position: { x: 3, y: 2 }, width: 2, height: 1, userData: 'target' }));
    canvas.world = world;
    const log: { type: string; body: unknown; x: number; y: number }[] = [];
    for (const type of ['bodypress', 'bodyrelease', 'bodytap', 'backgroundtap'] as const) {
      canvas.addEventListener(type, (event) => {
        const { body, point } = event.detail;
        log.push({ type, body: body === null ? null : body.userData, x: point.x, y: point.y });
      });
    }
    (window as unknown as { log: typeof log }).log = log;
  });
  await waitFrames(page);
  return page;
}

type Log = { type: string; body: unknown; x: number; y: number }[];

test('input: a tap on a body fires bodypress, bodyrelease and bodytap with that body', async ({
  open,
}) => {
  const page = await setUp(open);
  await page.mouse.click(120 + 10, 80 - 5);
  const log = await page.evaluate(() => (window as unknown as { log: Log }).log);
  assert.deepEqual(
    log.map((entry) => [entry.type, entry.body]),
    [
      ['bodypress', 'target'],
      ['bodyrelease', 'target'],
      ['bodytap', 'target'],
    ],
  );
  assert.ok(Math.abs(log[2]!.x - 3.25) < 1e-9 && Math.abs(log[2]!.y - 1.875) < 1e-9);
});

test('input: a tap on empty space fires backgroundtap with the world point', async ({ open }) => {
  const page = await setUp(open);
  await page.mouse.click(300, 40);
  const log = await page.evaluate(() => (window as unknown as { log: Log }).log);
  assert.deepEqual(log, [{ type: 'backgroundtap', body: null, x: 7.5, y: 1 }]);
  const mapped = await page.evaluate(() =>
    document.querySelector('physical-canvas')!.screenToWorld({ x: 300, y: 40 }),
  );
  assert.deepEqual(mapped, { x: 7.5, y: 1 });
});

test('input: a touch tap hits the body; a drag is a press and release but no tap', async ({
  open,
}) => {
  const page = await setUp(open, true);
  await page.touchscreen.tap(120, 80);
  await page.mouse.move(120, 80);
  await page.mouse.down();
  await page.mouse.move(180, 150, { steps: 4 });
  await page.mouse.up();
  const log = await page.evaluate(() => (window as unknown as { log: Log }).log);
  assert.deepEqual(
    log.map((entry) => [entry.type, entry.body]),
    [
      ['bodypress', 'target'],
      ['bodyrelease', 'target'],
      ['bodytap', 'target'],
      ['bodypress', 'target'],
      ['bodyrelease', 'target'],
    ],
  );
  assert.deepEqual([log[4]!.x, log[4]!.y], [4.5, 3.75]);
});

test('accessibility: focusable, labelled, Space toggles paused', async ({ open }) => {
  const page = await open('/canvas/fixture.html');
  const attributes = await page.evaluate(() => {
    const canvas = document.querySelector('physical-canvas')!;
    return [canvas.tabIndex, canvas.getAttribute('role'), canvas.getAttribute('aria-label')];
  });
  assert.deepEqual(attributes, [0, 'img', 'Physics simulation']);
  await page.keyboard.press('Tab');
  await page.keyboard.press(' ');
  assert.equal(await page.evaluate(() => document.querySelector('physical-canvas')!.paused), true);
  await page.keyboard.press(' ');
  assert.equal(await page.evaluate(() => document.querySelector('physical-canvas')!.paused), false);
});
