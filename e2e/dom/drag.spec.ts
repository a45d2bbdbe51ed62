import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import { boxes, waitSettled } from './page-helpers.ts';

test('dom: a drag moves the element with the pointer, a release throws it, and no click fires', async ({
  open,
}) => {
  const page = await open('/dom/showcase.html', { viewport: { width: 700, height: 600 } });
  await page.click('#drop');
  await waitSettled(page);
  const start = (await boxes(page)).elements.find((element) => element.id === 'count')!;
  // Press on the button, lift it to the middle of the box, and hold it there.
  await page.mouse.move(start.x, start.y);
  await page.mouse.down();
  await page.mouse.move(200, 150, { steps: 12 });
  await page.waitForTimeout(600);
  const held = (await boxes(page)).elements.find((element) => element.id === 'count')!;
  assert.equal(held.state, 'dragging');
  // Held at the grab point (the button's centre): within a few px of the pointer.
  assert.ok(Math.hypot(held.x - 200, held.y - 150) < 12, `held at ${held.x}, ${held.y}`);
  // Fling to the right and let go: it keeps flying right after the release.
  await page.mouse.move(350, 150, { steps: 10 });
  await page.mouse.up();
  const released = (await boxes(page)).elements.find((element) => element.id === 'count')!;
  const velocity = await page.evaluate(
    () => window.ui.bodyOf(document.querySelector('#count')!)!.linearVelocity.x,
  );
  await page.waitForTimeout(150);
  const flying = (await boxes(page)).elements.find((element) => element.id === 'count')!;
  assert.equal(flying.state, 'free');
  assert.ok(velocity > 1, `thrown at ${velocity} m/s`);
  assert.ok(flying.x > released.x + 10, `flew from ${released.x} to ${flying.x}`);
  // The drag's release sent no click.
  assert.equal(await page.evaluate(() => document.querySelector('#count span')!.textContent), '0');
});

test('dom: two touches drag two elements at once', async ({ open }) => {
  const page = await open('/dom/showcase.html', {
    viewport: { width: 700, height: 600 },
    hasTouch: true,
  });
  await page.click('#drop');
  await waitSettled(page);
  const [a, b] = (await boxes(page)).elements.filter(
    (element) => element.id === 'count' || element.id === 'likes',
  );
  const session = await page.context().newCDPSession(page);
  const touch = (
    type: 'touchStart' | 'touchMove' | 'touchEnd',
    points: { x: number; y: number; id: number }[],
  ) =>
    session.send('Input.dispatchTouchEvent', {
      type,
      touchPoints: points.map(({ x, y, id }) => ({ x, y, id })),
    });
  await touch('touchStart', [
    { x: a!.x, y: a!.y, id: 1 },
    { x: b!.x, y: b!.y, id: 2 },
  ]);
  for (let i = 1; i <= 10; i++) {
    await touch('touchMove', [
      { x: a!.x, y: a!.y - 15 * i, id: 1 },
      { x: b!.x, y: b!.y - 15 * i, id: 2 },
    ]);
    await page.waitForTimeout(16);
  }
  const dragging = await page.evaluate(() => [
    window.ui.isDragging(document.querySelector('#likes')!),
    window.ui.isDragging(document.querySelector('#count')!),
  ]);
  await page.waitForTimeout(400);
  const lifted = await boxes(page);
  await touch('touchEnd', []);
  assert.deepEqual(dragging, [true, true]);
  for (const before of [a!, b!]) {
    const now = lifted.elements.find((element) => element.id === before.id)!;
    assert.ok(now.y < before.y - 100, `${before.id} lifted from ${before.y} to ${now.y}`);
  }
});
