// Runs in Chromium: steps Physical on the 1,000-box pile and leaves the result on window.
import { physical } from '../src/engines/physical.ts';
import { pile } from '../src/scenes/pile.ts';

interface PageResult {
  steps: number;
  medianMs: number;
  meanMs: number;
  minMs: number;
  nan: number;
  userAgent: string;
}

function run(): PageResult {
  const scene = pile();
  const world = physical.create(scene);
  world.step(); // step 0: not timed
  const times: number[] = [];
  for (let i = 1; i < scene.steps; i++) {
    const t0 = performance.now();
    world.step();
    times.push(performance.now() - t0);
  }
  let nan = 0;
  for (let i = 1; i < scene.bodies.length; i++) {
    const p = world.pose(i);
    if (!Number.isFinite(p.x) || !Number.isFinite(p.y)) nan++;
  }
  const sorted = [...times].sort((a, b) => a - b);
  return {
    steps: times.length,
    medianMs: sorted[Math.floor(sorted.length / 2)]!,
    meanMs: times.reduce((a, b) => a + b, 0) / times.length,
    minMs: sorted[0]!,
    nan,
    userAgent: navigator.userAgent,
  };
}

const target = window as unknown as { benchResult?: PageResult; benchError?: string };
setTimeout(() => {
  try {
    target.benchResult = run();
  } catch (error) {
    target.benchError = String(error);
  }
  document.body.textContent = JSON.stringify(target.benchResult ?? target.benchError);
}, 100);
