import assert from 'node:assert/strict';
import type { Body } from '@physical/engine';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import type {} from './fixture-api.ts';
import { waitFrames } from './page-helpers.ts';

// 40 px/m, origin (0, 0), the element at the page's top-left: a floor at y = 7 m (280 px) and
// two 1 m boxes resting on it, centred at x = 3 m (120 px) and x = 7 m (280 px).
async function setUp(page: Page, drag?: string): Promise<void> {
  await page.evaluate((dragAttribute) => {
    const { World, box } = window.physical;
    const canvas = document.querySelector('physical-canvas')!;
    canvas.pixelsPerMeter = 40;
    if (dragAttribute !== undefined) canvas.setAttribute('drag', dragAttribute);
    const world = new World();
    world.add(box({ type: 'static', position: { x: 5, y: 7.5 }, width: 10, height: 1 }));
    const a = world.add(box({ position: { x: 3, y: 6.5 }, width: 1, height: 1, userData: 'a' }));
    const b = world.add(box({ position: { x: 7, y: 6.5 }, width: 1, height: 1, userData: 'b' }));
    canvas.world = world;
    Object.assign(window, { a, b });
  }, drag);
  await waitFrames(page, 5);
}

const pose = (page: Page, name: 'a' | 'b') =>
  page.evaluate((key) => {
    const body = (window as unknown as Record<string, Body>)[key]!;
    return { x: body.position.x, y: body.position.y, vx: body.linearVelocity.x };
  }, name);

test('drag: a pressed body follows the mouse, and a fling throws it', async ({ open }) => {
  const page = await open('/canvas/fixture.html', { viewport: { width: 400, height: 300 } });
  // The throw takes the pointer's speed over its last 80 ms (pointer-input.ts). On a loaded machine
  // the release can reach the page later than that after the last move, which rightly throws
  // nothing, as do moves that reach it more than 80 ms apart. So the page records the times, and
  // the fling is tried again (up to 4 times) until its last two moves came within 50 ms of each
  // other and its release within 50 ms of the last.
  await page.evaluate(() => {
    const canvas = document.querySelector('physical-canvas')!;
    const times = { previous: 0, move: 0, up: 0 };
    canvas.addEventListener('pointermove', (event) => {
      times.previous = times.move;
      times.move = event.timeStamp;
    });
    canvas.addEventListener('pointerup', (event) => (times.up = event.timeStamp));
    Object.assign(window, { pointerTimes: times });
  });
  const releaseGap = () =>
    page.evaluate(() => {
      const times = (
        window as unknown as { pointerTimes: { previous: number; move: number; up: number } }
      ).pointerTimes;
      return Math.max(times.up - times.move, times.move - times.previous);
    });
  let flung = false;
  for (let attempt = 0; attempt < 4 && !flung; attempt++) {
    await setUp(page);
    await page.mouse.move(120, 260);
    await page.mouse.down();
    await page.mouse.move(120, 120, { steps: 10 });
    await page.waitForTimeout(700);
    const held = await pose(page, 'a');
    // Held by the point pressed (its centre): near the pointer at (3, 3) m.
    assert.ok(Math.hypot(held.x - 3, held.y - 3) < 0.2, JSON.stringify(held));
    await page.mouse.move(300, 120, { steps: 8 });
    await page.mouse.up();
    const thrown = await pose(page, 'a');
    await page.waitForTimeout(100);
    const later = await pose(page, 'a');
    // The other body never moved.
    const other = await pose(page, 'b');
    assert.ok(
      Math.abs(other.x - 7) < 0.01 && Math.abs(other.y - 6.5) < 0.02,
      JSON.stringify(other),
    );
    if ((await releaseGap()) > 50) continue;
    assert.ok(thrown.vx > 1, `thrown at ${thrown.vx} m/s`);
    assert.ok(later.x > thrown.x + 0.1, `flew from ${thrown.x} to ${later.x}`);
    flung = true;
  }
  assert.ok(flung, 'in 4 flings the moves and release never came within 50 ms of each other');
});

