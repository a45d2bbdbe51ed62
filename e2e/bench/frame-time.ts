// Measures @physical/canvas in headless Chromium: median frame time (step + draw) of 1,000 moving
// boxes with overlays off and on, and the main-thread CPU time of a page whose world sleeps.
// Usage: tsx e2e/bench/frame-time.ts
import { chromium } from 'playwright-core';
import { startServer } from '../server.ts';
import { CHROMIUM_LAUNCH } from '../chromium.ts';

interface Bench {
  frameTimes(overlays: boolean, frames?: number): Promise<{ median: number; p95: number }>;
  settle(): Promise<number>;
}

const server = await startServer();
const browser = await chromium.launch(CHROMIUM_LAUNCH);
try {
  const context = await browser.newContext({ viewport: { width: 800, height: 600 } });
  await context.addInitScript(`
    globalThis.__name = (target) => target;
    window.frameRequests = 0;
    const original = window.requestAnimationFrame.bind(window);
    window.requestAnimationFrame = (callback) => { window.frameRequests++; return original(callback); };
  `);
  const page = await context.newPage();
  await page.goto(`${server.url}/bench/bench.html`);
  await page.waitForFunction(() => document.documentElement.dataset['ready'] === 'true');
  const bench = (overlays: boolean) =>
    page.evaluate((on) => (window as unknown as { bench: Bench }).bench.frameTimes(on), overlays);
  const off = await bench(false);
  const on = await bench(true);
  const format = (t: { median: number; p95: number }) =>
    `median ${t.median.toFixed(2)} ms, p95 ${t.p95.toFixed(2)} ms`;
  process.stdout.write(
    `1,000 moving boxes, 800x600 CSS px at dpr 1, one 1/60 s step + draw per frame (300 frames):\n`,
  );
  process.stdout.write(`  overlays off: ${format(off)}\n`);
  process.stdout.write(`  overlays on (debug="all" + collision-arrows): ${format(on)}\n`);

  const seconds = await page.evaluate(() => (window as unknown as { bench: Bench }).bench.settle());
  const session = await context.newCDPSession(page);
  await session.send('Performance.enable');
  const metric = async (name: string): Promise<number> => {
    const { metrics } = await session.send('Performance.getMetrics');
    return metrics.find((entry) => entry.name === name)?.value ?? Number.NaN;
  };
  const idleSeconds = 10;
  const [task0, script0] = [await metric('TaskDuration'), await metric('ScriptDuration')];
  const frames0 = await page.evaluate(
    () => (window as unknown as { frameRequests: number }).frameRequests,
  );
  await new Promise((resolve) => setTimeout(resolve, idleSeconds * 1000));
  const [task1, script1] = [await metric('TaskDuration'), await metric('ScriptDuration')];
  const frames1 = await page.evaluate(
    () => (window as unknown as { frameRequests: number }).frameRequests,
  );
  process.stdout.write(
    `sleeping world (100-box pile, at rest after ${seconds.toFixed(1)} s), ${idleSeconds} s idle:\n` +
      `  main-thread task time ${(task1 - task0) * 1000 > 0 ? ((task1 - task0) * 1000).toFixed(1) : '0.0'} ms ` +
      `(${(((task1 - task0) / idleSeconds) * 100).toFixed(3)} % of one core), script ${((script1 - script0) * 1000).toFixed(1)} ms, ` +
      `animation frames requested: ${frames1 - frames0}\n`,
  );
} finally {
  await browser.close();
  await server.close();
}
