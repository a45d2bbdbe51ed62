import assert from 'node:assert/strict';
import type { Route } from 'playwright-core';
import { test } from '../harness.ts';
import { startAppServer } from './app-server.ts';
import { PHONE, waitReady } from './phone.ts';

/** The default force and the body's mass, as the app states them (N, kg), and its fixed step (s). */
const FORCE = 1;
const MASS = 1;
const STEP = 1 / 60;

test('newton: first tap, Inertia answers Apply force while the engine is still arriving, and the force acts from the first step (v = F t / m)', async ({
  browser,
}) => {
  const server = await startAppServer();
  const context = await browser.newContext(PHONE);
  try {
    const page = await context.newPage();
    const problems: string[] = [];
    page.on('pageerror', (error) => problems.push(error.message));
    // The engine's chunk is held back (a slow network): the controls come without it.
    const held: Route[] = [];
    let engineAsked = (): void => undefined;
    const asked = new Promise<void>((resolve) => (engineAsked = resolve));
    await page.route(/\/assets\/engine-[\w-]+\.js$/, (route) => {
      held.push(route);
      engineAsked();
    });
    await page.goto(`${server.url}/#inertia`);
    const apply = page.locator('#inertia [data-action="toggle-force"]');
    await apply.tap();
    await page.locator('#inertia [data-action="toggle-force"][aria-pressed="true"]').waitFor();
    await asked;
    const before = await page.evaluate(() => ({
      ready: document.documentElement.dataset['ready'] ?? null,
      canvas: document.querySelector('#inertia physical-canvas') !== null,
      force: document.querySelector('#inertia [data-readout="force"]')?.textContent ?? '',
    }));
    assert.equal(before.canvas, false, 'no canvas yet: the engine has not arrived');
    assert.equal(before.ready, null, 'the app is not marked ready before its world exists');
    assert.match(before.force.replace(/\u00a0/g, ' '), /^1(\.0)? N, 0°$/, 'the force readout');

    for (const route of held.splice(0)) await route.continue();
    await waitReady(page);
    // The force has acted from the world's first step: v = F t / m after every step, read with
    // the step count in one go.
    await page.waitForFunction(() => {
      const canvas = document.querySelector('#inertia physical-canvas') as unknown as {
        world: { steps: number } | null;
      } | null;
      return (canvas?.world?.steps ?? 0) >= 10;
    });
    const motion = await page.evaluate(() => {
      const canvas = document.querySelector('#inertia physical-canvas') as unknown as {
        world: {
          steps: number;
          bodies: readonly { type: string; linearVelocity: { x: number; y: number } }[];
        };
      };
      const body = canvas.world.bodies.find((item) => item.type === 'dynamic')!;
      return { steps: canvas.world.steps, vx: body.linearVelocity.x, vy: body.linearVelocity.y };
    });
    const expected = (FORCE * motion.steps * STEP) / MASS;
    assert.ok(motion.steps >= 1, `the world stepped (${motion.steps} steps)`);
    assert.ok(
      Math.abs(motion.vx - expected) < 1e-6 && Math.abs(motion.vy) < 1e-9,
      `v = F t / m = ${expected} m/s after ${motion.steps} steps (got ${motion.vx}, ${motion.vy})`,
    );
    assert.equal(
      await page.locator('#inertia [data-action="toggle-force"]').getAttribute('aria-pressed'),
      'true',
      'Apply force stays pressed once the world is built',
    );
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
    await server.close();
  }
});
