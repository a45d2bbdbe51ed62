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

  // Back to visible, then sample the step count and the frame's timestamp at each of the next
  // frames. The element's loop asked for its frame first, so it has stepped when ours runs.
  const frames = await page.evaluate(async () => {
    Object.defineProperty(document, 'visibilityState', {
      configurable: true,
      get: () => 'visible',
    });
    Object.defineProperty(document, 'hidden', { configurable: true, get: () => false });
    const world = document.querySelector('physical-canvas')!.world!;
    let last = world.steps;
    document.dispatchEvent(new Event('visibilitychange'));
    const increments: number[] = [];
    const times: number[] = [];
    for (let i = 0; i < 6; i++) {
      times.push(await new Promise<number>((resolve) => requestAnimationFrame(resolve)));
      increments.push(world.steps - last);
      last = world.steps;
    }
    return { increments, times };
  });
  // A jump would count the 600 ms away (36 steps, or the cap of 4 in the first frame). Instead the
  // first frame back counts no time, and after it the steps taken match the frames' own time
  // (1/60 s a step, one more for the accumulator's rounding), however slow the machine's frames.
  const { increments, times } = frames;
  const seen = increments.join(', ');
  assert.equal(increments[0], 0, `steps per frame after resuming: ${seen}`);
  const elapsedMs = times[times.length - 1]! - times[0]!;
  const taken = increments.reduce((a, b) => a + b);
  assert.ok(
    taken <= Math.floor(elapsedMs / (1000 / 60)) + 1,
    `${taken} steps in ${elapsedMs.toFixed(1)} ms of frames after resuming: ${seen}`,
  );
  assert.ok(taken >= 3, `steps per frame: ${seen}`);
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
