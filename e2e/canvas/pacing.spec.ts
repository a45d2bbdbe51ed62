import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import type {} from './fixture-api.ts';

// The same scene, driven by a manual scheduler at several display rates for 1 s of real time,
// must take the same 60 steps and end in bit-identical poses.
test('pacing: 60, 90, 120 and 144 Hz give the same body positions after 1 s', async ({ open }) => {
  const page = await open('/canvas/fixture.html');
  const results = await page.evaluate(() => {
    const { World, box, particle, wall, ManualFrameScheduler } = window.physical;
    return [60, 90, 120, 144].map((rate) => {
      const canvas = document.createElement('physical-canvas');
      document.body.append(canvas);
      const scheduler = new ManualFrameScheduler(1000);
      canvas.frameScheduler = scheduler;
      const world = new World();
      world.add(wall({ from: { x: 0, y: 5 }, to: { x: 8, y: 5 } }));
      for (let i = 0; i < 6; i++) {
        world.add(
          box({
            position: { x: 2 + 0.3 * i, y: 4 - 0.6 * i },
            width: 0.5,
            height: 0.5,
            angle: 0.2 * i,
          }),
        );
      }
      world.add(
        particle({
          position: { x: 5, y: 1 },
          radius: 0.3,
          restitution: 0.5,
          linearVelocity: { x: -1, y: 0 },
        }),
      );
      canvas.world = world;
      scheduler.advance(0); // the first frame counts no time
      for (let frame = 0; frame < rate; frame++) scheduler.advance(1000 / rate);
      const poses = world.bodies.map((body) => [body.position.x, body.position.y, body.angle]);
      canvas.remove();
      return { rate, steps: world.steps, frames: canvas.frameCount, poses };
    });
  });
  for (const result of results) {
    assert.equal(result.steps, 60, `${result.rate} Hz took ${result.steps} steps`);
    assert.equal(result.frames, result.rate + 1);
    assert.deepEqual(result.poses, results[0]!.poses, `${result.rate} Hz poses differ from 60 Hz`);
  }
});

test('pacing: after a stall the catch-up is capped and the backlog dropped', async ({ open }) => {
  const page = await open('/canvas/fixture.html');
  const steps = await page.evaluate(() => {
    const { World, box, ManualFrameScheduler } = window.physical;
    const canvas = document.querySelector('physical-canvas')!;
    const scheduler = new ManualFrameScheduler();
    canvas.frameScheduler = scheduler;
    const world = new World();
    world.add(box({ position: { x: 1, y: 1 }, width: 1, height: 1 }));
    canvas.world = world;
    scheduler.advance(0);
    scheduler.advance(1000 / 60);
    const before = world.steps;
    scheduler.advance(2000); // a 2 s stall
    const stall = world.steps - before;
    scheduler.advance(1000 / 60);
    return [before, stall, world.steps - before - stall];
  });
  assert.deepEqual(steps, [1, 4, 1]);
});
