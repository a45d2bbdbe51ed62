import assert from 'node:assert/strict';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import { phoneOptions } from './fit.ts';
import { assertQuiet, closeApp, numberIn, openApp, readout } from './phone.ts';

const sleep = (ms: number): Promise<void> => new Promise((resolve) => setTimeout(resolve, ms));
/** The body's mass (kg) and the push per metre of drag (N/m), as the app states them. */
const MASS = 1;
const PUSH_PER_METRE = 2;
/** Steps taken with the Step button while pushed, and after. */
const STEPS = 12;

/** Simulated time and speed, read together from the readouts (one render shows both). */
async function timeAndSpeed(page: Page): Promise<{ t: number; v: number }> {
  const [time, speed] = await page.evaluate(() =>
    ['time', 'speed'].map(
      (name) => document.querySelector(`#inertia [data-readout="${name}"]`)?.textContent ?? '',
    ),
  );
  return { t: numberIn(time!), v: numberIn(speed!) };
}

/** Where the body's centre and a point `dx` metres right of it are, in page pixels. */
async function bodyOnPage(page: Page, dx: number) {
  return page.evaluate((metres) => {
    type Vec = { x: number; y: number };
    const canvas = document.querySelector('#inertia physical-canvas') as HTMLElement & {
      world: { bodies: readonly { type: string; position: Vec }[] };
      worldToScreen(point: Vec): Vec;
    };
    const body = canvas.world.bodies.find((item) => item.type === 'dynamic')!;
    const box = canvas.getBoundingClientRect();
    const at = (point: Vec) => {
      const screen = canvas.worldToScreen(point);
      return { x: box.x + screen.x, y: box.y + screen.y };
    };
    return {
      centre: at(body.position),
      pulled: at({ x: body.position.x + metres, y: body.position.y }),
    };
  }, dx);
}

/** Acceleration between two readings at least `ms` apart (m/s^2). */
async function measuredAcceleration(page: Page, ms: number): Promise<number> {
  const first = await timeAndSpeed(page);
  await sleep(ms);
  let second = await timeAndSpeed(page);
  for (let i = 0; i < 20 && second.t - first.t < 0.3; i++) {
    await sleep(100);
    second = await timeAndSpeed(page);
  }
  assert.ok(second.t - first.t >= 0.3, `time went on (${first.t} s to ${second.t} s)`);
  return (second.v - first.v) / (second.t - first.t);
}

test('newton: inertia push at 375x667, a student presses on the body and pulls 1 m: 2 N, v = F t / m step by step, and constant once let go', async ({
  browser,
}) => {
  const app = await openApp(browser, '#inertia', phoneOptions(375, 667, false));
  const { page } = app;
  try {
    // Paused, so the motion is read step by step (Step is a tap with another finger).
    await page.locator('#inertia [data-action="play"]').tap();
    const { centre, pulled } = await bodyOnPage(page, 1);
    // A real touch (touchstart, moves, and the finger held still), as a phone sends it.
    const cdp = await page.context().newCDPSession(page);
    const touch = async (type: 'touchStart' | 'touchMove' | 'touchEnd', x = 0, y = 0) =>
      cdp.send('Input.dispatchTouchEvent', {
        type,
        touchPoints: type === 'touchEnd' ? [] : [{ x, y, id: 1 }],
      });
    await touch('touchStart', centre.x, centre.y);
    for (let i = 1; i <= 8; i++) {
      await touch(
        'touchMove',
        centre.x + ((pulled.x - centre.x) * i) / 8,
        centre.y + ((pulled.y - centre.y) * i) / 8,
      );
    }
    // The push is the applied force: 1 m of pull, 2 N, to the right (0°).
    await page.waitForFunction(() =>
      /^push/.test(document.querySelector('#inertia [data-readout="force"]')?.textContent ?? ''),
    );
    const force = await readout(page, 'force', '#inertia');
    assert.match(force, /^push 2(\.0)? N, 0°$/, `the force readout shows the push (${force})`);
    assert.match(
      (await page.locator('#inertia physical-canvas').getAttribute('aria-label')) ?? '',
      /A push by hand of 2(\.0)?\sN at 0° acts on it\./,
    );
    // 12 steps of 1/60 s pushed from rest: v = F t / m = 2 N x 0.2 s / 1 kg = 0.4 m/s.
    const step = page.locator('#inertia [data-action="step"]');
    for (let i = 0; i < STEPS; i++) await step.click();
    const pushed = await timeAndSpeed(page);
    const expected = (PUSH_PER_METRE * 1 * (STEPS / 60)) / MASS;
    assert.ok(Math.abs(pushed.t - STEPS / 60) < 0.006, `t = ${pushed.t} s after ${STEPS} steps`);
    assert.ok(
      Math.abs(pushed.v - expected) <= 1e-3,
      `v = F t / m while pushed: ${pushed.v} m/s, expected ${expected} m/s`,
    );
    assert.equal(await readout(page, 'direction', '#inertia'), '0°');

    // Let go: no force, the body glides on at the speed it had (first law, on ice).
    await touch('touchEnd');
    await page.waitForFunction(
      () => document.querySelector('#inertia [data-readout="force"]')?.textContent === 'off',
    );
    for (let i = 0; i < STEPS; i++) await step.click();
    const coasting = await timeAndSpeed(page);
    assert.ok(coasting.t > pushed.t + 0.15, `time went on (${coasting.t} s)`);
    assert.ok(
      Math.abs(coasting.v - expected) <= 1e-3,
      `constant speed once let go: ${coasting.v} m/s, expected ${expected} m/s`,
    );
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: inertia push by keyboard at 375x667, an arrow key held on the canvas pushes 2 N that way until let go', async ({
  browser,
}) => {
  const app = await openApp(browser, '#inertia', phoneOptions(375, 667, false));
  const { page } = app;
  try {
    await page.locator('#inertia physical-canvas').focus();
    await page.keyboard.down('ArrowUp');
    await sleep(300);
    const force = await readout(page, 'force', '#inertia');
    assert.match(force, /^push 2(\.0)? N, 90°$/, `the force readout shows the push (${force})`);
    const a = await measuredAcceleration(page, 500);
    assert.ok(Math.abs(a - 2 / MASS) <= 0.1, `a = F/m while the key is held: ${a} m/s^2`);
    assert.equal(await readout(page, 'direction', '#inertia'), '90°');
    await page.keyboard.up('ArrowUp');
    await sleep(300);
    assert.equal(await readout(page, 'force', '#inertia'), 'off');
    const coasting = await measuredAcceleration(page, 400);
    assert.ok(Math.abs(coasting) <= 0.01, `constant speed once let go: ${coasting} m/s^2`);
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});
