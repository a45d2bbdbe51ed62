import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import type {} from './fixture-api.ts';
import { RAF_COUNTER, waitFrames } from './page-helpers.ts';

test('sleep: once every body sleeps, no animation frames are requested; a change wakes it', async ({
  open,
}) => {
  const page = await open('/canvas/fixture.html', {}, RAF_COUNTER);
  await page.evaluate(() => {
    const { World, box, wall } = window.physical;
    const canvas = document.querySelector('physical-canvas')!;
    const world = new World();
    world.add(wall({ from: { x: 0, y: 5 }, to: { x: 8, y: 5 } }));
    world.add(box({ position: { x: 3, y: 4.4 }, width: 1, height: 1 }));
    world.add(box({ position: { x: 5, y: 3 }, width: 1, height: 1 }));
    canvas.world = world;
  });
  await page.waitForFunction(
    () => {
      const canvas = document.querySelector('physical-canvas')!;
      return canvas.world!.awakeBodyCount === 0 && !canvas.isRunning;
    },
    undefined,
    { timeout: 10_000 },
  );
  const idle = await page.evaluate(async () => {
    const canvas = document.querySelector('physical-canvas')!;
    const requests = window.frameRequests!;
    const frames = canvas.frameCount;
    await new Promise((resolve) => setTimeout(resolve, 1000));
    return { requests: window.frameRequests! - requests, frames: canvas.frameCount - frames };
  });
  assert.deepEqual(idle, { requests: 0, frames: 0 });

  await page.evaluate(() => {
    const { box } = window.physical;
    const canvas = document.querySelector('physical-canvas')!;
    canvas.world!.add(box({ position: { x: 3, y: 1 }, width: 1, height: 1 }));
  });
  await waitFrames(page, 5);
  const woken = await page.evaluate(() => document.querySelector('physical-canvas')!.isRunning);
  assert.equal(woken, true);
});
