import assert from 'node:assert/strict';
import type { Page } from 'playwright-core';
import type { WorkerWorld } from '@physical/worker';
import { test } from '../harness.ts';
import type {} from './fixture-api.ts';
import { screenPixels, waitFrames } from '../canvas/page-helpers.ts';

// 40 px/m, origin (0, 0), the canvas at the page's top-left (400 x 300 px = 10 x 7.5 m): a floor
// at y = 7 m and a 1 m box resting on it at x = 3 m, in a worker world the canvas draws.
async function setUp(page: Page, shared: boolean | null = null): Promise<void> {
  await page.evaluate(async (expectShared) => {
    const api = window.physicalWorker;
    const canvas = document.querySelector('physical-canvas')!;
    canvas.pixelsPerMeter = 40;
    const world = api.createWorkerWorld();
    if (expectShared !== null && world.isShared !== expectShared) {
      throw new Error(`isShared is ${world.isShared}`);
    }
    const floor = world.add({
      kind: 'box',
      type: 'static',
      position: { x: 5, y: 7.5 },
      width: 10,
      height: 1,
    });
    const a = world.add({ kind: 'box', position: { x: 3, y: 6.5 }, width: 1, height: 1 });
    canvas.world = world;
    Object.assign(window, { world, floor, a });
    await world.flush();
  }, shared);
  await waitFrames(page, 5);
}

const position = (page: Page, name: string) =>
  page.evaluate(async (key) => {
    const { world } = window as unknown as { world: WorkerWorld };
    await world.flush();
    return world.position((window as unknown as Record<string, number>)[key] as never);
  }, name);

const BACKGROUND = [0x12, 0x12, 0x12];
const isBackground = (rgba: number[]): boolean =>
  rgba.slice(0, 3).every((value, i) => Math.abs(value - BACKGROUND[i]!) <= 2);

test('worker: bodies added to a worker world are drawn by <physical-canvas>, removed ones vanish', async ({
  open,
}) => {
  const page = await open('/worker/fixture.html', { viewport: { width: 400, height: 300 } });
  await setUp(page);
  // Box a covers (100..140, 240..280) px; (200, 150) is empty.
  const [before, empty] = await screenPixels(page, [
    { x: 120, y: 260 },
    { x: 200, y: 150 },
  ]);
  assert.ok(!isBackground(before!), `box drawn: ${before}`);
  assert.ok(isBackground(empty!), `empty space: ${empty}`);
  await page.evaluate(() => {
    const w = window as unknown as { world: WorkerWorld; a: never };
    w.world.remove(w.a);
  });
  await waitFrames(page, 4);
  const [inBox] = await screenPixels(page, [{ x: 120, y: 260 }]);
  assert.ok(isBackground(inBox!), `removed box gone: ${inBox}`);
  const count = await page.evaluate(
    () => (window as unknown as { world: { bodies: unknown[] } }).world.bodies.length,
  );
  assert.equal(count, 1);
});

test('worker: a constant force with a duration moves a body as F = ma, then stops', async ({
  open,
}) => {
  const page = await open('/worker/fixture.html');
  const result = await page.evaluate(async () => {
    const world = window.physicalWorker.createWorkerWorld({ world: { gravity: { x: 0, y: 0 } } });
    // 1 m x 1 m at density 1: 1 kg. 2 N for 0.5 s: a = 2 m/s^2, v = 1 m/s at the end.
    const id = world.add({ kind: 'box', width: 1, height: 1, position: { x: 0, y: 0 } });
    world.applyForce(id, { x: 2, y: 0 }, { duration: 0.5 });
    for (let i = 0; i < 60; i++) world.step(1 / 60);
    await world.flush();
    const state = await world.getBody(id);
    return { x: world.position(id).x, vx: state!.linearVelocity.x };
  });
  // After 0.5 s of push and 0.5 s coasting at 1 m/s: x = a t^2 / 2 + 1 * 0.5 = 0.75 m.
  assert.ok(Math.abs(result.vx - 1) < 1e-9, `vx ${result.vx}`);
  assert.ok(Math.abs(result.x - 0.75) < 0.01, `x ${result.x}`);
});

