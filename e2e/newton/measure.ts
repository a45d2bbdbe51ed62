// Newton on a slow phone: cold load on Slow 4G with 4x CPU throttling (first contentful paint,
// and "interactive" = the first screen rendered), and the frame rate of Reactions with 50
// particles under 4x CPU throttling. Figures, not a test (speed lives in measurements).
// Usage: npm run build -w @physical/newton && npx tsx e2e/newton/measure.ts
import { chromium } from 'playwright-core';
import { startPreviewServer } from './app-server.ts';
import { PHONE } from './phone.ts';

const ARGS = [
  '--no-sandbox',
  '--disable-gpu',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
];
// Chrome DevTools' "Slow 4G" preset.
const SLOW_4G = {
  offline: false,
  latency: 562.5,
  downloadThroughput: (1.44e6 * 0.9) / 8,
  uploadThroughput: (675e3 * 0.9) / 8,
};
const READY_AT = `
  const poll = setInterval(() => {
    if (document.documentElement && document.documentElement.dataset.ready === 'true') {
      window.__readyAt = performance.now();
      clearInterval(poll);
    }
  }, 16);
`;
const median = (values: number[]): number => [...values].sort((a, b) => a - b)[values.length >> 1]!;

const server = await startPreviewServer();
const browser = await chromium.launch({
  executablePath: process.env['CHROMIUM_PATH'] ?? '/usr/bin/chromium',
  args: ARGS,
});
try {
  const fcps: number[] = [];
  const readies: number[] = [];
  for (let run = 0; run < 3; run++) {
    const context = await browser.newContext({ ...PHONE, serviceWorkers: 'block' });
    await context.addInitScript(READY_AT);
    const page = await context.newPage();
    const cdp = await context.newCDPSession(page);
    await cdp.send('Network.enable');
    await cdp.send('Network.setCacheDisabled', { cacheDisabled: true });
    await cdp.send('Network.emulateNetworkConditions', SLOW_4G);
    await cdp.send('Emulation.setCPUThrottlingRate', { rate: 4 });
    await page.goto(`${server.url}/#inertia`);
    await page.waitForFunction(
      () => document.documentElement.dataset['ready'] === 'true',
      undefined,
      {
        timeout: 60_000,
      },
    );
    const { fcp, ready } = await page.evaluate(() => ({
      fcp: performance.getEntriesByName('first-contentful-paint')[0]?.startTime ?? NaN,
      ready: (window as unknown as { __readyAt?: number }).__readyAt ?? NaN,
    }));
    fcps.push(fcp);
    readies.push(ready);
    await context.close();
  }
  process.stdout.write(
    `cold load, Slow 4G + 4x CPU (3 runs): first contentful paint median ${Math.round(median(fcps))} ms ` +
      `(${fcps.map(Math.round).join(', ')}), interactive median ${Math.round(median(readies))} ms ` +
      `(${readies.map(Math.round).join(', ')})\n`,
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
  await cdp.send('Emulation.setCPUThrottlingRate', { rate: 4 });
  const rates: number[] = [];
  for (let i = 0; i < 4; i++) {
    // Keep them moving: the tilt turns every second.
    await page.evaluate((k) => {
      window.dispatchEvent(
        new DeviceOrientationEvent('deviceorientation', {
          alpha: 0,
          beta: [40, 0, -40, 0][k % 4],
          gamma: [0, 40, 0, -40][k % 4],
        }),
      );
    }, i);
    const before = await page.evaluate(() => (window as unknown as { __frames: number }).__frames);
    const started = Date.now();
    await new Promise((resolve) => setTimeout(resolve, 1500));
    const after = await page.evaluate(() => (window as unknown as { __frames: number }).__frames);
    rates.push(((after - before) * 1000) / (Date.now() - started));
  }
  const count = await page.locator('[data-readout="count"]').textContent();
  process.stdout.write(
    `Reactions, ${count} particles, 4x CPU throttling: ${rates.map((r) => r.toFixed(0)).join(', ')} frames/s (median ${median(rates).toFixed(0)})\n`,
  );
  await context.close();
} finally {
  await browser.close();
  await server.close();
}
