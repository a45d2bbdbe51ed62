import assert from 'node:assert/strict';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import { boxes, waitSettled } from './page-helpers.ts';

const count = (page: Page) =>
  page.evaluate(() => Number(document.querySelector('#count span')!.textContent));

test('dom: a click on a physical button fires its handler once, in layout and after falling', async ({
  open,
}) => {
  const page = await open('/dom/showcase.html', { viewport: { width: 700, height: 600 } });
  const clicks: string[] = [];
  await page.exposeFunction('recordClick', (id: string) => clicks.push(id));
  await page.evaluate(() => {
    document.querySelector('#count')!.addEventListener('click', (event) => {
      (window as unknown as { recordClick(id: string): void }).recordClick(
        (event.currentTarget as HTMLElement).id,
      );
    });
  });
  const inLayout = (await boxes(page)).elements.find((element) => element.id === 'count')!;
  await page.mouse.click(inLayout.x, inLayout.y);
  assert.equal(await count(page), 1);
  await waitSettled(page); // the first click dropped it
  const fallen = (await boxes(page)).elements.find((element) => element.id === 'count')!;
  assert.equal(fallen.state, 'free');
  assert.ok(fallen.y > inLayout.y + 100, `it fell (${inLayout.y} -> ${fallen.y})`);
  await page.mouse.click(fallen.x, fallen.y);
  assert.equal(await count(page), 2);
  assert.deepEqual(clicks, ['count', 'count']);
});

test('dom: a touch tap and a pen-sized wobble under the drag slop are still one click', async ({
  open,
}) => {
  const page = await open('/dom/showcase.html', {
    viewport: { width: 700, height: 600 },
    hasTouch: true,
  });
  const target = (await boxes(page)).elements.find((element) => element.id === 'count')!;
  await page.touchscreen.tap(target.x, target.y);
  await page.waitForFunction(() => document.querySelector('#count span')!.textContent === '1');
  await waitSettled(page);
  const fallen = (await boxes(page)).elements.find((element) => element.id === 'count')!;
  await page.mouse.move(fallen.x, fallen.y);
  await page.mouse.down();
  await page.mouse.move(fallen.x + 2, fallen.y + 2, { steps: 2 });
  await page.mouse.up();
  assert.equal(await count(page), 2);
  assert.equal(
    await page.evaluate(() => window.ui.isDragging(document.querySelector('#count')!)),
    false,
  );
});