test('worker: collision and contact events arrive batched, once per step, with body ids', async ({
  open,
}) => {
  const page = await open('/worker/fixture.html');
  const result = await page.evaluate(async () => {
    const world = window.physicalWorker.createWorkerWorld();
    const floor = world.add({ kind: 'wall', from: { x: -5, y: 2 }, to: { x: 5, y: 2 } });
    const ball = world.add({ kind: 'particle', radius: 0.25, position: { x: 0, y: 0 } });
    const sensor = world.add({
      kind: 'body',
      type: 'static',
      position: { x: 0, y: 1 },
      shapes: [{ type: 'circle', radius: 0.1, sensor: true }],
    });
    const log: string[] = [];
    const speeds: number[] = [];
    world.on('contactBegin', (event) => log.push(`begin ${event.bodyA}-${event.bodyB}`));
    world.on('sensorBegin', (event) =>
      log.push(`sensor ${event.sensorBody}<-${event.visitorBody}`),
    );
    world.on('collision', (event) => speeds.push(event.approachSpeed));
    const steps: number[] = [];
    world.on('frame', (step) => steps.push(step));
    for (let i = 0; i < 60; i++) world.step(1 / 60);
    await world.flush();
    return { floor, ball, sensor, log, speeds, steps: steps.length, applied: world.steps };
  });
  const { floor, ball, sensor } = result;
  assert.ok(result.log.includes(`sensor ${sensor}<-${ball}`), result.log.join());
  const begin = result.log.find((entry) => entry.startsWith('begin'));
  assert.ok(
    begin === `begin ${floor}-${ball}` || begin === `begin ${ball}-${floor}`,
    result.log.join(),
  );
  // It fell about 1.75 m: it hit at close to sqrt(2 g h) = 5.9 m/s.
  assert.ok(result.speeds.length > 0);
  assert.ok(Math.abs(result.speeds[0]! - Math.sqrt(2 * 9.81 * 1.75)) < 0.3, String(result.speeds));
  assert.equal(result.applied, 60);
});

test('worker: dragging a body of a worker world with the mouse moves it, and a fling throws it', async ({
  open,
}) => {
  const page = await open('/worker/fixture.html', { viewport: { width: 400, height: 300 } });
  await setUp(page);
  await page.mouse.move(120, 260);
  await page.mouse.down();
  await page.mouse.move(120, 120, { steps: 10 });
  await page.waitForTimeout(700);
  const held = await position(page, 'a');
  assert.ok(Math.hypot(held.x - 3, held.y - 3) < 0.25, JSON.stringify(held));
  await page.mouse.move(300, 120, { steps: 8 });
  await page.mouse.up();
  // Thrown right: it passes x = 5 m (the pointer let go at 7.5 m) within a few seconds.
  let flown = held;
  for (let i = 0; i < 30 && flown.x < 5; i++) {
    await page.waitForTimeout(100);
    flown = await position(page, 'a');
  }
  assert.ok(flown.x >= 5, `thrown from ${JSON.stringify(held)} reached ${JSON.stringify(flown)}`);
});

