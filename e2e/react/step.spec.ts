import assert from 'node:assert/strict';
import type { PhysicalCanvasElement } from '@physical/canvas';
import type { Body } from '@physical/engine';
import { test } from '../harness.ts';
import { waitFrames } from '../canvas/page-helpers.ts';

test('react: the ref of a paused <PhysicalCanvas> steps it once per step()', async ({ open }) => {
  const page = await open('/react/step.html', { viewport: { width: 400, height: 300 } });
  await waitFrames(page, 3);
  const result = await page.evaluate(async () => {
    const { crate, canvas } = window as unknown as {
      crate: Body;
      canvas: { current: PhysicalCanvasElement | null };
    };
    const y0 = crate.position.y;
    await new Promise((resolve) => setTimeout(resolve, 200));
    const pausedMoved = crate.position.y - y0;
    const steps = canvas.current!.stepCount;
    canvas.current!.step();
    canvas.current!.step();
    return {
      pausedMoved,
      steps: canvas.current!.stepCount - steps,
      vy: crate.linearVelocity.y,
      worldSteps: canvas.current!.world!.steps,
    };
  });
  assert.equal(result.pausedMoved, 0);
  assert.equal(result.steps, 2);
  assert.equal(result.worldSteps, 2);
  // Two steps of 1/60 s of free fall at the default gravity: v = g t.
  assert.ok(Math.abs(result.vy - (9.81 * 2) / 60) < 1e-9, `vy ${result.vy}`);
});
