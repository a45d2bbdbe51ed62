import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import type {} from './fixture-api.ts';
import { screenPixels, waitFrames } from './page-helpers.ts';

// A 2 m x 1 m red box centred at (3, 2) m, at 40 CSS px/m from origin (0, 0), must cover CSS px
// x 80..160, y 60..100: device px times the devicePixelRatio, on screen and in the backing store.
for (const ratio of [1, 2, 3]) {
  test(`painting: a box at a known world position lands on the expected device pixels (dpr ${ratio})`, async ({
    open,
  }) => {
    const page = await open('/canvas/fixture.html', {
      viewport: { width: 400, height: 300 },
      deviceScaleFactor: ratio,
    });
    const store = await page.evaluate(() => {
      const { World, box } = window.physical;
      const canvas = document.querySelector('physical-canvas')!;
      canvas.pixelsPerMeter = 40;
      canvas.background = '#000000';
      const world = new World();
      const body = world.add(
        box({ type: 'static', position: { x: 3, y: 2 }, width: 2, height: 1 }),
      );
      canvas.setStyle(body, { fill: '#ff0000', stroke: 'transparent' });
      canvas.world = world;
      const backing = canvas.shadowRoot!.querySelector('canvas')!;
      return { width: backing.width, height: backing.height };
    });
    await waitFrames(page, 3);
    const size = await page.evaluate(() => {
      const backing = document
        .querySelector('physical-canvas')!
        .shadowRoot!.querySelector('canvas')!;
      return { width: backing.width, height: backing.height };
    });
    assert.deepEqual(
      size,
      { width: 400 * ratio, height: 300 * ratio },
      `backing store ${JSON.stringify(store)}`,
    );

    const [left, top, right, bottom] = [80 * ratio, 60 * ratio, 160 * ratio, 100 * ratio];
    const inside = [
      { x: left, y: top },
      { x: right - 1, y: top },
      { x: left, y: bottom - 1 },
      { x: right - 1, y: bottom - 1 },
      { x: (left + right) / 2, y: (top + bottom) / 2 },
    ];
    const outside = [
      { x: left - 1, y: top },
      { x: left, y: top - 1 },
      { x: right, y: bottom - 1 },
      { x: right - 1, y: bottom },
    ];
    const backingPixels = await page.evaluate(
      (points) => {
        const backing = document
          .querySelector('physical-canvas')!
          .shadowRoot!.querySelector('canvas')!;
        const context = backing.getContext('2d')!;
        return points.map(({ x, y }) => Array.from(context.getImageData(x, y, 1, 1).data));
      },
      [...inside, ...outside],
    );
    const shown = await screenPixels(page, [...inside, ...outside]);
    for (const [where, pixels] of [
      ['backing store', backingPixels],
      ['screen', shown],
    ] as const) {
      inside.forEach((point, i) =>
        assert.deepEqual(pixels[i], [255, 0, 0, 255], `${where}: ${JSON.stringify(point)} inside`),
      );
      outside.forEach((point, i) =>
        assert.deepEqual(
          pixels[inside.length + i],
          [0, 0, 0, 255],
          `${where}: ${JSON.stringify(point)} outside`,
        ),
      );
    }
  });
}
