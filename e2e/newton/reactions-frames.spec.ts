import assert from 'node:assert/strict';
import type { Locator, Page } from 'playwright-core';
import { DYNAMIC_PALETTE } from '@physical/canvas';
import { MAX_SHOWN_PAIRS } from '../../apps/newton/src/screens/reactions/collision-arrows.ts';
import { test } from '../harness.ts';
import { closeApp, openApp } from './phone.ts';

/** Adds `count` particles as a keyboard user does (Enter on Add); returns the Add button. */
async function addFromKeyboard(page: Page, count: number): Promise<Locator> {
  const add = page.locator('#reactions [data-action="add"]');
  await add.focus();
  for (let i = 0; i < count; i++) await page.keyboard.press('Enter');
  return add;
}

/** Waits for the page's next two frames. */
async function twoFrames(page: Page): Promise<void> {
  await page.evaluate(
    () =>
      new Promise<void>((resolve) =>
        requestAnimationFrame(() => requestAnimationFrame(() => resolve())),
      ),
  );
}

// A frame of the tray should cost the physics and the canvas only: an animation that never ends
// (MUI's focus ripple, pulsing on a button focused from the keyboard) restyled the whole page in
// every frame, a few milliseconds each on a slow phone with 50 particles.
test('newton: reactions, a button focused from the keyboard runs no endless animation beside the tray', async ({
  browser,
}) => {
  const app = await openApp(browser, '#reactions');
  try {
    const { page } = app;
    const add = await addFromKeyboard(page, 5);
    await page.locator('#reactions [data-action="tilt-right"]').focus();
    await page.keyboard.press('Enter');
    await add.focus();
    // Two frames: any animation the focus started is running by then.
    await twoFrames(page);
    const endless = await page.evaluate(() =>
      document
        .getAnimations()
        .filter((animation) => animation.effect?.getComputedTiming().iterations === Infinity)
        .map((animation) => {
          const target = (animation.effect as KeyframeEffect | null)?.target;
          return `${animation.constructor.name} on <${target?.tagName.toLowerCase()} class="${String(target?.className).slice(0, 50)}">`;
        }),
    );
    assert.deepEqual(endless, [], 'no animation without end runs while the tray does');
    assert.equal(
      await page.evaluate(() => document.activeElement?.getAttribute('data-action')),
      'add',
      'the add button has the focus',
    );
  } finally {
    await closeApp(app);
  }
});

// A pile of 50 particles crossing a tilted tray collides in some 130 pairs at a time: all their
// arrows covered the particles, and filling them took most of a slow phone's frame. The tray
// shows the strongest pairs (collision-arrows.ts, MAX_SHOWN_PAIRS), and still shows some.
test(`newton: reactions, a crowd crossing the tray shows its ${MAX_SHOWN_PAIRS} strongest collisions, not all`, async ({
  browser,
}) => {
  const app = await openApp(browser, '#reactions');
  try {
    const { page } = app;
    await addFromKeyboard(page, 50);
    assert.equal(await page.locator('[data-readout="count"]').textContent(), '50');
    const counts: number[] = [];
    // Each press leans the tray a quarter further (TILT_STEP): right, then as far left, and back.
    for (const [direction, presses] of [
      ['tilt-right', 3],
      ['tilt-left', 6],
      ['tilt-right', 6],
    ] as const) {
      const button = page.locator(`#reactions [data-action="${direction}"]`);
      for (let i = 0; i < presses; i++) await button.click();
      for (let i = 0; i < 6; i++) {
        await page.waitForTimeout(250);
        counts.push(
          Number(await page.locator('#reactions [data-arrows]').getAttribute('data-arrows')),
        );
      }
    }
    const most = Math.max(...counts);
    assert.ok(most >= 8, `the crowd's collisions show arrows (at most ${most} at a time)`);
    assert.ok(
      most <= 2 * MAX_SHOWN_PAIRS,
      `at most ${MAX_SHOWN_PAIRS} pairs of arrows at a time, not ${most} arrows`,
    );
  } finally {
    await closeApp(app);
  }
});

