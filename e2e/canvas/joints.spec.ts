import assert from 'node:assert/strict';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import type {} from './fixture-api.ts';
import { waitFrames } from './page-helpers.ts';

// Joint drawing and the drag are chunks loaded when first used: a joint (or a held body) is drawn
// once its code arrives, on a running or a paused element alike. 40 CSS px/m, origin (0, 0), a
// black background: the joints' line colour, rgba(236, 239, 241, 0.6), shows as a light grey.

/** The backing store's pixel at CSS (x, y), as RGBA (dpr 1). */
const pixelAt = (page: Page, x: number, y: number): Promise<number[]> =>
  page.evaluate(
    ({ x, y }) => {
      const source = document
        .querySelector('physical-canvas')!
        .shadowRoot!.querySelector('canvas')!;
      const copy = document.createElement('canvas');
      copy.width = source.width;
      copy.height = source.height;
      const context = copy.getContext('2d', { willReadFrequently: true })!;
      context.drawImage(source, 0, 0);
      return Array.from(context.getImageData(x, y, 1, 1).data);
    },
    { x, y },
  );

const isLine = ([r, g, b]: number[]): boolean => r! > 100 && g! > 100 && b! > 100;

/** Waits, frame by frame (at most `frames`), until the pixel at (x, y) is the line's grey. */
async function untilLine(page: Page, x: number, y: number, frames = 120): Promise<number[]> {
  let pixel = await pixelAt(page, x, y);
  for (let i = 0; i < frames && !isLine(pixel); i++) {
    await waitFrames(page, 1);
    pixel = await pixelAt(page, x, y);
  }
  return pixel;
}

test('joints: a paused canvas draws a joint once its drawing code has loaded', async ({ open }) => {
  const page = await open('/canvas/fixture.html', { viewport: { width: 400, height: 300 } });
  await page.evaluate(() => {
    const { World, box, distanceJoint } = window.physical;
    const canvas = document.querySelector('physical-canvas')!;
    canvas.pixelsPerMeter = 40;
    canvas.background = '#000000';
    canvas.paused = true;
    const world = new World();
    const a = world.add(box({ type: 'static', position: { x: 2, y: 2 }, width: 0.2, height: 0.2 }));
    const b = world.add(box({ position: { x: 6, y: 2 }, width: 0.2, height: 0.2 }));
    world.addJoint(distanceJoint({ bodyA: a, bodyB: b, anchorA: a.position, anchorB: b.position }));
    canvas.world = world;
  });
  // The rod from (2, 2) m to (6, 2) m: CSS px (80, 80) to (240, 80); its middle is (160, 80).
  assert.ok(isLine(await untilLine(page, 160, 80)), 'the joint is drawn');
  assert.deepEqual((await pixelAt(page, 160, 90)).slice(0, 3), [0, 0, 0], 'and nothing beside it');
});

test('joints: a held body is drawn linked to the pointer, as a mouse joint was', async ({
  open,
}) => {
  const page = await open('/canvas/fixture.html', { viewport: { width: 400, height: 300 } });
  await page.evaluate(() => {
    const { World, box } = window.physical;
    const canvas = document.querySelector('physical-canvas')!;
    canvas.pixelsPerMeter = 40;
    canvas.background = '#000000';
    canvas.paused = true; // nothing moves: the line stays where the pointer left it
    const world = new World();
    world.add(box({ position: { x: 3, y: 3 }, width: 1, height: 1 }));
    canvas.world = world;
  });
  await waitFrames(page, 3);
  // Press the box's centre, CSS px (120, 120), and move 2.5 m right: the line runs along y = 120
  // from the box (its right edge at x = 140) to the pointer at x = 220.
  await page.mouse.move(120, 120);
  await page.mouse.down();
  await page.mouse.move(220, 120, { steps: 5 });
  const pixel = await untilLine(page, 180, 120);
  const held = await page.evaluate(
    () => document.querySelector('physical-canvas')!.world!.joints.length,
  );
  await page.mouse.up();
  assert.ok(isLine(pixel), `the drag's line is drawn: ${pixel.join(', ')}`);
  assert.equal(held, 0, 'the drag adds no joint to the world');
});
