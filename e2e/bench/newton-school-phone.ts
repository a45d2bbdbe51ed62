// Newton on a school phone: with Lighthouse's Slow 4G (150 ms round trip, 1.6 Mbit/s down,
// 750 kbit/s up) and 4x CPU slowdown, the time from navigation until the first screen answers a
// tap (Apply force pressed and shown as pressed), from a cold cache; and the frame rate of
// Reactions with 50 particles at 4x CPU slowdown, tilted by a phone in the hand (readings 60
// times a second, never quite still). Targets: a tap answered within 3 s, 50 frames/s
// or more. Figures, not a test (speed lives in measurements; the machine may be shared).
// Beside the wall time, each load's main-thread CPU time until the tap is answered (the thread
// time of the page's top-level tasks in a trace): on a shared machine the wall time follows the
// load average, this much less. Both are printed with the load average before and after.
// Usage: npm run bench:newton (builds the app, then runs this); RUNS=N sets the cold loads (5).
import { loadavg } from 'node:os';
import { chromium, type CDPSession } from 'playwright-core';
import { CHROMIUM_LAUNCH } from '../chromium.ts';
import { startPreviewServer } from '../newton/app-server.ts';
import { PHONE } from '../newton/phone.ts';

// Lighthouse's mobile throttling ("Slow 4G"): 150 ms round trip, 1.6 Mbit/s down, 750 kbit/s up.
const SLOW_4G = {
  offline: false,
  latency: 150,
  downloadThroughput: 1.6e6 / 8,
  uploadThroughput: 750e3 / 8,
};
const CPU_SLOWDOWN = 4;
// When Apply force first shows as pressed (the tap's answer), in ms since navigation.
const ANSWERED_AT = `
  new MutationObserver((_records, observer) => {
    if (document.querySelector('[data-action="toggle-force"][aria-pressed="true"]')) {
      window.__answeredAt = performance.now();
      observer.disconnect();
    }
  }).observe(document, { subtree: true, childList: true, attributes: true });
`;
const RUNS = Number(process.env['RUNS'] ?? 5);
const median = (values: number[]): number => [...values].sort((a, b) => a - b)[values.length >> 1]!;
const load = (): string =>
  loadavg()
    .map((value) => value.toFixed(1))
    .join(', ');

interface TraceEvent {
  name: string;
  ph: string;
  pid: number;
  tid: number;
  tdur?: number;
  args?: { name?: string; beginData?: { url?: string } };
}

/** Starts a trace of the timeline (its top-level tasks carry their thread time). */
async function startTrace(cdp: CDPSession): Promise<() => Promise<TraceEvent[]>> {
  const events: TraceEvent[] = [];
  cdp.on('Tracing.dataCollected', (data) => {
    events.push(...(data.value as unknown as TraceEvent[]));
  });
  const done = new Promise<void>((resolve) => cdp.once('Tracing.tracingComplete', () => resolve()));
  await cdp.send('Tracing.start', {
    categories: 'devtools.timeline,disabled-by-default-devtools.timeline',
    transferMode: 'ReportEvents',
  });
  return async () => {
    await cdp.send('Tracing.end');
    await done;
    return events;
  };
}

/** Thread CPU time (ms) of the top-level tasks on the main thread of the renderer that parsed `url`. */
function mainThreadCpu(events: TraceEvent[], url: string): number {
  const parser = events.find(
    (event) => event.name === 'ParseHTML' && (event.args?.beginData?.url ?? '').startsWith(url),
  );
  if (parser === undefined) return Number.NaN;
  let total = 0;
  for (const event of events) {
    if (event.pid !== parser.pid || event.tid !== parser.tid) continue;
    if (event.ph === 'X' && event.name === 'RunTask') total += (event.tdur ?? 0) / 1000;
  }
  return total;
}

