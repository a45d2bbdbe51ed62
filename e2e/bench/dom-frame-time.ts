// Measures @physical/dom in headless Chromium: 200 physical elements falling into an 800x600
// container. Prints the median and 95th percentile of the script time per frame (one 1/60 s step
// plus the transform writes, timed in the page), the median interval between real animation
// frames, the main thread's time per frame (script, style, paint: Chrome's TaskDuration), and
// the layouts and layout reads made during the frames (both must be 0).
// Usage: npm run bench:dom  (tsx e2e/bench/dom-frame-time.ts [count])
import { chromium } from 'playwright-core';
import { startServer } from '../server.ts';
import { COUNT_LAYOUT_READS } from '../dom/layout-reads.ts';
import { CHROMIUM_LAUNCH } from '../chromium.ts';

const count = Number(process.argv[2] ?? 200);
const server = await startServer();
const browser = await chromium.launch(CHROMIUM_LAUNCH);
try {
  const context = await browser.newContext({ viewport: { width: 800, height: 600 } });
  await context.addInitScript('globalThis.__name = (target) => target;');
  await context.addInitScript(COUNT_LAYOUT_READS);
  const page = await context.newPage();
  await page.goto(`${server.url}/dom/fixture.html`);
  await page.waitForFunction(() => document.documentElement.dataset['ready'] === 'true');

  // 1. Script time per frame, driven by a manual scheduler: 30 frames of warm-up, then 300.
  const script = await page.evaluate(async (n) => {
    const { PhysicalUI, ManualFrameScheduler, fill } = window.dom;
    const scheduler = new ManualFrameScheduler(performance.now());
    const ui = new PhysicalUI(fill(n), { released: true, frameScheduler: scheduler });
    scheduler.advance(0);
    const times: number[] = [];
    for (let i = 0; i < 330; i++) {
      const start = performance.now();
      scheduler.advance(1000 / 60);
      if (i >= 30) times.push(performance.now() - start);
      if (i % 30 === 0) await new Promise((resolve) => setTimeout(resolve, 0));
    }
    ui.destroy();
    document.getElementById('box')!.replaceChildren();
    times.sort((a, b) => a - b);
    return { median: times[150]!, p95: times[285]! };
  }, count);

  // 2. Real frames: a fresh pile falling with requestAnimationFrame, watched by Chrome's metrics.
  await page.evaluate((n) => {
    const { PhysicalUI, fill } = window.dom;
    Object.assign(window, { ui: new PhysicalUI(fill(n), { released: true }) });
  }, count);
  const session = await context.newCDPSession(page);
  await session.send('Performance.enable');
  const metrics = async () => {
    const { metrics } = await session.send('Performance.getMetrics');
    const value = (name: string) => metrics.find((entry) => entry.name === name)?.value ?? NaN;
    return { task: value('TaskDuration'), layouts: value('LayoutCount') };
  };
  await page.waitForTimeout(200);
  const before = await metrics();
  const real = await page.evaluate(
    () =>
      new Promise<{ intervals: number[]; reads: number; frames: number }>((resolve) => {
        const intervals: number[] = [];
        let last = -1;
        const counters = window as unknown as { layoutReads: number; frameCallbacks: number };
        const reads0 = counters.layoutReads;
        const tick = (time: number): void => {
          if (last >= 0) intervals.push(time - last);
          last = time;
          if (intervals.length < 180) requestAnimationFrame(tick);
          else
            resolve({ intervals, reads: counters.layoutReads - reads0, frames: intervals.length });
        };
        requestAnimationFrame(tick);
      }),
  );
  const after = await metrics();
  const intervals = [...real.intervals].sort((a, b) => a - b);
  const median = intervals[Math.floor(intervals.length / 2)]!;
  const perFrame = ((after.task - before.task) * 1000) / real.frames;
  process.stdout.write(
    `${count} physical elements falling in an 800x600 container, dpr 1, 1/60 s steps:\n` +
      `  script per frame (step + transform writes): median ${script.median.toFixed(2)} ms, p95 ${script.p95.toFixed(2)} ms (330 frames, manual clock)\n` +
      `  real frames (${real.frames}): median interval ${median.toFixed(2)} ms, main-thread time ${perFrame.toFixed(2)} ms per frame\n` +
      `  layouts during frames: ${after.layouts - before.layouts}, layout reads inside frame callbacks: ${real.reads}\n`,
  );
} finally {
  await browser.close();
  await server.close();
}
