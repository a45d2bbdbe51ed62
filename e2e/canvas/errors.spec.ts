import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import type {} from './fixture-api.ts';

test('errors: a bad attribute is reported and the last good value kept; a bad property throws', async ({
  open,
}) => {
  const page = await open('/canvas/fixture.html');
  const messages: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') messages.push(message.text());
  });
  const result = await page.evaluate(() => {
    const canvas = document.querySelector('physical-canvas')!;
    const reported: string[] = [];
    canvas.addEventListener('attributeerror', (event) => reported.push(event.detail.error.message));
    canvas.setAttribute('pixels-per-meter', '40');
    canvas.setAttribute('pixels-per-meter', '-3');
    canvas.setAttribute('pixels-per-meter', 'NaN');
    canvas.setAttribute('background', 'not-a-colour');
    canvas.setAttribute('debug', 'contacts sparkles');
    let thrown = '';
    try {
      canvas.pixelsPerMeter = Number.NaN;
    } catch (error) {
      thrown = `${(error as Error).name}: ${(error as Error).message}`;
    }
    return {
      reported,
      thrown,
      pixelsPerMeter: canvas.pixelsPerMeter,
      background: canvas.background,
    };
  });
  assert.deepEqual(result.reported, [
    '<physical-canvas> pixels-per-meter: expected a finite number greater than 0, got "-3".',
    '<physical-canvas> pixels-per-meter: expected a finite number greater than 0, got "NaN".',
    '<physical-canvas> background: expected a CSS colour, got "not-a-colour".',
    '<physical-canvas> debug: expected overlay names among contacts, normals, aabbs, centers, velocities, sleep or all, got "contacts sparkles".',
  ]);
  assert.equal(
    result.thrown,
    'CanvasSettingError: <physical-canvas> pixels-per-meter: expected a finite number greater than 0, got NaN.',
  );
  assert.equal(result.pixelsPerMeter, 40);
  assert.equal(result.background, '#121212');
  assert.equal(messages.length, 4);
});

test('overlays: every debug overlay and collision arrows draw without errors', async ({ open }) => {
  const page = await open('/canvas/fixture.html');
  const drawn = await page.evaluate(() => {
    const { World, box, particle, wall, ManualFrameScheduler } = window.physical;
    const canvas = document.querySelector('physical-canvas')!;
    const scheduler = new ManualFrameScheduler();
    canvas.frameScheduler = scheduler;
    canvas.setAttribute('debug', 'all');
    canvas.collisionArrows = true;
    const world = new World();
    world.add(wall({ from: { x: 0, y: 5 }, to: { x: 8, y: 5 } }));
    world.add(box({ position: { x: 3, y: 3 }, width: 1, height: 1 }));
    world.add(particle({ position: { x: 5, y: 3 }, radius: 0.4 }));
    canvas.world = world;
    let overlays = 0;
    canvas.drawOverlay = () => overlays++;
    for (let i = 0; i < 120; i++) scheduler.advance(1000 / 60);
    return { overlays, frames: canvas.frameCount };
  });
  assert.ok(drawn.overlays > 30, JSON.stringify(drawn));
});
