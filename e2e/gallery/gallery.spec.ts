import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { test } from '../harness.ts';
import { assertQuiet, axeViolations, paintedPixels } from '../newton/phone.ts';
import { closeGallery, openGallery, screenshot, stageWorld } from './gallery-page.ts';

// The samples are the modules in packages/scenes/src/samples (no engine import here: the specs
// run in Node without a build). Titles come from the list page.
const ids = readdirSync(new URL('../../packages/scenes/src/samples/', import.meta.url))
  .filter((name) => name.endsWith('.ts'))
  .map((name) => name.slice(0, -3));
const scenes = ids.map((id) => ({ id }));

const sleep = (ms: number): Promise<void> => new Promise((resolve) => setTimeout(resolve, ms));

test('gallery: the list shows a drawn picture of every sample', async ({ browser }) => {
  const gallery = await openGallery(browser);
  const { page } = gallery;
  try {
    assert.deepEqual(
      (
        await page
          .locator('[data-sample]')
          .evaluateAll((cards) => cards.map((card) => card.getAttribute('data-sample')))
      ).sort(),
      [...ids].sort(),
    );
    // Pictures are made one per task: wait until the last has its world.
    await page.waitForFunction(
      () =>
        [...document.querySelectorAll('.card physical-canvas')].every(
          (canvas) => (canvas as unknown as { world: unknown }).world !== null,
        ),
      undefined,
      { timeout: 20_000 },
    );
    await sleep(200);
    for (const scene of scenes) {
      const selector = `[data-sample="${scene.id}"] physical-canvas`;
      await page.locator(selector).scrollIntoViewIfNeeded();
      // A picture scrolled back into view is drawn on its next frame, which a loaded machine may
      // take a while to give: poll for it (up to 3 s) rather than sleep a fixed time.
      let painted = 0;
      for (let waited = 0; waited < 3000 && painted <= 200; waited += 100) {
        await sleep(waited === 0 ? 50 : 100);
        painted = await paintedPixels(page, selector);
      }
      assert.ok(painted > 200, `${scene.id}: picture drawn (${painted} pixels)`);
    }
    await page.evaluate(() => window.scrollTo(0, 0));
    await sleep(100);
    await screenshot(page, 'list-phone');
    assertQuiet(gallery);
  } finally {
    await closeGallery(gallery);
  }
});

test('gallery: every sample opens, runs and draws without a console error', async ({ browser }) => {
  const gallery = await openGallery(browser);
  const { page } = gallery;
  try {
    const titles = new Map<string, string>();
    for (const card of await page.locator('[data-sample]').all()) {
      titles.set((await card.getAttribute('data-sample'))!, (await card.textContent())!.trim());
    }
    for (const scene of scenes) {
      await page.evaluate((id) => (location.hash = `#/${id}`), scene.id);
      await page.locator(`[data-source="${scene.id}"]`).waitFor();
      assert.equal((await page.locator('.app-bar h1').textContent())!.trim(), titles.get(scene.id));
      await sleep(300);
      const pixels = await paintedPixels(page, '.stage physical-canvas');
      assert.ok(pixels > 500, `${scene.id}: canvas drawn (${pixels} pixels)`);
      const { steps } = await stageWorld(page);
      assert.ok(steps > 0, `${scene.id}: the world is stepping`);
      if (scene.id === 'pyramid') await screenshot(page, 'sample-phone');
    }
    assertQuiet(gallery);
  } finally {
    await closeGallery(gallery);
  }
});

test('gallery: a parameter slider rebuilds the scene with the new value', async ({ browser }) => {
  const gallery = await openGallery(browser, '#/vertical-stack');
  const { page } = gallery;
  try {
    assert.equal((await stageWorld(page)).bodies, 11); // the ground and 10 boxes
    await sleep(200);
    const before = await paintedPixels(page, '.stage physical-canvas');
    const slider = page.locator('[data-parameter="count"]');
    await slider.focus();
    for (let i = 0; i < 7; i++) await page.keyboard.press('ArrowLeft');
    assert.equal(await slider.inputValue(), '3');
    assert.equal((await page.locator('output[for="parameter-count"]').textContent())!.trim(), '3');
    assert.equal((await stageWorld(page)).bodies, 4);
    await sleep(200);
    const after = await paintedPixels(page, '.stage physical-canvas');
    assert.ok(after < before * 0.6, `fewer boxes drawn (${before} -> ${after} pixels)`);
    assertQuiet(gallery);
  } finally {
    await closeGallery(gallery);
  }
});

test('gallery: the source shown is the sample module itself', async ({ browser }) => {
  const gallery = await openGallery(browser, '#/newtons-cradle');
  const { page } = gallery;
  try {
    const file = readFileSync(
      new URL('../../packages/scenes/src/samples/newtons-cradle.ts', import.meta.url),
      'utf8',
    );
    assert.equal(await page.locator('[data-source="newtons-cradle"]').textContent(), file);
    assertQuiet(gallery);
  } finally {
    await closeGallery(gallery);
  }
});

