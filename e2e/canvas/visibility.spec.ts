import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import type {} from './fixture-api.ts';
import { waitFrames } from './page-helpers.ts';

// Page visibility is simulated: headless Chromium never hides its page, so the test overrides
// document.visibilityState and sends the visibilitychange event the browser would send.
test('visibility: a hidden page takes no steps, and resumes without a jump', async ({ open }) => {
  const page = await open('/canvas/fixture.html');
  await page.evaluate(() => {
    const { World, box } = window.physical;
    const canvas = document.querySelector('physical-canvas')!;
    const world = new World({ gravity: { x: 0, y: 1 } });
    world.add(box({ position: { x: 3, y: 1 }, width: 1, height: 1 }));
    canvas.world = world;
  });
  await waitFrames(page, 10);
  const setHidden = (hidden: boolean) =>
    page.evaluate((isHidden) => {
      Object.defineProperty(document, 'visibilityState', {
        configurable: true,
        get: () => (isHidden ? 'hidden' : 'visible'),
      });
      Object.defineProperty(document, 'hidden', { configurable: true, get: () => isHidden });
      document.dispatchEvent(new Event('visibilitychange'));
    }, hidden);
  await setHidden(true);
  const hidden = await page.evaluate(async () => {
    const canvas = document.querySelector('physical-canvas')!;
    const world = canvas.world!;
    const steps = world.steps;
    const y = world.bodies[0]!.position.y;
    await new Promise((resolve) => setTimeout(resolve, 600));
    return {
      steps: world.steps - steps,
      running: canvas.isRunning,
      y,
      y2: world.bodies[0]!.position.y,
    };
  });
  assert.deepEqual([hidden.steps, hidden.running, hidden.y2], [0, false, hidden.y]);

  // Back to visible, then sample the step count at each of the next frames.
  const perFrame = await page.evaluate(async () => {
    Object.defineProperty(document, 'visibilityState', {
      configurable: true,
      get: () => 'visible',
    });
    Object.defineProperty(document, 'hidden', { configurable: true, get: () => false });
    const world = document.querySelector('physical-canvas')!.world!;
    let last = world.steps;
    document.dispatchEvent(new Event('visibilitychange'));
    const increments: number[] = [];
    for (let i = 0; i < 6; i++) {
      await new Promise((resolve) => requestAnimationFrame(resolve));
      increments.push(world.steps - last);
      last = world.steps;
    }
    return increments;
  });
  // 600 ms away would be 36 steps (or the cap of 4 in one frame): the first frame back counts no
  // time, the next ones a frame's worth each, and the simulation goes on.
  assert.ok(Math.max(...perFrame) <= 2, `steps per frame after resuming: ${perFrame.join(', ')}`);
  assert.ok(perFrame.reduce((a, b) => a + b) >= 3, `steps per frame: ${perFrame.join(', ')}`);
});

test('visibility: scrolled out of view, the element stops; back in view, it runs', async ({
  open,
}) => {
  const page = await open('/canvas/fixture.html', { viewport: { width: 400, height: 300 } });
  await page.evaluate(() => {
    const { World, box } = window.physical;
    document.body.style.height = '5000px';
    const canvas = document.querySelector('physical-canvas')!;
    const world = new World({ gravity: { x: 0, y: 0.1 } });
    world.add(box({ position: { x: 3, y: 1 }, width: 1, height: 1 }));
    canvas.world = world;
  });
  await waitFrames(page, 3);
  await page.evaluate(() => window.scrollTo(0, 2000));
  await waitFrames(page, 3);
  const away = await page.evaluate(async () => {
    const canvas = document.querySelector('physical-canvas')!;
    const steps = canvas.world!.steps;
    await new Promise((resolve) => setTimeout(resolve, 300));
    return { steps: canvas.world!.steps - steps, running: canvas.isRunning };
  });
  assert.deepEqual(away, { steps: 0, running: false });
  await page.evaluate(() => window.scrollTo(0, 0));
  await waitFrames(page, 5);
  assert.equal(
    await page.evaluate(() => document.querySelector('physical-canvas')!.isRunning),
    true,
  );
});
