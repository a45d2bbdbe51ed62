import { ManualFrameScheduler, define } from '@physical/canvas';
import { movingBoxes, settlingPile } from './scenes.ts';

define();

/** Median and 95th percentile of a list (ms). */
function summary(times: number[]): { median: number; p95: number } {
  const sorted = [...times].sort((a, b) => a - b);
  return {
    median: sorted[Math.floor(sorted.length / 2)]!,
    p95: sorted[Math.floor(sorted.length * 0.95)]!,
  };
}

/**
 * Frame time of 1,000 moving boxes: each frame is one 1/60 s step plus a full redraw, driven by a
 * manual scheduler and timed with performance.now; a 1-pixel read-back after each frame makes the
 * canvas finish rasterising inside the measured time.
 */
async function frameTimes(
  overlays: boolean,
  frames = 300,
): Promise<{ median: number; p95: number }> {
  const canvas = document.querySelector('physical-canvas')!;
  const scheduler = new ManualFrameScheduler(performance.now());
  canvas.frameScheduler = scheduler;
  canvas.debug = overlays ? 'all' : '';
  canvas.collisionArrows = overlays;
  canvas.world = movingBoxes();
  const context = canvas.shadowRoot!.querySelector('canvas')!.getContext('2d')!;
  scheduler.advance(0);
  const times: number[] = [];
  for (let i = 0; i < frames + 30; i++) {
    const start = performance.now();
    scheduler.advance(1000 / 60);
    context.getImageData(0, 0, 1, 1);
    if (i >= 30) times.push(performance.now() - start); // 30 frames of warm-up
    if (i % 30 === 0) await new Promise((resolve) => setTimeout(resolve, 0));
  }
  canvas.world = null;
  return summary(times);
}

/** Lets a pile settle with the real requestAnimationFrame; resolves when every body sleeps. */
async function settle(): Promise<number> {
  const canvas = document.querySelector('physical-canvas')!;
  canvas.frameScheduler = null;
  canvas.debug = '';
  canvas.collisionArrows = false;
  const world = settlingPile();
  canvas.world = world;
  const start = performance.now();
  while (world.awakeBodyCount > 0 || canvas.isRunning) {
    await new Promise((resolve) => setTimeout(resolve, 100));
    if (performance.now() - start > 30_000)
      throw new Error('the pile did not come to rest in 30 s');
  }
  return (performance.now() - start) / 1000;
}

Object.assign(window, { bench: { frameTimes, settle } });
document.documentElement.dataset['ready'] = 'true';