test('worker: bad input throws the same PhysicalError and field as in-thread; a crash is an error event', async ({
  open,
}) => {
  const page = await open('/worker/fixture.html');
  const result = await page.evaluate(async () => {
    const { World, PhysicalError, box, createWorkerWorld, createCrashingWorkerWorld } =
      window.physicalWorker;
    const world = createWorkerWorld();
    const local = new World();
    const fieldOf = (call: () => unknown): string => {
      try {
        call();
      } catch (error) {
        return error instanceof PhysicalError
          ? error.field
          : `not a PhysicalError: ${String(error)}`;
      }
      return 'nothing thrown';
    };
    const pairs = [
      [
        fieldOf(() => world.add({ kind: 'box', width: 1, height: 0 })),
        fieldOf(() => box({ width: 1, height: 0 })),
      ],
      [
        fieldOf(() =>
          world.add({ kind: 'particle', radius: 1, position: { x: Number.NaN, y: 0 } }),
        ),
        fieldOf(() =>
          local.add(
            window.physicalWorker.particle({ radius: 1, position: { x: Number.NaN, y: 0 } }),
          ),
        ),
      ],
      [fieldOf(() => (world.subSteps = 0)), fieldOf(() => (local.subSteps = 0))],
    ];
    const id = world.add({ kind: 'box', width: 1, height: 1 });
    const body = local.add(box({ width: 1, height: 1 }));
    pairs.push([
      fieldOf(() => world.applyImpulse(id, { x: Number.POSITIVE_INFINITY, y: 0 })),
      fieldOf(() => body.applyImpulse({ x: Number.POSITIVE_INFINITY, y: 0 })),
    ]);
    const crashing = createCrashingWorkerWorld();
    const message = await new Promise<string>((resolve) => {
      crashing.on('error', (error) => resolve(error.message));
      setTimeout(() => resolve('no error event'), 20_000);
    });
    return { pairs, message };
  });
  for (const [worker, inThread] of result.pairs) {
    assert.ok(!worker!.startsWith('no') && !worker!.startsWith('not'), worker);
    assert.equal(worker, inThread);
  }
  assert.match(result.message, /the physics worker failed/);
});

for (const isolated of [false, true]) {
  test(`worker: the worker world steps exactly as the same world on the page (${isolated ? 'shared' : 'transferred'} poses)`, async ({
    open,
  }) => {
    const page = await open(`/worker/fixture.html${isolated ? '?coi' : ''}`);
    assert.equal(await page.evaluate(() => crossOriginIsolated), isolated);
    const result = await page.evaluate(async () => {
      const { World, box, wall, createWorkerWorld, worldStateHash } = window.physicalWorker;
      const local = new World();
      const remote = createWorkerWorld();
      local.add(wall({ from: { x: -10, y: 10 }, to: { x: 10, y: 10 } }));
      remote.add({ kind: 'wall', from: { x: -10, y: 10 }, to: { x: 10, y: 10 } });
      const ids = [];
      for (let i = 0; i < 100; i++) {
        const options = {
          width: 0.4 + (i % 3) * 0.1,
          height: 0.4,
          position: { x: (i % 10) * 0.7 - 3.5, y: 9 - Math.floor(i / 10) * 0.6 },
          angle: (i % 7) * 0.05,
        };
        local.add(box(options));
        ids.push(remote.add({ kind: 'box', ...options }));
      }
      local.bodies[10]!.applyForce({ x: 20, y: 0 }, { duration: 1 });
      remote.applyForce(ids[9]!, { x: 20, y: 0 }, { duration: 1 });
      local.bodies[50]!.linearVelocity = { x: -3, y: -2 };
      remote.setLinearVelocity(ids[49]!, { x: -3, y: -2 });
      for (let i = 0; i < 200; i++) {
        local.step(1 / 60);
        remote.step(1 / 60);
      }
      await remote.flush();
      const body = local.bodies[50]!;
      return {
        shared: remote.isShared,
        local: worldStateHash(local),
        remote: await remote.stateHash(),
        pose: { x: body.position.x, y: body.position.y },
        streamed: remote.position(ids[49]!),
      };
    });
    assert.equal(result.shared, isolated);
    assert.equal(result.remote, result.local);
    // The streamed pose (float32) matches the page world's.
    assert.ok(Math.abs(result.streamed.x - result.pose.x) < 1e-5, JSON.stringify(result));
    assert.ok(Math.abs(result.streamed.y - result.pose.y) < 1e-5, JSON.stringify(result));
  });
}

