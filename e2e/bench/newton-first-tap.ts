// What Newton's first tap waits for on a school phone: one cold load of #inertia with
// Lighthouse's Slow 4G and 4x CPU (as npm run bench:newton), printed as a timeline in ms since
// navigation: each file on the wire (requested, first byte, last byte, bytes transferred), the
// main thread's tasks of 15 ms or more with the scripts they ran (evaluation, calls, the kernel's
// WebAssembly compile), when Apply force is first in the page and when the tap is answered.
// Usage: npm run build -w @physical/newton && tsx e2e/bench/newton-first-tap.ts [trace.json]
import { writeFileSync } from 'node:fs';
import { chromium } from 'playwright-core';
import { CHROMIUM_LAUNCH } from '../chromium.ts';
import { startPreviewServer } from '../newton/app-server.ts';
import { PHONE } from '../newton/phone.ts';

const SLOW_4G = {
  offline: false,
  latency: 150,
  downloadThroughput: 1.6e6 / 8,
  uploadThroughput: 750e3 / 8,
};
// When Apply force is first in the page, and when it first shows as pressed.
const MARKS = `
  new MutationObserver((_records, observer) => {
    const button = document.querySelector('[data-action="toggle-force"]');
    if (button && window.__shownAt === undefined) window.__shownAt = performance.now();
    if (button && button.getAttribute('aria-pressed') === 'true') {
      window.__answeredAt = performance.now();
      observer.disconnect();
    }
  }).observe(document, { subtree: true, childList: true, attributes: true });
`;

interface TraceEvent {
  name: string;
  cat: string;
  ph: string;
  ts: number;
  dur?: number;
  tdur?: number;
  pid: number;
  tid: number;
  args?: { data?: Record<string, unknown>; beginData?: { url?: string } };
}

