import assert from 'node:assert/strict';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import { boxes, waitSettled } from './page-helpers.ts';

test('dom: tapped chips fall and every element comes to rest inside the container', async ({
  open,
}) => {
  const page: Page = await open('/dom/showcase.html', { viewport: { width: 700, height: 600 } });
  const before = await boxes(page);
  const chip = before.elements[0]!;
  await page.mouse.click(chip.x, chip.y);
  await page.click('#drop');
  await waitSettled(page);
  const after = await boxes(page);
  const inner = after.container;
  for (const element of after.elements) {
    assert.equal(element.state, 'free');
    // The centre is inside, and the element is not above its slot any more: it fell.
    assert.ok(element.x > inner.left && element.x < inner.right, `x ${element.x} inside`);
    assert.ok(element.y > inner.top && element.y < inner.bottom, `y ${element.y} inside`);
    // The body's bounding box (m to px) stays within the walls (1 px of contact slop).
    assert.ok(
      element.bodyMinX >= -1 && element.bodyMaxX <= inner.width + 1,
      JSON.stringify(element),
    );
    assert.ok(
      element.bodyMinY >= -1 && element.bodyMaxY <= inner.height + 1,
      JSON.stringify(element),
    );
  }
  const lowest = Math.max(...after.elements.map((element) => element.y));
  assert.ok(lowest > inner.bottom - 60, `something lies on the floor (${lowest}, ${inner.bottom})`);
  const fell = after.elements.filter((element, i) => element.y > before.elements[i]!.y + 50);
  assert.ok(fell.length >= after.elements.length - 1, `${fell.length} fell`);
});
