// Where Newton's time goes on a school phone: a CPU profile (Chromium's sampling profiler through
// CDP) or a performance trace of the cold load until the first tap is answered (Slow 4G, 4x CPU,
// as npm run bench:newton), or of 3 s of Reactions with 50 particles at 4x CPU slowdown. A
// profile is summarised as self time per function and per script; a trace as the thread CPU
// time (not wall time: the machine may be shared) of each event name on each busy thread, so
// the main thread's frame shows as FireAnimationFrame (scripts) and
// LayerTreeHost::DoUpdateLayers (the canvas's software raster at commit).
// The frames modes take the CPU slowdown as RATE (default 4; RATE=1 for the machine's own speed)
// and print the canvas' frame count, so that a figure per frame can be read off.
// Usage: npm run build -w @physical/newton &&
//   [RATE=1] tsx e2e/bench/newton-profile.ts load|loadtrace|frames|trace [out.cpuprofile or out.json]
import { writeFileSync } from 'node:fs';
import { chromium, type CDPSession } from 'playwright-core';
import { startPreviewServer } from '../newton/app-server.ts';
import { PHONE } from '../newton/phone.ts';

interface ProfileNode {
  id: number;
  callFrame: { functionName: string; url: string; lineNumber: number; columnNumber: number };
  hitCount?: number;
  children?: number[];
}
interface Profile {
  nodes: ProfileNode[];
  startTime: number;
  endTime: number;
  samples: number[];
  timeDeltas: number[];
}

const which = process.argv[2] ?? 'frames';
const rate = Number(process.env['RATE'] ?? 4);
const out = process.argv[3];
const SLOW_4G = {
  offline: false,
  latency: 150,
  downloadThroughput: 1.6e6 / 8,
  uploadThroughput: 750e3 / 8,
};

function summarise(profile: Profile): void {
  const byId = new Map(profile.nodes.map((node) => [node.id, node]));
  const self = new Map<number, number>();
  for (let i = 0; i < profile.samples.length; i++) {
    const id = profile.samples[i]!;
    self.set(id, (self.get(id) ?? 0) + (profile.timeDeltas[i + 1] ?? 0) / 1000);
  }
  const total = (profile.endTime - profile.startTime) / 1000;
  const byFunction = new Map<string, number>();
  const byScript = new Map<string, number>();
  for (const [id, ms] of self) {
    const frame = byId.get(id)!.callFrame;
    const file = frame.url.split('/').pop() || '(native)';
    const key = `${frame.functionName || '(anonymous)'} ${file}:${frame.lineNumber + 1}:${frame.columnNumber + 1}`;
    byFunction.set(key, (byFunction.get(key) ?? 0) + ms);
    byScript.set(file, (byScript.get(file) ?? 0) + ms);
  }
  const top = (map: Map<string, number>, n: number): string =>
    [...map]
      .sort((a, b) => b[1] - a[1])
      .slice(0, n)
      .map(([k, v]) => `  ${v.toFixed(0).padStart(6)} ms  ${k}`)
      .join('\n');
  process.stdout.write(
    `profile ${total.toFixed(0)} ms\nby script:\n${top(byScript, 15)}\nby function:\n${top(byFunction, 40)}\n`,
  );
}

async function profile(cdp: CDPSession, run: () => Promise<void>): Promise<void> {
  await cdp.send('Profiler.enable');
  await cdp.send('Profiler.setSamplingInterval', { interval: 200 });
  await cdp.send('Profiler.start');
  await run();
  const { profile: result } = (await cdp.send('Profiler.stop')) as unknown as { profile: Profile };
  if (out !== undefined) writeFileSync(out, JSON.stringify(result));
  summarise(result);
}

interface TraceEvent {
  name: string;
  ph: string;
  dur?: number;
  tdur?: number;
  tid: number;
  pid: number;
  args?: { name?: string; data?: unknown };
}

