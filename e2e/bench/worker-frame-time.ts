// Measures @physical/worker in headless Chromium: 2,000 boxes falling into a pile, 800x600 CSS px
// at DPR 2, drawn by <physical-canvas> with a real animation-frame loop. For the world on the
// page and in a worker, with and without cross-origin isolation: main-thread time per frame
// (CDP TaskDuration over the frames drawn), frames and steps per second, tap-to-move latency and
// pose bytes per frame.
// Usage: tsx e2e/bench/worker-frame-time.ts [seconds per run, default 5]
import { chromium } from 'playwright-core';
import { startServer } from '../server.ts';
import { CHROMIUM_LAUNCH } from '../chromium.ts';

interface Bench {
  start(where: 'page' | 'worker' | 'offscreen'): { shared: boolean };
  counters(): { frames: number; steps: number; bytes: number };
  armTap(): void;
  tapLatency(): Promise<number>;
}

const seconds = Number(process.argv[2] ?? 5);
const server = await startServer();
const browser = await chromium.launch(CHROMIUM_LAUNCH);

const median = (values: number[]): number => {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)] ?? Number.NaN;
};

async function measure(where: 'page' | 'worker' | 'offscreen', isolated: boolean): Promise<string> {
  const context = await browser.newContext({
    viewport: { width: 800, height: 600 },
    deviceScaleFactor: 2,
  });
  await context.addInitScript('globalThis.__name = (target) => target;');
  const page = await context.newPage();
  await page.goto(`${server.url}/bench/worker-bench.html${isolated ? '?coi' : ''}`);
  await page.waitForFunction(() => document.documentElement.dataset['ready'] === 'true');
  const session = await context.newCDPSession(page);
  await session.send('Performance.enable');
  const metric = async (name: string): Promise<number> => {
    const { metrics } = await session.send('Performance.getMetrics');
    return metrics.find((entry) => entry.name === name)?.value ?? Number.NaN;
  };
  const taskSeconds = (): Promise<number> => metric('TaskDuration');
  const counters = (): Promise<{ frames: number; steps: number; bytes: number }> =>
    page.evaluate(() => (window as unknown as { bench: Bench }).bench.counters());
  const { shared } = await page.evaluate(
    (w) => (window as unknown as { bench: Bench }).bench.start(w),
    where,
  );
  // The worker loads its modules first: measure from its first step on.
  await page.waitForFunction(
    () => (window as unknown as { bench: Bench }).bench.counters().steps > 0,
    undefined,
    { timeout: 60_000 },
  );
  await page.waitForTimeout(500);
  process.stderr.write(`  (${where} started)\n`);
  const c0 = await counters();
  const t0 = await taskSeconds();
  const s0 = await metric('ScriptDuration');
  const w0 = performance.now();
  await page.waitForTimeout(seconds * 1000);
  const t1 = await taskSeconds();
  const s1 = await metric('ScriptDuration');
  const w1 = performance.now();
  const c1 = await counters();
  const wall = (w1 - w0) / 1000;
  const frames = c1.frames - c0.frames;
  const steps = c1.steps - c0.steps;
  const perFrame = ((t1 - t0) * 1000) / frames;
  const scriptPerFrame = ((s1 - s0) * 1000) / frames;
  process.stderr.write(`  (${where}: ${frames} frames, ${steps} steps)\n`);
  // Taps on the pile, each after the last one's body has moved.
  const latencies: number[] = [];
  for (let i = 0; i < 7; i++) {
    await page.evaluate(() => (window as unknown as { bench: Bench }).bench.armTap());
    await page.mouse.click(400, 300);
    const pending = page.evaluate(() => (window as unknown as { bench: Bench }).bench.tapLatency());
    latencies.push(
      await Promise.race([
        pending,
        new Promise<number>((r) => setTimeout(() => r(Infinity), 5000)),
      ]),
    );
    await page.waitForTimeout(200);
  }
  await context.close();
  const bytes = frames > 0 ? (c1.bytes - c0.bytes) / Math.max(1, steps) : 0;
  return (
    `${where === 'page' ? 'world on the page' : `world in a worker (${shared ? 'shared memory' : 'transferred poses'}${where === 'offscreen' ? ', drawn in the worker' : ''})`}, ` +
    `${isolated ? 'cross-origin isolated' : 'not isolated'}:\n` +
    `  main thread ${perFrame.toFixed(2)} ms/frame (script ${scriptPerFrame.toFixed(2)}), ${(frames / wall).toFixed(1)} fps, ` +
    `${(steps / wall).toFixed(1)} steps/s, tap-to-move median ${median(latencies).toFixed(1)} ms ` +
    `(${latencies.map((l) => l.toFixed(0)).join(', ')}), pose bytes/step ${bytes.toFixed(0)}\n`
  );
}

try {
  process.stdout.write(
    `2,000 boxes falling into a pile, 800x600 CSS px at DPR 2, rAF loop, ${seconds} s per run after 0.5 s:\n`,
  );
  for (const isolated of [false, true]) {
    for (const where of ['page', 'worker', 'offscreen'] as const) {
      process.stdout.write(await measure(where, isolated));
    }
  }
} finally {
  await browser.close();
  await server.close();
}