// The particles are drawn by Reactions' overlay as bitmaps copied at whole device pixels
// (disc-sprites.ts: a third of the raster time of filling them on a phone without GPU raster).
// Each must still be where its body is, as large as it is, in its own palette colour: A the
// first colour, B the second, and so on.
test('newton: reactions, every particle is drawn at its body, its size, in its colour', async ({
  browser,
}) => {
  const app = await openApp(browser, '#reactions');
  try {
    const { page } = app;
    await addFromKeyboard(page, 10);
    await page.locator('#reactions [data-action="play"]').click();
    // Two frames after the pause: the last one drawn shows the bodies as they stay.
    await twoFrames(page);
    const seen = await page.evaluate((palette) => {
      type Canvas = HTMLElement & {
        world: {
          bodies: {
            type: string;
            position: { x: number; y: number };
            shapes: { geometry: { radius: number } }[];
          }[];
        };
        viewport: { scale: number; originX: number; originY: number; devicePixelRatio: number };
        paused: boolean;
      };
      const element = document.querySelector('#reactions physical-canvas') as Canvas;
      const canvas = (element.shadowRoot?.querySelector('canvas') ??
        element.querySelector('canvas')) as HTMLCanvasElement;
      const context = canvas.getContext('2d')!;
      const { scale, originX, originY, devicePixelRatio } = element.viewport;
      const k = scale * devicePixelRatio;
      const hex = (x: number, y: number): string => {
        const [r, g, b] = context.getImageData(Math.round(x), Math.round(y), 1, 1).data;
        return `#${[r, g, b].map((c) => c!.toString(16).padStart(2, '0')).join('')}`;
      };
      return {
        paused: element.paused,
        particles: element.world.bodies
          .filter((body) => body.type === 'dynamic')
          .map((body, index) => {
            const x = (body.position.x - originX) * k;
            const y = (body.position.y - originY) * k;
            const r = body.shapes[0]!.geometry.radius * k;
            return {
              index,
              want: palette[index % palette.length],
              // Just inside the rim on four sides (the centre holds the particle's name): 3 px,
              // past the rim's anti-aliased pixel (a disc is placed to the nearest pixel, its
              // radius to a quarter pixel; 2 px in met the rim's blend in CI), and
              // just outside it: the tray's background, or a neighbour.
              inside: [hex(x + r - 3, y), hex(x - r + 3, y), hex(x, y + r - 3), hex(x, y - r + 3)],
              outside: hex(x + r + 4, y),
            };
          }),
      };
    }, DYNAMIC_PALETTE);
    assert.ok(seen.paused, 'the tray is paused');
    assert.equal(seen.particles.length, 10);
    for (const particle of seen.particles) {
      assert.deepEqual(
        particle.inside,
        [particle.want, particle.want, particle.want, particle.want],
        `particle ${particle.index}: its colour out to its rim`,
      );
    }
    // Outside the rim is not the particle (a neighbour of another colour, or the background).
    const backgrounds = seen.particles.filter((particle) => particle.outside === '#121212');
    assert.ok(
      backgrounds.length >= 5,
      `background outside most rims: ${JSON.stringify(seen.particles.map((p) => p.outside))}`,
    );
  } finally {
    await closeApp(app);
  }
});

// The tray takes a new lean at its next step; with every particle asleep the canvas takes no
// step at all, so a lean must wake them itself (it once did not, until something else did).
test('newton: reactions, tilting a tray whose particles have all fallen asleep sets them moving', async ({
  browser,
}) => {
  const app = await openApp(browser, '#reactions');
  try {
    const { page } = app;
    await addFromKeyboard(page, 3);
    type Canvas = HTMLElement & {
      world: { awakeBodyCount: number; bodies: { type: string; position: { x: number } }[] };
    };
    await page.waitForFunction(
      () =>
        (document.querySelector('#reactions physical-canvas') as unknown as Canvas).world
          .awakeBodyCount === 0,
      undefined,
      { timeout: 10000 },
    );
    const xs = () =>
      page.evaluate(() =>
        (document.querySelector('#reactions physical-canvas') as unknown as Canvas).world.bodies
          .filter((body) => body.type === 'dynamic')
          .map((body) => body.position.x),
      );
    const before = await xs();
    await page.evaluate(() =>
      window.dispatchEvent(
        new DeviceOrientationEvent('deviceorientation', { alpha: 0, beta: 0, gamma: 45 }),
      ),
    );
    await page.waitForTimeout(500);
    const after = await xs();
    for (let i = 0; i < before.length; i++) {
      assert.ok(
        after[i]! > before[i]! + 0.02,
        `particle ${i} moved right: ${before[i]} -> ${after[i]}`,
      );
    }
  } finally {
    await closeApp(app);
  }
});