/** A performance trace: thread CPU time of each event name on each busy thread (ms). */
async function trace(cdp: CDPSession, run: () => Promise<void>): Promise<void> {
  const events: TraceEvent[] = [];
  cdp.on('Tracing.dataCollected', (data) => {
    events.push(...(data.value as unknown as TraceEvent[]));
  });
  const done = new Promise<void>((resolve) => cdp.once('Tracing.tracingComplete', () => resolve()));
  await cdp.send('Tracing.start', {
    categories:
      'devtools.timeline,disabled-by-default-devtools.timeline,v8.execute,blink,cc,gpu,viz',
    transferMode: 'ReportEvents',
  });
  await run();
  await cdp.send('Tracing.end');
  await done;
  if (out !== undefined) writeFileSync(out, JSON.stringify({ traceEvents: events }));
  const main = events.find((e) => e.name === 'thread_name' && e.args?.name === 'CrRendererMain');
  const byThread = new Map<string, Map<string, number>>();
  const threadName = new Map<string, string>();
  for (const e of events)
    if (e.name === 'thread_name') threadName.set(`${e.pid}:${e.tid}`, e.args?.name ?? '?');
  for (const e of events) {
    const time = e.tdur ?? e.dur;
    if (e.ph !== 'X' || time === undefined) continue;
    const key = `${e.pid}:${e.tid}`;
    const map = byThread.get(key) ?? new Map<string, number>();
    map.set(e.name, (map.get(e.name) ?? 0) + time / 1000);
    byThread.set(key, map);
  }
  for (const [key, map] of byThread) {
    const name = threadName.get(key) ?? key;
    const isMain = main !== undefined && key === `${main.pid}:${main.tid}`;
    const rows = [...map].sort((a, b) => b[1] - a[1]).slice(0, isMain ? 30 : 8);
    if (rows[0]![1] < 50) continue;
    process.stdout.write(
      `${name}${isMain ? ' (main)' : ''}:\n${rows.map(([k, v]) => `  ${v.toFixed(0).padStart(6)} ms  ${k}`).join('\n')}\n`,
    );
  }
}

const server = await startPreviewServer();
const browser = await chromium.launch({
  executablePath: process.env['CHROMIUM_PATH'] ?? '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--no-first-run'],
});
try {
  if (which === 'load' || which === 'loadtrace') {
    const context = await browser.newContext({ ...PHONE, serviceWorkers: 'block' });
    const page = await context.newPage();
    const cdp = await context.newCDPSession(page);
    await cdp.send('Network.enable');
    await cdp.send('Network.setCacheDisabled', { cacheDisabled: true });
    await cdp.send('Network.emulateNetworkConditions', SLOW_4G);
    await cdp.send('Emulation.setCPUThrottlingRate', { rate: 4 });
    const requests: string[] = [];
    const t0 = Date.now();
    page.on('requestfinished', (request) => {
      requests.push(`${Date.now() - t0} ms ${request.url().split('/').pop()}`);
    });
    await page.goto('about:blank');
    const load = async (): Promise<void> => {
      await page.goto(`${server.url}/#inertia`, { waitUntil: 'commit' });
      await page.locator('#inertia [data-action="toggle-force"]').tap({ timeout: 60_000 });
      await page.locator('#inertia [data-action="toggle-force"][aria-pressed="true"]').waitFor();
    };
    if (which === 'loadtrace') await trace(cdp, load);
    else await profile(cdp, load);
    process.stdout.write(`requests finished:\n  ${requests.join('\n  ')}\n`);
  } else {
    const context = await browser.newContext(PHONE);
    const page = await context.newPage();
    await page.goto(`${server.url}/#reactions`);
    await page.waitForFunction(() => document.documentElement.dataset['ready'] === 'true');
    await page.locator('#reactions [data-action="add"]').focus();
    for (let i = 0; i < 50; i++) await page.keyboard.press('Enter');
    const cdp = await context.newCDPSession(page);
    await cdp.send('Emulation.setCPUThrottlingRate', { rate });
    const frameCount = (): Promise<number> =>
      page.evaluate(
        () =>
          (
            document.querySelector('#reactions physical-canvas') as unknown as {
              frameCount: number;
            }
          ).frameCount,
      );
    const framesBefore = await frameCount();
    const moving = async (): Promise<void> => {
      for (let k = 0; k < 2; k++) {
        await page.evaluate((k) => {
          window.dispatchEvent(
            new DeviceOrientationEvent('deviceorientation', {
              alpha: 0,
              beta: [40, -40][k],
              gamma: [0, 40][k],
            }),
          );
        }, k);
        await new Promise((resolve) => setTimeout(resolve, 1500));
      }
    };
    if (which === 'trace') await trace(cdp, moving);
    else await profile(cdp, moving);
    const frames = (await frameCount()) - framesBefore;
    process.stdout.write(
      `${rate}x CPU: ${frames} canvas frames in 3 s (${(frames / 3).toFixed(0)}/s)\n`,
    );
  }
} finally {
  await browser.close();
  await server.close();
}
