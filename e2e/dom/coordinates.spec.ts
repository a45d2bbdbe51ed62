import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import { waitFrames } from '../canvas/page-helpers.ts';

// The fixture's box, scrolled down the page, inside a CSS-zoomed wrapper, on a dpr 2 screen.
test('dom: scrolled, zoomed and at dpr 2, a dragged element stays under the pointer', async ({
  open,
}) => {
  const page = await open('/dom/fixture.html', {
    viewport: { width: 700, height: 500 },
    deviceScaleFactor: 2,
  });
  await page.evaluate(() => {
    const box = document.getElementById('box')!;
    box.style.width = '400px';
    box.style.height = '300px';
    const wrapper = document.createElement('div');
    wrapper.style.cssText = 'zoom: 1.5; margin-top: 600px; margin-bottom: 800px;';
    box.before(wrapper);
    wrapper.append(box);
    const { PhysicalUI, fill } = window.dom;
    fill(6);
    window.scrollTo(0, 700);
    Object.assign(window, { ui: new PhysicalUI(box) });
  });
  await waitFrames(page, 3);
  const target = await page.evaluate(() => {
    const element = window.ui.elements[2]!;
    const rect = element.getBoundingClientRect();
    return { x: rect.left + rect.width / 2, y: rect.top + rect.height / 2, w: rect.width };
  });
  const container = await page.evaluate(() => {
    const rect = window.ui.container.getBoundingClientRect();
    return { left: rect.left, top: rect.top, width: rect.width };
  });
  assert.ok(Math.abs(container.width - 600) < 1, `zoomed to ${container.width} px`);
  // Drag it from its slot to the middle of the box (client px), and hold.
  const to = { x: container.left + 300, y: container.top + 225 };
  await page.mouse.move(target.x, target.y);
  await page.mouse.down();
  await page.mouse.move(to.x, to.y, { steps: 12 });
  await page.waitForTimeout(800);
  const held = await page.evaluate(() => {
    const element = window.ui.elements[2]!;
    const rect = element.getBoundingClientRect();
    return {
      x: rect.left + rect.width / 2,
      y: rect.top + rect.height / 2,
      transform: element.style.transform,
    };
  });
  await page.mouse.up();
  assert.ok(Math.hypot(held.x - to.x, held.y - to.y) < 8, JSON.stringify({ held, to }));
  // Translations land on device pixels: multiples of 1 / (dpr 2 x zoom 1.5) CSS px.
  const [dx, dy] = held.transform.match(/-?[\d.]+(?=px)/g)!.map(Number);
  for (const value of [dx!, dy!]) {
    assert.ok(Math.abs(value * 3 - Math.round(value * 3)) < 0.01, `${value} px is on the grid`);
  }
});

test('dom: bad options and inline elements are refused with an error naming the field', async ({
  open,
}) => {
  const page = await open('/dom/fixture.html');
  const errors = await page.evaluate(() => {
    const { PhysicalUI, fill } = window.dom;
    const box = fill(2);
    const attempt = (make: () => unknown): string => {
      try {
        make();
        return 'no error';
      } catch (error) {
        return `${(error as Error).name}: ${(error as Error).message}`;
      }
    };
    const inline = document.createElement('a');
    inline.textContent = 'link';
    // Inside a flex item (flex items themselves are blockified, so transformable).
    box.firstElementChild!.append(inline);
    return [
      attempt(() => new PhysicalUI(box, { pixelsPerMeter: Number.NaN })),
      attempt(() => new PhysicalUI(box, { friction: -1 })),
      attempt(() => new PhysicalUI(box, { reducedMotion: 'sometimes' as 'ignore' })),
      attempt(() => new PhysicalUI(box, { elements: [inline] })),
      attempt(() => new PhysicalUI(null as unknown as HTMLElement)),
    ];
  });
  assert.deepEqual(errors, [
    'PhysicalError: pixelsPerMeter: must be a finite number greater than 0, got NaN.',
    'PhysicalError: friction: must be a finite number, 0 or more, got -1.',
    "PhysicalError: reducedMotion: must be 'respect' or 'ignore', got sometimes.",
    'PhysicalError: elements: <a> is display: inline, which CSS cannot transform; give it display: inline-block or block.',
    'PhysicalError: container: must be an HTMLElement in a document.',
  ]);
});
