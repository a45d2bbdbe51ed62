import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import { boxes } from './page-helpers.ts';
import { waitFrames } from '../canvas/page-helpers.ts';

test('dom: with prefers-reduced-motion everything stays in its layout and still clicks', async ({
  open,
}) => {
  const page = await open('/dom/showcase.html', {
    viewport: { width: 700, height: 600 },
    reducedMotion: 'reduce',
  });
  const before = await boxes(page);
  assert.equal(await page.evaluate(() => window.ui.motionAllowed), false);
  await page.click('#drop');
  const chip = before.elements[0]!;
  await page.mouse.click(chip.x, chip.y);
  // A drag does not move anything either.
  const count = before.elements.find((element) => element.id === 'count')!;
  await page.mouse.move(count.x, count.y);
  await page.mouse.down();
  await page.mouse.move(count.x + 120, count.y + 150, { steps: 8 });
  await page.mouse.up();
  await waitFrames(page, 30);
  const after = await boxes(page);
  assert.deepEqual(
    after.elements.map((element) => [element.x, element.y, element.state, element.transform]),
    before.elements.map((element) => [element.x, element.y, 'layout', '']),
  );
  // The showcase offers the explicit opt-in; the API takes it.
  assert.equal(await page.isVisible('#motion'), true);
  await page.evaluate(() => {
    window.ui.reducedMotion = 'ignore';
    window.ui.release();
  });
  await waitFrames(page, 20);
  const moving = await boxes(page);
  assert.ok(moving.elements.every((element) => element.state === 'free'));
  assert.ok(moving.elements.some((element, i) => element.y > before.elements[i]!.y + 5));
});

test('dom: reduced motion turned on while elements fly puts them back in their layout at once', async ({
  open,
}) => {
  const page = await open('/dom/showcase.html', { viewport: { width: 700, height: 600 } });
  const before = await boxes(page);
  await page.click('#drop');
  await waitFrames(page, 20);
  await page.emulateMedia({ reducedMotion: 'reduce' });
  await waitFrames(page, 2);
  const after = await boxes(page);
  assert.deepEqual(
    after.elements.map((element) => [element.x, element.y, element.state, element.transform]),
    before.elements.map((element) => [element.x, element.y, 'layout', '']),
  );
});