const server = await startPreviewServer();
const browser = await chromium.launch(CHROMIUM_LAUNCH);
const loadBefore = load();
try {
  const fcps: number[] = [];
  const answers: number[] = [];
  const cpus: number[] = [];
  for (let run = 0; run < RUNS; run++) {
    const context = await browser.newContext({ ...PHONE, serviceWorkers: 'block' });
    await context.addInitScript(ANSWERED_AT);
    const page = await context.newPage();
    const cdp = await context.newCDPSession(page);
    await cdp.send('Network.enable');
    await cdp.send('Network.setCacheDisabled', { cacheDisabled: true });
    await cdp.send('Network.emulateNetworkConditions', SLOW_4G);
    await cdp.send('Emulation.setCPUThrottlingRate', { rate: CPU_SLOWDOWN });
    const stopTrace = await startTrace(cdp);
    await page.goto(`${server.url}/#inertia`, { waitUntil: 'commit' });
    // The learner taps Apply force as soon as it is on the screen (Playwright waits until it is
    // visible, stable and enabled), then the page answers by showing it pressed.
    await page.locator('#inertia [data-action="toggle-force"]').tap({ timeout: 60_000 });
    await page.waitForFunction(
      () => (window as unknown as { __answeredAt?: number }).__answeredAt !== undefined,
      undefined,
      { timeout: 60_000 },
    );
    const { fcp, answered } = await page.evaluate(() => ({
      fcp: performance.getEntriesByName('first-contentful-paint')[0]?.startTime ?? NaN,
      answered: (window as unknown as { __answeredAt: number }).__answeredAt,
    }));
    cpus.push(mainThreadCpu(await stopTrace(), server.url));
    fcps.push(fcp);
    answers.push(answered);
    await context.close();
  }
  const answer = median(answers);
  process.stdout.write(
    `cold load, Slow 4G (150 ms, 1.6 Mbit/s) + ${CPU_SLOWDOWN}x CPU, ${RUNS} runs: ` +
      `first contentful paint median ${Math.round(median(fcps))} ms (${fcps.map(Math.round).join(', ')}); ` +
      `first tap answered median ${Math.round(answer)} ms (${answers.map(Math.round).join(', ')}), ` +
      `target 3000 ms: ${answer <= 3000 ? 'met' : 'MISSED'}; ` +
      `main-thread CPU until then median ${Math.round(median(cpus))} ms (${cpus.map(Math.round).join(', ')}); ` +
      `load average ${loadBefore} before, ${load()} after (2 cores)\n`,
  );

  const context = await browser.newContext(PHONE);
  await context.addInitScript(
    'window.__frames = 0; const raf = window.requestAnimationFrame.bind(window); window.requestAnimationFrame = (cb) => raf((t) => { window.__frames++; cb(t); });',
  );
  const page = await context.newPage();
  await page.goto(`${server.url}/#reactions`);
  await page.waitForFunction(() => document.documentElement.dataset['ready'] === 'true');
  await page.locator('#reactions [data-action="add"]').focus();
  for (let i = 0; i < 50; i++) await page.keyboard.press('Enter');
  const cdp = await context.newCDPSession(page);
  await cdp.send('Emulation.setCPUThrottlingRate', { rate: CPU_SLOWDOWN });
  // A phone in the hand: its sensor reports 60 times a second, each reading a little off the
  // last (a hand is never still: +-0.5 degrees here), so the tray's gravity changes in almost
  // every step. Turned to a new lean for each window below.
  await page.evaluate(() => {
    const lean = { beta: 0, gamma: 0 };
    (window as unknown as { __lean: typeof lean }).__lean = lean;
    setInterval(() => {
      window.dispatchEvent(
        new DeviceOrientationEvent('deviceorientation', {
          alpha: 0,
          beta: lean.beta + Math.random() - 0.5,
          gamma: lean.gamma + Math.random() - 0.5,
        }),
      );
    }, 1000 / 60);
  });
  const rates: number[] = [];
  for (let i = 0; i < 4; i++) {
    // Keep them moving: the lean turns for each window.
    await page.evaluate((k) => {
      const lean = (window as unknown as { __lean: { beta: number; gamma: number } }).__lean;
      lean.beta = [40, 0, -40, 0][k % 4]!;
      lean.gamma = [0, 40, 0, -40][k % 4]!;
    }, i);
    const before = await page.evaluate(() => (window as unknown as { __frames: number }).__frames);
    const started = Date.now();
    await new Promise((resolve) => setTimeout(resolve, 1500));
    const after = await page.evaluate(() => (window as unknown as { __frames: number }).__frames);
    rates.push(((after - before) * 1000) / (Date.now() - started));
  }
  const count = await page.locator('[data-readout="count"]').textContent();
  process.stdout.write(
    `Reactions, ${count} particles, ${CPU_SLOWDOWN}x CPU: ${rates.map((r) => r.toFixed(0)).join(', ')} frames/s ` +
      `(median ${median(rates).toFixed(0)}), target 50: ${median(rates) >= 50 ? 'met' : 'MISSED'}; ` +
      `load average ${load()} (2 cores)\n`,
  );
  await context.close();
} finally {
  await browser.close();
  await server.close();
}
