import { chromium } from 'playwright-core';
import { createServer } from 'node:http';
import { readFileSync, statSync } from 'node:fs';
import { join, extname } from 'node:path';
const app = '/tmp/physical-consumers-C5mekf/app';
const server = createServer((req, res) => {
  const p = join(app, decodeURIComponent(new URL(req.url, 'http://x').pathname));
  try { res.writeHead(200, { 'content-type': { '.html': 'text/html', '.js': 'text/javascript' }[extname(p)] ?? 'application/octet-stream' }); res.end(readFileSync(p)); } catch { res.writeHead(404).end(); }
});
await new Promise((r) => server.listen(0, '127.0.0.1', r));
const origin = `http://127.0.0.1:${server.address().port}`;
let html = readFileSync(join(app, 'cdn/react.html'), 'utf8').replace(/http:\/\/127\.0\.0\.1:\d+/g, origin);

import { writeFileSync } from 'node:fs';
writeFileSync(join(app, 'cdn/react-debug.html'), html);
const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--no-sandbox'] });
const page = await browser.newPage();
page.on('console', (m) => console.log('console', m.text()));
page.on('pageerror', (e) => console.log('pageerror', e.message));
page.on('requestfailed', (r) => console.log('failed', r.url()));
await page.goto(`${origin}/cdn/react-debug.html`);
await page.waitForTimeout(5000);
console.log(await page.evaluate(() => { const c = document.querySelector('physical-canvas'); return c && { world: c.world !== null, steps: c.stepCount, frames: c.frameCount, h: c.clientHeight, html: document.body.innerHTML.slice(0, 300) }; }));
await browser.close(); server.close();
