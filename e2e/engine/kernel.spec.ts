import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import type { PileResult } from './pile.ts';

test('engine: the WebAssembly contact kernel runs in Chromium, and a page whose Content-Security-Policy forbids WebAssembly gets the same world bit for bit from the JavaScript passes', async ({
  open,
}) => {
  const read = async (path: string): Promise<PileResult> => {
    const page = await open(path);
    return page.evaluate(() => window.pileResult!);
  };
  const open_ = await read('/engine/pile.html');
  const strict = await read('/engine/pile-strict-csp.html');
  assert.equal(open_.kernel, true, 'the page without a policy runs the WebAssembly kernel');
  assert.equal(strict.kernel, false, 'the strict policy leaves the JavaScript passes');
  // The pile fell into the bin and rests on its floor (y = 0, y down), well below where it began.
  assert.ok(open_.maxY < 0 && open_.maxY > -0.5, `lowest body at y = ${open_.maxY}`);
  assert.ok(open_.minY > -4, `highest body at y = ${open_.minY}`);
  assert.equal(strict.bits, open_.bits);
});