test('worker: with an OffscreenCanvas the worker draws the world itself, stepped by run()', async ({
  open,
}) => {
  const page = await open('/worker/fixture.html', { viewport: { width: 400, height: 300 } });
  await page.evaluate(async () => {
    document.querySelector('physical-canvas')!.remove();
    const element = document.createElement('canvas');
    element.width = 400;
    element.height = 300;
    element.style.cssText = 'display: block; width: 400px; height: 300px;';
    document.body.append(element);
    const world = window.physicalWorker.createWorkerWorld({
      offscreen: { canvas: element.transferControlToOffscreen(), pixelsPerMeter: 40 },
    });
    world.add({ kind: 'box', type: 'static', position: { x: 5, y: 7.5 }, width: 10, height: 1 });
    const ball = world.add({ kind: 'particle', radius: 0.5, position: { x: 3, y: 1 } });
    world.run();
    // Falls about 5.5 m onto the floor (y = 7 m): wait until it rests there.
    for (let i = 0; i < 100 && world.position(ball).y < 6.4; i++) {
      await new Promise((resolve) => setTimeout(resolve, 50));
    }
  });
  await waitFrames(page, 5);
  // The ball rests centred at (3, 6.5) m = (120, 260) px; (300, 100) is empty.
  const [ball, empty, floor] = await screenPixels(page, [
    { x: 120, y: 260 },
    { x: 300, y: 100 },
    { x: 200, y: 290 },
  ]);
  assert.ok(!isBackground(ball!), `ball drawn: ${ball}`);
  assert.ok(isBackground(empty!), `empty: ${empty}`);
  assert.ok(!isBackground(floor!), `floor drawn: ${floor}`);
});

test('worker: collision arrows are drawn for a worker world from its collision events', async ({
  open,
}) => {
  const page = await open('/worker/fixture.html', { viewport: { width: 400, height: 300 } });
  // Drops a 0.25 m ball 4 m onto a floor in a worker world and counts the canvas' pixels in the
  // force-arrow colour (#ff8a65) after the impact, frame by frame: the most seen in up to `frames`
  // frames, stopping once `enough` are seen. The arrows' drawing code loads on first use, so on a
  // loaded machine they appear some frames after the impact (they fade over 5 s).
  const arrowPixels = (arrows: boolean, frames: number, enough: number) =>
    page.evaluate(
      async ({ on, frames, enough }) => {
        const canvas = document.querySelector('physical-canvas')!;
        canvas.pixelsPerMeter = 40;
        canvas.collisionArrows = on;
        canvas.collisionArrowDuration = 5;
        const world = window.physicalWorker.createWorkerWorld();
        world.add({ kind: 'wall', from: { x: 0, y: 6 }, to: { x: 10, y: 6 } });
        const ball = world.add({ kind: 'particle', radius: 0.25, position: { x: 5, y: 2 } });
        canvas.world = world;
        await world.flush();
        await new Promise<void>((resolve) => {
          const off = world.on('collision', (event) => {
            if (event.bodyA !== ball && event.bodyB !== ball) return;
            off();
            resolve();
          });
        });
        const source = canvas.shadowRoot!.querySelector('canvas')!;
        const copy = document.createElement('canvas');
        const context = copy.getContext('2d', { willReadFrequently: true })!;
        let most = 0;
        for (let frame = 0; frame < frames && most < enough; frame++) {
          await new Promise((resolve) => requestAnimationFrame(resolve));
          copy.width = source.width;
          copy.height = source.height;
          context.drawImage(source, 0, 0);
          const { data } = context.getImageData(0, 0, copy.width, copy.height);
          let count = 0;
          for (let i = 0; i < data.length; i += 4) {
            const [r, g, b] = [data[i]!, data[i + 1]!, data[i + 2]!];
            if (r > 200 && g > 100 && g < 170 && b > 60 && b < 130) count++;
          }
          most = Math.max(most, count);
        }
        canvas.world = null;
        world.terminate();
        return most;
      },
      { on: arrows, frames, enough },
    );
  const without = await arrowPixels(false, 8, Infinity);
  const withArrows = await arrowPixels(true, 120, 4 * without + 101);
  // Without arrows only a few anti-aliased edge pixels come near the colour.
  assert.ok(
    withArrows > 4 * without + 100,
    `the impact's arrows are drawn: ${withArrows} pixels in their colour, ${without} without`,
  );
});
