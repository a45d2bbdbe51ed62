import { define } from '@physical/canvas';
import { World, box } from '@physical/engine';
import { WorkerWorld, type BodyId } from '@physical/worker';

define();

/** 2,000 boxes of 0.25 m in a 20 m x 15 m box (800 x 600 px at 40 px/m), falling into a pile. */
const BOXES = 2000;

function boxOptions(i: number): {
  width: number;
  height: number;
  position: { x: number; y: number };
} {
  const column = i % 50;
  const row = Math.floor(i / 50);
  return { width: 0.25, height: 0.25, position: { x: 0.6 + column * 0.38, y: 13.5 - row * 0.34 } };
}

const WALLS = [
  { type: 'static' as const, position: { x: 10, y: 15.25 }, width: 20, height: 0.5 },
  { type: 'static' as const, position: { x: -0.25, y: 7.5 }, width: 0.5, height: 15 },
  { type: 'static' as const, position: { x: 20.25, y: 7.5 }, width: 0.5, height: 15 },
];

interface Run {
  /** Bodies stepped so far (the canvas's steps for a page world, the applied steps for a worker world). */
  steps(): number;
  /** Gives the tapped body an upward impulse; returns a reader of its drawn y. */
  tap(): () => number;
  /** Pose bytes received so far. */
  bytes(): number;
  /** Frames drawn so far (page canvas), or steps applied (drawn in the worker). */
  frames(): number;
}

let run: Run | null = null;

/** Builds the pile on the page (`'page'`) or in a worker (`'worker'`) and lets the canvas run it. */
function start(where: 'page' | 'worker' | 'offscreen'): { shared: boolean } {
  const canvas = document.querySelector('physical-canvas')!;
  let frames = (): number => canvas.frameCount;
  if (where === 'page') {
    const world = new World();
    for (const wall of WALLS) world.add(box(wall));
    for (let i = 0; i < BOXES; i++) world.add(box(boxOptions(i)));
    const top = world.bodies[world.bodies.length - 1]!;
    canvas.world = world;
    run = {
      steps: () => world.steps,
      tap: () => {
        top.applyImpulse({ x: 0, y: -top.mass * 3 });
        return () => top.position.y;
      },
      bytes: () => 0,
      frames: () => frames(),
    };
    return { shared: false };
  }
  const worker = new Worker(new URL('./worker-bench.worker.ts', import.meta.url), {
    type: 'module',
  });
  let offscreen: OffscreenCanvas | null = null;
  if (where === 'offscreen') {
    // The worker draws: a plain canvas of the same size and density takes the element's place.
    const element = document.createElement('canvas');
    element.width = 800 * devicePixelRatio;
    element.height = 600 * devicePixelRatio;
    element.style.cssText = 'display: block; width: 800px; height: 600px;';
    canvas.replaceWith(element);
    offscreen = element.transferControlToOffscreen();
  }
  const world = new WorkerWorld(
    worker,
    offscreen === null
      ? {}
      : { offscreen: { canvas: offscreen, pixelsPerMeter: 40, devicePixelRatio } },
  );
  for (const wall of WALLS) world.add({ kind: 'box', ...wall });
  let top = 0 as BodyId;
  for (let i = 0; i < BOXES; i++) top = world.add({ kind: 'box', ...boxOptions(i) });
  let bytes = 0;
  let applied = 0;
  world.on('frame', () => {
    bytes += world.lastPoseBytes;
    applied++;
  });
  if (offscreen === null) canvas.world = world;
  else {
    world.run();
    frames = () => applied;
  }
  const mass = 0.25 * 0.25;
  run = {
    steps: () => world.steps,
    tap: () => {
      world.applyImpulse(top, { x: 0, y: -mass * 3 });
      return () => world.position(top).y;
    },
    bytes: () => bytes,
    frames: () => frames(),
  };
  return { shared: world.isShared };
}

/** Frames drawn, steps and pose bytes so far. */
function counters(): { frames: number; steps: number; bytes: number } {
  return { frames: run!.frames(), steps: run!.steps(), bytes: run!.bytes() };
}

let tapResult: Promise<number> | null = null;

/**
 * Arms a tap-to-move measurement (ms): from the next pointerdown on the canvas (its event time)
 * to the first animation frame after which the tapped body's drawn position has changed. Read it
 * with {@link tapLatency}.
 */
function armTap(): void {
  const canvas = document.querySelector('physical-canvas') ?? document.querySelector('canvas')!;
  tapResult = new Promise((resolve) => {
    canvas.addEventListener(
      'pointerdown',
      (event) => {
        const t0 = event.timeStamp;
        const y = run!.tap();
        const y0 = y();
        const check = (): void => {
          // rAF callbacks run in order: this one, requested after the canvas's, sees its frame.
          // The clock is read here, not taken from rAF's argument: that is the frame's start,
          // which can precede an event dispatched in the same frame.
          if (y() !== y0) resolve(performance.now() - t0);
          else requestAnimationFrame(check);
        };
        requestAnimationFrame(check);
      },
      { once: true, capture: true },
    );
  });
}

function tapLatency(): Promise<number> {
  return tapResult!;
}

Object.assign(window, { bench: { start, counters, armTap, tapLatency } });
document.documentElement.dataset['ready'] = 'true';
