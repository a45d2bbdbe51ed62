import assert from 'node:assert/strict';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import { assertQuiet } from '../newton/phone.ts';
import { closeGallery, openGallery, screenshot } from './gallery-page.ts';

/** A body's centre on the stage, in CSS px from the canvas element's top-left corner. */
interface OnStage {
  readonly index: number;
  readonly x: number;
  readonly y: number;
}

/**
 * Pauses the live sample, gives its dynamic bodies the velocities `throws` (in order, if any),
 * steps its world to `steps` steps of 1/60 s, lets two frames pass (the page moves its view once
 * per frame), and returns where the dynamic bodies are drawn, with the stage's size.
 */
async function stageAfter(
  page: Page,
  steps: number,
  throws: readonly { x: number; y: number }[] = [],
): Promise<{ width: number; height: number; bodies: OnStage[] }> {
  return page.evaluate(
    async ({ steps, throws }) => {
      interface Body {
        readonly type: string;
        position: { x: number; y: number };
        linearVelocity: { x: number; y: number };
      }
      const canvas = document.querySelector('.stage physical-canvas') as unknown as HTMLElement & {
        paused: boolean;
        world: { bodies: Body[]; steps: number; step(dt: number): void };
        worldToScreen(p: { x: number; y: number }): { x: number; y: number };
      };
      canvas.paused = true;
      const world = canvas.world;
      const dynamic = world.bodies.filter((body) => body.type === 'dynamic');
      throws.forEach((velocity, i) => (dynamic[i]!.linearVelocity = velocity));
      while (world.steps < steps) world.step(1 / 60);
      for (let frame = 0; frame < 2; frame++) {
        await new Promise((resolve) => requestAnimationFrame(resolve));
      }
      const rect = canvas.getBoundingClientRect();
      return {
        width: rect.width,
        height: rect.height,
        bodies: world.bodies.flatMap((body, index) =>
          body.type === 'dynamic' ? [{ index, ...canvas.worldToScreen(body.position) }] : [],
        ),
      };
    },
    { steps, throws },
  );
}

/** Fails unless every listed body is drawn inside the stage. */
function assertInView(
  stage: { width: number; height: number; bodies: OnStage[] },
  what: string,
): void {
  assert.ok(stage.bodies.length > 0, `${what}: no dynamic bodies`);
  for (const { index, x, y } of stage.bodies) {
    assert.ok(
      x >= 0 && x <= stage.width && y >= 0 && y <= stage.height,
      `${what}: body ${index} is drawn at (${x.toFixed(0)}, ${y.toFixed(0)}) px, outside the ` +
        `${stage.width.toFixed(0)} x ${stage.height.toFixed(0)} px stage`,
    );
  }
}

test('gallery: the car stays in view as it drives, at 8 s and at the end of the road', async ({
  browser,
}) => {
  const gallery = await openGallery(browser, '#/car');
  const { page } = gallery;
  try {
    assertInView(await stageAfter(page, 480), 'the car at 8 s');
    await screenshot(page, 'car-8s-phone');
    assertInView(await stageAfter(page, 3000), 'the car at 50 s');
    assertQuiet(gallery);
  } finally {
    await closeGallery(gallery);
  }
});

test('gallery: in Newton: forces, a square thrown hard in any direction stays in the box', async ({
  browser,
}) => {
  const gallery = await openGallery(browser, '#/newton-forces');
  const { page } = gallery;
  try {
    // Thrown up and back, and down and forward, far faster than the force could turn them.
    const stage = await stageAfter(page, 600, [
      { x: -30, y: -25 },
      { x: 25, y: 30 },
    ]);
    assert.equal(stage.bodies.length, 2, 'two squares');
    assertInView(stage, 'thrown squares after 10 s');
    await screenshot(page, 'newton-forces-thrown-phone');
    assertQuiet(gallery);
  } finally {
    await closeGallery(gallery);
  }
});

test('gallery: the bullets are still in view at 2 s, between the walls', async ({ browser }) => {
  const gallery = await openGallery(browser, '#/bullets');
  const { page } = gallery;
  try {
    const stage = await stageAfter(page, 120);
    assert.equal(stage.bodies.length, 6, 'six bullets');
    assertInView(stage, 'bullets at 2 s');
    await screenshot(page, 'bullets-2s-phone');
    assertQuiet(gallery);
  } finally {
    await closeGallery(gallery);
  }
});
