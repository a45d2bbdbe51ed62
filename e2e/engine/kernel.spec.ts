import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import type { PileResult } from './pile.ts';
import { CONTACT_KERNEL_HEX } from '../../packages/engine/src/dynamics/contact-kernel-binary.ts';

test('engine: the WebAssembly contact kernel runs in Chromium, and a page whose Content-Security-Policy forbids WebAssembly gets the same world bit for bit from the JavaScript build', async ({
  open,
}) => {
  const read = async (path: string): Promise<PileResult> => {
    const page = await open(path);
    return page.evaluate(() => window.pileResult!);
  };
  const open_ = await read('/engine/pile.html');
  const strict = await read('/engine/pile-strict-csp.html');
  assert.equal(open_.kernel, true, 'the page without a policy runs the WebAssembly kernel');
  // Compiled synchronously on the main thread (new WebAssembly.Module): Chromium allows it for a
  // module of this size, more than the 4 KB it once allowed. A one-box world runs it from its
  // first step: the JavaScript build is an entry the page need not load.
  const moduleBytes = CONTACT_KERNEL_HEX.length / 2;
  assert.ok(moduleBytes > 4096, `a module of ${moduleBytes} bytes`);
  assert.equal(open_.smallWorldKernel, true, 'a small world runs WebAssembly from its first step');
  assert.equal(open_.error, null);
  assert.equal(strict.kernel, false, 'the strict policy leaves the JavaScript build');
  // The attempt to compile is refused and reported: what kernel: 'javascript' avoids (below).
  assert.ok(strict.violations.length > 0, 'the strict page reports the refused compilation');
  // The pile fell into the bin and rests on its floor (y = 0, y down), well below where it began.
  assert.ok(open_.maxY < 0 && open_.maxY > -0.5, `lowest body at y = ${open_.maxY}`);
  assert.ok(open_.minY > -4, `highest body at y = ${open_.minY}`);
  assert.equal(strict.bits, open_.bits);
});

test("engine: kernel: 'javascript' makes no WebAssembly attempt, so a page under script-src 'self' reports no Content-Security-Policy violation, and its world is the same bit for bit", async ({
  open,
}) => {
  const page = await open('/engine/pile-strict-csp.html?kernel=javascript');
  const strict = await page.evaluate(() => window.pileResult!);
  const reference = await (await open('/engine/pile.html')).evaluate(() => window.pileResult!);
  assert.deepEqual(strict.violations, [], 'no securitypolicyviolation reported');
  assert.equal(strict.kernel, false);
  assert.equal(reference.kernel, true);
  assert.equal(strict.bits, reference.bits);
});

test("engine: under script-src 'self', a page that did not load @physical/engine/javascript-kernel gets a PhysicalError naming the kernel option and that import, and runs once it loads it", async ({
  open,
}) => {
  const page = await open('/engine/pile-strict-csp.html?entry=none');
  const strict = await page.evaluate(() => window.pileResult!);
  const reference = await (
    await open('/engine/pile.html?entry=none')
  ).evaluate(() => window.pileResult!);
  assert.match(strict.error ?? '', /^kernel: .*import '@physical\/engine\/javascript-kernel'/);
  assert.equal(reference.error, null, 'where WebAssembly compiles, the entry is not needed');
  assert.equal(reference.kernel, true);
  assert.equal(strict.kernel, false);
  assert.equal(strict.bits, reference.bits);
});
