import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import type {} from './fixture-api.ts';

// canvas.step() on a paused element: exactly one fixed step of free fall per call, drawn at once
// (the frame count moves with it), against v = g t and y = y0 + g h^2 m (m + 1) / 2 for the m
// semi-implicit Euler sub-steps of h = dt / subSteps the engine takes (velocity, then position).
test('step: a paused canvas advances exactly one fixed step per call and draws it', async ({
  open,
}) => {
  const page = await open('/canvas/fixture.html');
  const result = await page.evaluate(() => {
    const { World, box } = window.physical;
    const canvas = document.querySelector('physical-canvas')!;
    canvas.paused = true;
    canvas.stepsPerSecond = 50;
    const world = new World({ gravity: { x: 0, y: 10 } });
    const crate = world.add(box({ position: { x: 4, y: 1 }, width: 1, height: 1 }));
    canvas.world = world;
    const frames = canvas.frameCount;
    const rows: { y: number; vy: number; steps: number; frames: number }[] = [];
    for (let i = 0; i < 3; i++) {
      canvas.step();
      rows.push({
        y: crate.position.y,
        vy: crate.linearVelocity.y,
        steps: canvas.stepCount,
        frames: canvas.frameCount - frames,
      });
    }
    let error = '';
    canvas.world = null;
    try {
      canvas.step();
    } catch (caught) {
      error = (caught as Error).message;
    }
    return { rows, error, subSteps: world.subSteps };
  });
  const dt = 1 / 50;
  result.rows.forEach((row, index) => {
    const n = index + 1;
    assert.equal(row.steps, n);
    assert.equal(row.frames, n);
    assert.ok(Math.abs(row.vy - 10 * n * dt) < 1e-9, `v after ${n} steps: ${row.vy}`);
    const m = n * result.subSteps;
    const h = dt / result.subSteps;
    const y = 1 + (10 * h * h * m * (m + 1)) / 2;
    assert.ok(Math.abs(row.y - y) < 1e-9, `y after ${n} steps: ${row.y}, expected ${y}`);
  });
  assert.match(result.error, /world/);
});

test('step: the paused world does not move between calls', async ({ open }) => {
  const page = await open('/canvas/fixture.html');
  const moved = await page.evaluate(async () => {
    const { World, box } = window.physical;
    const canvas = document.querySelector('physical-canvas')!;
    canvas.paused = true;
    const world = new World();
    const crate = world.add(box({ position: { x: 4, y: 1 }, width: 1, height: 1 }));
    canvas.world = world;
    canvas.step();
    const y = crate.position.y;
    await new Promise((resolve) => setTimeout(resolve, 300));
    return crate.position.y - y;
  });
  assert.equal(moved, 0);
});
