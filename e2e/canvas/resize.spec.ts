import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import type {} from './fixture-api.ts';
import { waitFrames } from './page-helpers.ts';

test('resize: with fit="none" the scale and the origin stay; the backing store follows', async ({
  open,
}) => {
  const page = await open('/canvas/fixture.html', {
    viewport: { width: 800, height: 600 },
    deviceScaleFactor: 2,
  });
  await page.evaluate(() => {
    const { World } = window.physical;
    const canvas = document.querySelector('physical-canvas')!;
    canvas.setAttribute('pixels-per-meter', '40');
    canvas.setAttribute('origin', '1 2');
    canvas.world = new World();
  });
  await waitFrames(page);
  const before = await page.evaluate(() => {
    const canvas = document.querySelector('physical-canvas')!;
    return { viewport: canvas.viewport, screen: canvas.worldToScreen({ x: 3, y: 4 }) };
  });
  await page.evaluate(() => {
    const canvas = document.querySelector('physical-canvas')!;
    canvas.style.width = '640px';
    canvas.style.height = '200px';
  });
  await waitFrames(page, 3);
  const after = await page.evaluate(() => {
    const canvas = document.querySelector('physical-canvas')!;
    const backing = canvas.shadowRoot!.querySelector('canvas')!;
    return {
      viewport: canvas.viewport,
      screen: canvas.worldToScreen({ x: 3, y: 4 }),
      backing: [backing.width, backing.height],
    };
  });
  assert.deepEqual(before.viewport, {
    width: 400,
    height: 300,
    devicePixelRatio: 2,
    scale: 40,
    originX: 1,
    originY: 2,
  });
  assert.deepEqual(after.viewport, {
    width: 640,
    height: 200,
    devicePixelRatio: 2,
    scale: 40,
    originX: 1,
    originY: 2,
  });
  assert.deepEqual(after.screen, before.screen);
  assert.deepEqual(after.backing, [1280, 400]);
});

test('resize: with fit="contain" the view box stays whole and centred', async ({ open }) => {
  const page = await open('/canvas/fixture.html', { viewport: { width: 1000, height: 600 } });
  await page.evaluate(() => {
    const { World } = window.physical;
    const canvas = document.querySelector('physical-canvas')!;
    canvas.fit = 'contain';
    canvas.viewBox = { x: 0, y: 0, width: 10, height: 5 };
    canvas.world = new World();
  });
  const measure = () =>
    page.evaluate(() => {
      const canvas = document.querySelector('physical-canvas')!;
      return {
        scale: canvas.viewport.scale,
        center: canvas.worldToScreen({ x: 5, y: 2.5 }),
        topLeft: canvas.worldToScreen({ x: 0, y: 0 }),
        bottomRight: canvas.worldToScreen({ x: 10, y: 5 }),
      };
    });
  await waitFrames(page);
  const wide = await measure();
  assert.equal(wide.scale, 40); // 400 x 300: width limits, 400 / 10
  assert.deepEqual(wide.center, { x: 200, y: 150 });
  assert.deepEqual(
    [wide.topLeft, wide.bottomRight],
    [
      { x: 0, y: 50 },
      { x: 400, y: 250 },
    ],
  );
  await page.evaluate(() => {
    const canvas = document.querySelector('physical-canvas')!;
    canvas.style.width = '900px';
  });
  await waitFrames(page, 3);
  const tall = await measure();
  assert.equal(tall.scale, 60); // 900 x 300: height limits, 300 / 5
  assert.deepEqual(tall.center, { x: 450, y: 150 });
  assert.deepEqual(
    [tall.topLeft, tall.bottomRight],
    [
      { x: 150, y: 0 },
      { x: 750, y: 300 },
    ],
  );

  await page.evaluate(() => {
    document.querySelector('physical-canvas')!.fit = 'cover';
  });
  const cover = await measure();
  assert.equal(cover.scale, 90); // 900 / 10: the box fills the width, cropped top and bottom
  assert.deepEqual(cover.center, { x: 450, y: 150 });
});

test('resize: max-pixel-ratio caps the backing store on a 3x screen; world points stay where they were', async ({
  open,
}) => {
  const page = await open('/canvas/fixture.html', {
    viewport: { width: 800, height: 600 },
    deviceScaleFactor: 3,
  });
  const read = () =>
    page.evaluate(() => {
      const canvas = document.querySelector('physical-canvas')!;
      const backing = canvas.shadowRoot!.querySelector('canvas')!;
      return {
        ratio: canvas.viewport.devicePixelRatio,
        backing: [backing.width, backing.height],
        css: [backing.clientWidth, backing.clientHeight],
        screen: canvas.worldToScreen({ x: 3, y: 4 }),
      };
    });
  await page.evaluate(() => {
    const { World } = window.physical;
    const canvas = document.querySelector('physical-canvas')!;
    canvas.setAttribute('pixels-per-meter', '40');
    canvas.world = new World();
  });
  await waitFrames(page);
  const full = await read();
  assert.equal(full.ratio, 3);
  assert.deepEqual(full.backing, [3 * full.css[0]!, 3 * full.css[1]!]);
  await page.evaluate(() => {
    document.querySelector('physical-canvas')!.maxPixelRatio = 1.5;
  });
  await waitFrames(page, 3);
  const capped = await read();
  assert.equal(capped.ratio, 1.5);
  assert.deepEqual(capped.backing, [1.5 * full.css[0]!, 1.5 * full.css[1]!]);
  assert.deepEqual(capped.screen, full.screen, 'CSS-pixel mapping unchanged');
  assert.equal(
    await page.evaluate(() =>
      document.querySelector('physical-canvas')!.getAttribute('max-pixel-ratio'),
    ),
    '1.5',
  );
});