const server = await startPreviewServer();
const browser = await chromium.launch(CHROMIUM_LAUNCH);
try {
  const context = await browser.newContext({ ...PHONE, serviceWorkers: 'block' });
  await context.addInitScript(MARKS);
  const page = await context.newPage();
  const cdp = await context.newCDPSession(page);
  await cdp.send('Network.enable');
  await cdp.send('Network.setCacheDisabled', { cacheDisabled: true });
  await cdp.send('Network.emulateNetworkConditions', SLOW_4G);
  await cdp.send('Emulation.setCPUThrottlingRate', { rate: 4 });
  const events: TraceEvent[] = [];
  cdp.on('Tracing.dataCollected', (data) => {
    events.push(...(data.value as unknown as TraceEvent[]));
  });
  const done = new Promise<void>((resolve) => cdp.once('Tracing.tracingComplete', () => resolve()));
  await cdp.send('Tracing.start', {
    categories:
      'devtools.timeline,disabled-by-default-devtools.timeline,v8,v8.execute,v8.wasm,disabled-by-default-v8.wasm.detailed,blink.user_timing,loading',
    transferMode: 'ReportEvents',
  });
  await page.goto(`${server.url}/#inertia`, { waitUntil: 'commit' });
  await page.locator('#inertia [data-action="toggle-force"]').tap({ timeout: 60_000 });
  await page.waitForFunction(() => (window as unknown as { __answeredAt?: number }).__answeredAt);
  const marks = await page.evaluate(() => {
    const w = window as unknown as { __shownAt: number; __answeredAt: number };
    const fcp = performance.getEntriesByName('first-contentful-paint')[0]?.startTime ?? NaN;
    const files = (performance.getEntriesByType('resource') as PerformanceResourceTiming[]).map(
      (entry) => ({
        name: entry.name.split('/').pop() ?? '',
        start: entry.startTime,
        firstByte: entry.responseStart,
        end: entry.responseEnd,
        bytes: entry.transferSize,
      }),
    );
    const nav = performance.getEntriesByType('navigation')[0] as PerformanceNavigationTiming;
    files.unshift({
      name: '(document)',
      start: nav.startTime,
      firstByte: nav.responseStart,
      end: nav.responseEnd,
      bytes: nav.transferSize,
    });
    return {
      fcp,
      shown: w.__shownAt,
      answered: w.__answeredAt,
      files,
      origin: performance.timeOrigin,
    };
  });
  await cdp.send('Tracing.end');
  await done;
  if (process.argv[2] !== undefined)
    writeFileSync(process.argv[2], JSON.stringify({ traceEvents: events }));
  const f = (ms: number): string => ms.toFixed(0).padStart(6);
  process.stdout.write('files (ms since navigation): requested, first byte, last byte, bytes\n');
  for (const file of marks.files)
    process.stdout.write(
      `${f(file.start)} ${f(file.firstByte)} ${f(file.end)} ${String(file.bytes).padStart(7)}  ${file.name}\n`,
    );

  // The page's main thread: the renderer thread that parsed the document.
  const parser = events.find(
    (e) => e.name === 'ParseHTML' && (e.args?.beginData?.url ?? '').startsWith(server.url),
  )!;
  const onMain = events.filter((e) => e.pid === parser.pid && e.tid === parser.tid);
  const origin = marks.origin * 1000; // trace clock: the navigation's start, in µs
  const navStart = events.find((e) => e.name === 'navigationStart' && e.pid === parser.pid)?.ts;
  const zero = navStart ?? origin;
  const at = (ts: number): number => (ts - zero) / 1000;
  process.stdout.write('\nmain-thread tasks of 15 ms or more: start, wall, thread CPU; inside\n');
  let cpu = 0;
  for (const task of onMain.filter((e) => e.ph === 'X' && e.name === 'RunTask')) {
    if (at(task.ts) > marks.answered) continue;
    cpu += (task.tdur ?? 0) / 1000;
    if ((task.dur ?? 0) < 15_000) continue;
    const inside = onMain.filter(
      (e) =>
        e.ph === 'X' &&
        e !== task &&
        e.ts >= task.ts &&
        e.ts < task.ts + (task.dur ?? 0) &&
        (e.dur ?? 0) >= 5_000,
    );
    const what = new Map<string, number>();
    for (const e of inside) {
      const data = e.args?.data ?? {};
      const url = String(data['url'] ?? data['fileName'] ?? '')
        .split('/')
        .pop();
      const label = /wasm/i.test(e.name)
        ? e.name
        : [
              'v8.evaluateModule',
              'EvaluateScript',
              'v8.compileModule',
              'v8.compile',
              'FunctionCall',
              'TimerFire',
              'FireAnimationFrame',
              'EventDispatch',
              'RunMicrotasks',
              'UpdateLayoutTree',
              'Layout',
              'Paint',
              'MinorGC',
              'MajorGC',
              'ParseHTML',
              'ParseAuthorStyleSheet',
              'FireIdleCallback',
              'HandlePostMessage',
            ].includes(e.name)
          ? `${e.name}${url ? ` ${url}` : ''}${data['type'] ? ` ${String(data['type'])}` : ''}`
          : undefined;
      if (label !== undefined) what.set(label, Math.max(what.get(label) ?? 0, (e.dur ?? 0) / 1000));
    }
    const list = [...what]
      .sort((a, b) => b[1] - a[1])
      .slice(0, 6)
      .map(([k, v]) => `${k} ${v.toFixed(0)}`);
    process.stdout.write(
      `${f(at(task.ts))} ${f((task.dur ?? 0) / 1000)} ${f((task.tdur ?? 0) / 1000)}  ${list.join('; ')}\n`,
    );
  }
  process.stdout.write('\nWebAssembly on any thread of the page:\n');
  for (const e of events.filter(
    (e) => e.pid === parser.pid && /wasm/i.test(e.name) && (e.dur ?? 0) > 500,
  ))
    process.stdout.write(
      `${f(at(e.ts))} ${f((e.dur ?? 0) / 1000)}  ${e.name}${e.tid === parser.tid ? ' (main)' : ''}\n`,
    );
  process.stdout.write(
    `\nfirst contentful paint ${marks.fcp.toFixed(0)} ms; Apply force in the page ${marks.shown.toFixed(0)} ms; ` +
      `tap answered ${marks.answered.toFixed(0)} ms; main-thread CPU until then ${cpu.toFixed(0)} ms\n`,
  );
  await context.close();
} finally {
  await browser.close();
  await server.close();
}