test('gallery: pause, single step, slow motion, reset and overlays', async ({ browser }) => {
  const gallery = await openGallery(browser, '#/falling-pile');
  const { page } = gallery;
  try {
    await sleep(300);
    await page.locator('[data-action="play"]').click();
    assert.equal(await page.locator('[data-action="play"]').getAttribute('aria-label'), 'Play');
    const paused = (await stageWorld(page)).steps;
    await sleep(200);
    assert.equal((await stageWorld(page)).steps, paused, 'paused: no steps');
    await page.locator('[data-action="step"]').click();
    assert.equal((await stageWorld(page)).steps, paused + 1, 'one step');
    await page.locator('[data-action="slow"]').click();
    assert.equal(
      await page.evaluate(
        () =>
          (document.querySelector('.stage physical-canvas') as unknown as { timeScale: number })
            .timeScale,
      ),
      0.25,
    );
    await page.locator('.chip', { hasText: 'AABBs' }).click();
    await page.locator('.chip', { hasText: 'Contacts' }).click();
    assert.equal(
      await page.evaluate(() =>
        document.querySelector('.stage physical-canvas')!.getAttribute('debug'),
      ),
      'contacts aabbs',
    );
    await page.locator('[data-action="reset"]').click();
    assert.equal((await stageWorld(page)).steps, 0, 'reset builds a fresh world');
    await page.locator('[data-action="play"]').click();
    await sleep(300);
    assert.ok((await stageWorld(page)).steps > 0, 'running again');
    await screenshot(page, 'overlays-phone');
    assertQuiet(gallery);
  } finally {
    await closeGallery(gallery);
  }
});

test('gallery: a body dragged with the pointer follows it, and is let go', async ({ browser }) => {
  const gallery = await openGallery(browser, '#/vertical-stack');
  const { page } = gallery;
  try {
    await sleep(300);
    const stage = page.locator('.stage physical-canvas');
    // The top box of the stack, in page coordinates.
    const start = await stage.evaluate((element) => {
      const canvas = element as unknown as {
        world: { bodies: { position: { x: number; y: number } }[] };
        worldToScreen(p: { x: number; y: number }): { x: number; y: number };
      };
      const bodies = canvas.world.bodies;
      const top = bodies[bodies.length - 1]!.position;
      const screen = canvas.worldToScreen(top);
      const rect = element.getBoundingClientRect();
      return { x: rect.left + screen.x, y: rect.top + screen.y, worldX: top.x };
    });
    await page.mouse.move(start.x, start.y);
    await page.mouse.down();
    for (let i = 1; i <= 10; i++) {
      await page.mouse.move(start.x + 12 * i, start.y + 3 * i);
      await sleep(30);
    }
    await sleep(400);
    const held = await stage.evaluate((element) => {
      const world = (
        element as unknown as {
          world: { joints: unknown[]; bodies: { position: { x: number } }[] };
        }
      ).world;
      return { joints: world.joints.length, x: world.bodies[world.bodies.length - 1]!.position.x };
    });
    assert.equal(held.joints, 1, 'a mouse joint holds the box');
    assert.ok(held.x > start.worldX + 1, `the box followed the pointer (x ${held.x.toFixed(2)} m)`);
    await page.mouse.up();
    await sleep(100);
    assert.equal(
      await stage.evaluate(
        (element) => (element as unknown as { world: { joints: unknown[] } }).world.joints.length,
      ),
      0,
      'released',
    );
    assertQuiet(gallery);
  } finally {
    await closeGallery(gallery);
  }
});

test('gallery: axe-core finds no serious or critical violations', async ({ browser }) => {
  const gallery = await openGallery(browser);
  const { page } = gallery;
  try {
    const found = (await axeViolations(page)).map((v) => `list: ${v}`);
    await page.evaluate(() => (location.hash = '#/bridge'));
    await page.locator('[data-source="bridge"]').waitFor();
    found.push(...(await axeViolations(page)).map((v) => `sample: ${v}`));
    assert.deepEqual(found, []);
    assertQuiet(gallery);
  } finally {
    await closeGallery(gallery);
  }
});

test('gallery: the Physical UI page drops a tapped chip, and its buttons still count', async ({
  browser,
}) => {
  const gallery = await openGallery(browser);
  const { page } = gallery;
  try {
    await page.locator('[data-page="physical-ui"]').click();
    await page.waitForSelector('.physical-ui .chip');
    const chip = page.locator('.physical-ui .chip').first();
    assert.equal(await chip.getAttribute('data-physical'), 'layout');
    const before = await chip.boundingBox();
    await chip.click();
    await sleep(300);
    assert.equal(await chip.getAttribute('data-physical'), 'free', 'a tapped chip is released');
    // The chips below it are still in their layout (obstacles): drop them all.
    await page.locator('.physical-ui #drop').click();
    await sleep(1500);
    const after = await chip.boundingBox();
    assert.ok(after!.y > before!.y + 50, `the chip fell (${before!.y} -> ${after!.y} px)`);
    const counter = page.locator('.physical-ui #count');
    await counter.click();
    await sleep(100);
    assert.equal(await counter.locator('span').textContent(), '1', 'the button counted the click');
    await screenshot(page, 'physical-ui-phone');
    assertQuiet(gallery);
  } finally {
    await closeGallery(gallery);
  }
});