test('drag: drag="off" leaves bodies where they are; taps still fire', async ({ open }) => {
  const page = await open('/canvas/fixture.html', { viewport: { width: 400, height: 300 } });
  await setUp(page, 'off');
  assert.equal(await page.evaluate(() => document.querySelector('physical-canvas')!.drag), false);
  const events: string[] = [];
  await page.exposeFunction('record', (type: string) => events.push(type));
  await page.evaluate(() => {
    const canvas = document.querySelector('physical-canvas')!;
    for (const type of ['bodypress', 'bodyrelease', 'bodytap'] as const) {
      canvas.addEventListener(type, () =>
        (window as unknown as { record(t: string): void }).record(type),
      );
    }
  });
  await page.mouse.move(120, 260);
  await page.mouse.down();
  await page.mouse.move(120, 120, { steps: 10 });
  await page.waitForTimeout(300);
  await page.mouse.up();
  await page.mouse.click(120, 260);
  const still = await pose(page, 'a');
  assert.ok(Math.abs(still.x - 3) < 0.01 && Math.abs(still.y - 6.5) < 0.02, JSON.stringify(still));
  assert.deepEqual(events, ['bodypress', 'bodyrelease', 'bodypress', 'bodyrelease', 'bodytap']);
  // Turned back on by the property, the same drag lifts it.
  await page.evaluate(() => {
    document.querySelector('physical-canvas')!.drag = true;
  });
  await page.mouse.move(120, 260);
  await page.mouse.down();
  await page.mouse.move(120, 120, { steps: 10 });
  await page.waitForTimeout(500);
  const lifted = await pose(page, 'a');
  await page.mouse.up();
  assert.ok(lifted.y < 4, `lifted to ${lifted.y} m`);
});

test('drag: two fingers drag two bodies; a pen drags too', async ({ open }) => {
  const page = await open('/canvas/fixture.html', {
    viewport: { width: 400, height: 300 },
    hasTouch: true,
  });
  await setUp(page);
  const session = await page.context().newCDPSession(page);
  const touch = (
    type: 'touchStart' | 'touchMove' | 'touchEnd',
    points: { x: number; y: number; id: number }[],
  ) => session.send('Input.dispatchTouchEvent', { type, touchPoints: points });
  await touch('touchStart', [
    { x: 120, y: 260, id: 1 },
    { x: 280, y: 260, id: 2 },
  ]);
  for (let i = 1; i <= 10; i++) {
    await touch('touchMove', [
      { x: 120, y: 260 - 14 * i, id: 1 },
      { x: 280, y: 260 - 14 * i, id: 2 },
    ]);
    await page.waitForTimeout(16);
  }
  await page.waitForTimeout(500);
  const [a, b] = [await pose(page, 'a'), await pose(page, 'b')];
  await touch('touchEnd', []);
  assert.ok(a.y < 4 && b.y < 4, `both lifted: ${a.y}, ${b.y}`);
  await page.waitForTimeout(1500); // they fall back

  const pen = (type: 'mousePressed' | 'mouseMoved' | 'mouseReleased', x: number, y: number) =>
    session.send('Input.dispatchMouseEvent', {
      type,
      x,
      y,
      button: 'left',
      buttons: type === 'mouseReleased' ? 0 : 1,
      clickCount: 1,
      pointerType: 'pen',
    });
  const start = await pose(page, 'b');
  await pen('mousePressed', start.x * 40, start.y * 40);
  for (let i = 1; i <= 10; i++)
    await pen('mouseMoved', start.x * 40 - 12 * i, start.y * 40 - 12 * i);
  await page.waitForTimeout(500);
  const penned = await pose(page, 'b');
  await pen('mouseReleased', start.x * 40 - 120, start.y * 40 - 120);
  assert.ok(penned.y < start.y - 2 && penned.x < start.x - 2, JSON.stringify([start, penned]));
});
