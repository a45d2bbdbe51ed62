import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import { waitFrames } from '../canvas/page-helpers.ts';

const name = 'react: <PhysicalCanvas> under StrictMode taps once per tap and subscribes once';
test(name, async ({ open }) => {
  const page = await open('/react/fixture.html', { viewport: { width: 400, height: 300 } });
  await waitFrames(page, 3);
  await page.mouse.click(120, 80);
  await page.mouse.click(300, 40);
  const result = await page.evaluate(() => {
    const state = window as unknown as { taps: unknown[]; background: unknown[] };
    const canvas = document.querySelector('physical-canvas')!;
    return {
      taps: state.taps,
      background: state.background,
      ppm: canvas.pixelsPerMeter,
      hasWorld: canvas.world !== null,
    };
  });
  assert.deepEqual(result, {
    taps: [true],
    background: [{ x: 7.5, y: 1 }],
    ppm: 40,
    hasWorld: true,
  });
});
