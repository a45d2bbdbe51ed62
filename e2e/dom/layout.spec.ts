import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import { boxes, waitSettled } from './page-helpers.ts';
import { waitFrames } from '../canvas/page-helpers.ts';

test('dom: the container shrinking moves its walls and keeps every element inside', async ({
  open,
}) => {
  const page = await open('/dom/showcase.html', { viewport: { width: 700, height: 600 } });
  await page.click('#drop');
  await waitSettled(page);
  await page.evaluate(() => {
    window.ui.container.style.width = '320px';
    window.ui.container.style.height = '300px';
  });
  await waitFrames(page, 3);
  await waitSettled(page);
  const after = await boxes(page);
  assert.equal(after.container.width, 316); // 320 px minus the 2 px borders
  for (const element of after.elements) {
    assert.ok(
      element.bodyMinX >= -1 && element.bodyMaxX <= after.container.width + 1,
      JSON.stringify(element),
    );
    assert.ok(
      element.bodyMinY >= -1 && element.bodyMaxY <= after.container.height + 1,
      JSON.stringify(element),
    );
    assert.ok(element.x > after.container.left && element.x < after.container.right);
    assert.ok(element.y > after.container.top && element.y < after.container.bottom);
  }
});

test('dom: back to layout springs every element home, untransformed, in its reflowed slot', async ({
  open,
}) => {
  const page = await open('/dom/showcase.html', { viewport: { width: 700, height: 600 } });
  await page.click('#drop');
  await waitSettled(page);
  // The layout changes while they lie in the box: the slots move with it.
  await page.evaluate(() => {
    window.ui.container.style.width = '420px';
  });
  await waitFrames(page, 3);
  await page.evaluate(() => window.ui.restore());
  await waitSettled(page);
  const home = await boxes(page);
  // Without Physical UI at all, the layout puts them exactly there.
  const plain = await page.evaluate(() => {
    window.ui.destroy();
    return [...document.querySelectorAll('.box button')].map((element) => {
      const box = element.getBoundingClientRect();
      return [box.left + box.width / 2, box.top + box.height / 2];
    });
  });
  assert.deepEqual(
    home.elements.map((element) => [element.state, element.transform]),
    home.elements.map(() => ['layout', '']),
  );
  assert.deepEqual(
    home.elements.map((element) => [element.x, element.y]),
    plain,
  );
});

test('dom: keyboard focus order is the DOM order, before and after the elements fall', async ({
  open,
}) => {
  const page = await open('/dom/showcase.html', { viewport: { width: 700, height: 600 } });
  const order = async (): Promise<string[]> => {
    // Start from a sentinel before everything: Tab then walks the page from the top.
    await page.evaluate(() => {
      let start = document.getElementById('start');
      if (start === null) {
        start = document.createElement('div');
        start.id = 'start';
        start.tabIndex = -1;
        document.body.prepend(start);
      }
      start.focus();
    });
    const seen: string[] = [];
    for (let i = 0; i < 11; i++) {
      await page.keyboard.press('Tab');
      seen.push(await page.evaluate(() => document.activeElement?.textContent?.trim() ?? ''));
    }
    return seen;
  };
  const before = await order();
  await page.evaluate(() => window.ui.release());
  await waitSettled(page);
  const after = await order();
  assert.deepEqual(after, before);
  assert.deepEqual(before.slice(0, 3), ['Gravity', 'Friction', 'Restitution']);
  // Enter on a focused, fallen button is a click (keyboard clicks are never suppressed).
  await page.focus('#count');
  await page.keyboard.press('Enter');
  assert.equal(await page.evaluate(() => document.querySelector('#count span')!.textContent), '1');
});

test('dom: elements added and removed while running join and leave the world', async ({ open }) => {
  const page = await open('/dom/showcase.html', { viewport: { width: 700, height: 600 } });
  await page.click('#drop');
  await waitFrames(page, 10);
  const result = await page.evaluate(async () => {
    const ui = window.ui;
    const box = ui.container;
    const added = document.createElement('button');
    added.textContent = 'New';
    added.className = 'chip';
    box.append(added);
    const removed = box.querySelector<HTMLElement>('#likes')!;
    const removedBody = ui.bodyOf(removed)!;
    removed.remove();
    await new Promise((resolve) => setTimeout(resolve, 50));
    const joined = ui.stateOf(added);
    ui.release(added);
    // It grows: the body follows the new size.
    const widthBefore = ui.bodyOf(added)!.shapes[0]!.getBounds();
    added.style.padding = '20px 40px';
    await new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve)));
    await new Promise((resolve) => setTimeout(resolve, 50));
    const widthAfter = ui.bodyOf(added)!.shapes[0]!.getBounds();
    return {
      joined,
      removedGone: ui.stateOf(removed) === null && !ui.world.has(removedBody),
      removedTransform: removed.style.transform,
      grew: widthAfter.maxX - widthAfter.minX - (widthBefore.maxX - widthBefore.minX),
      count: ui.elements.length,
    };
  });
  assert.equal(result.joined, 'layout');
  assert.equal(result.removedGone, true);
  assert.equal(result.removedTransform, '');
  assert.ok(Math.abs(result.grew - 0.52) < 0.05, `the body grew by ${result.grew} m`);
  assert.equal(result.count, 9);
});

test('dom: one element sent back to its layout can be released again', async ({ open }) => {
  const page = await open('/dom/showcase.html', { viewport: { width: 700, height: 600 } });
  await page.click('#drop');
  await waitSettled(page);
  const states = await page.evaluate(async () => {
    const ui = window.ui;
    const [chip, other] = ui.elements as [HTMLElement, HTMLElement];
    ui.restore(chip);
    const sent = [ui.stateOf(chip), ui.stateOf(other)];
    while (ui.isRunning) await new Promise((resolve) => setTimeout(resolve, 50));
    const home = [ui.stateOf(chip), chip.style.transform];
    ui.release(chip);
    await new Promise((resolve) => setTimeout(resolve, 300));
    return { sent, home, again: ui.stateOf(chip), transform: chip.style.transform };
  });
  assert.deepEqual(states.sent, ['returning', 'free']);
  assert.deepEqual(states.home, ['layout', '']);
  assert.equal(states.again, 'free');
  assert.match(states.transform, /^translate\(0px, [1-9]\d*(\.\d+)?px\)/); // falling straight down
});
