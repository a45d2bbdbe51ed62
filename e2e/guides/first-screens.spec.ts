import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import { writeGuidePages } from './guide-pages.ts';

// Each guide's first screen on a 375x667 phone and an 800x600 window: the guide's own snippet
// and element (guide-pages.ts), run until its world sleeps. Every dynamic body must then be at
// rest inside the canvas, and the canvas inside the window. Screenshots go to
// test-results/guides/ for a look.

const sizes = [
  { width: 375, height: 667 },
  { width: 800, height: 600 },
] as const;

interface Placement {
  canvas: { left: number; top: number; right: number; bottom: number };
  bodies: { x: number; y: number; radius: number }[];
  /** Each wall (a static segment) as 21 points along it (client px). */
  walls: { x: number; y: number }[][];
  awake: number;
}

/** Every dynamic body's drawn centre (client px) and the canvas's box, read in the page. */
function placement(page: Page): Promise<Placement | null> {
  return page.evaluate(() => {
    const canvas = document.querySelector('physical-canvas');
    const source = canvas?.source;
    if (canvas === null || canvas === undefined || source === null || source === undefined) {
      return null;
    }
    const rect = canvas.getBoundingClientRect();
    const pose = { x: 0, y: 0, angle: 0 };
    const bodies = source.bodies
      .map((body, index) => ({ body, index }))
      .filter(({ body }) => body.type === 'dynamic')
      .map(({ body, index }) => {
        const at = source.remote?.poseOf(body, index, 1, pose) ?? body.position;
        const point = canvas.worldToScreen({ x: at.x, y: at.y });
        // A quarter metre around the centre must show too (the snippets' bodies are 0.3 m+).
        const radius = 0.25 * canvas.viewport.scale;
        return { x: rect.left + point.x, y: rect.top + point.y, radius };
      });
    const walls = source.bodies
      .filter((body) => body.type === 'static')
      .flatMap((body) =>
        body.shapes.flatMap(({ geometry }) => {
          if (geometry.kind !== 'segment') return [];
          const { x, y } = body.position;
          const cos = Math.cos(body.angle);
          const sin = Math.sin(body.angle);
          const points: { x: number; y: number }[] = [];
          for (let i = 0; i <= 20; i++) {
            const lx = geometry.x1 + ((geometry.x2 - geometry.x1) * i) / 20;
            const ly = geometry.y1 + ((geometry.y2 - geometry.y1) * i) / 20;
            const point = canvas.worldToScreen({
              x: x + cos * lx - sin * ly,
              y: y + sin * lx + cos * ly,
            });
            points.push({ x: rect.left + point.x, y: rect.top + point.y });
          }
          return [points];
        }),
      );
    return {
      canvas: { left: rect.left, top: rect.top, right: rect.right, bottom: rect.bottom },
      bodies,
      walls,
      awake: source.awakeBodyCount,
    };
  });
}

const pages = writeGuidePages();

test('guides: the first screens are the pages the guides describe', async () => {
  // Guide 01 (vanilla and React) and guide 12 (vanilla and React) at least.
  assert.ok(pages.length >= 4, `guide pages: ${pages.map((page) => page.name).join(', ')}`);
});

for (const guide of pages) {
  for (const size of sizes) {
    test(`guides: ${guide.name} at ${size.width}x${size.height}: bodies come to rest inside the canvas`, async ({
      open,
    }) => {
      const page = await open(guide.path, { viewport: size });
      await page.waitForFunction(
        () => (document.querySelector('physical-canvas')?.source?.bodies.length ?? 0) > 0,
        undefined,
        { timeout: 15_000 },
      );
      // Asleep: every body at rest (the engine's sleep test: slow for half a second).
      await page.waitForFunction(
        () => {
          const source = document.querySelector('physical-canvas')?.source;
          return source !== null && source !== undefined && source.awakeBodyCount === 0;
        },
        undefined,
        { timeout: 60_000, polling: 250 },
      );
      const first = await placement(page);
      assert.ok(first !== null, 'the page has a canvas with a world');
      const { canvas, bodies } = first;
      assert.ok(bodies.length > 0, 'dynamic bodies');
      // The canvas is on screen (a 1 px rounding margin).
      assert.ok(canvas.left >= -1 && canvas.top >= -1, `canvas at ${JSON.stringify(canvas)}`);
      assert.ok(
        canvas.right <= size.width + 1 && canvas.bottom <= size.height + 1,
        `canvas ${JSON.stringify(canvas)} beyond the ${size.width}x${size.height} window`,
      );
      // A first screen takes the window's height: not the element's bare 300 px default.
      assert.ok(
        canvas.bottom - canvas.top >= 0.9 * size.height,
        `canvas ${canvas.bottom - canvas.top} px tall in a ${size.height} px window: no height set`,
      );
      for (const [index, body] of bodies.entries()) {
        const inside =
          body.x - body.radius >= canvas.left - 1 &&
          body.x + body.radius <= canvas.right + 1 &&
          body.y - body.radius >= canvas.top - 1 &&
          body.y + body.radius <= canvas.bottom + 1;
        assert.ok(
          inside,
          `body ${index} at (${body.x}, ${body.y}) r ${body.radius} outside ${JSON.stringify(canvas)}`,
        );
      }
      // Every wall (the floor the bodies rest on) shows: part of it at least 3 px inside, not
      // on the canvas's edge or beyond it.
      for (const [index, wall] of first.walls.entries()) {
        const shows = wall.some(
          (point) =>
            point.x >= canvas.left + 3 &&
            point.x <= canvas.right - 3 &&
            point.y >= canvas.top + 3 &&
            point.y <= canvas.bottom - 3,
        );
        assert.ok(shows, `wall ${index} not in view: ${JSON.stringify([wall[0], wall.at(-1)])}`);
      }
      // At rest there: half a second later, nothing has moved (0.5 px).
      await page.waitForTimeout(500);
      const second = await placement(page);
      for (const [index, body] of bodies.entries()) {
        const later = second!.bodies[index]!;
        assert.ok(
          Math.hypot(later.x - body.x, later.y - body.y) < 0.5,
          `body ${index} still moving: (${body.x}, ${body.y}) -> (${later.x}, ${later.y})`,
        );
      }
      mkdirSync('test-results/guides', { recursive: true });
      const file = guide.path.split('/').at(-1)!.replace('.html', '');
      await page.screenshot({
        path: `test-results/guides/${file}-${size.width}x${size.height}.png`,
      });
    });
  }
}
