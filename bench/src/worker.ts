// One engine, one scene, one fresh process: builds the world (not timed), steps once (not timed),
// then times steps 1..N-1 with the scene's step callback inside the loop, and reports JSON over IPC
// (or stdout when run by hand).
import { PerformanceObserver, performance } from 'node:perf_hooks';
import { parseArgs } from 'node:util';
import { ENGINES } from './engines/index.ts';
import { measure, type Metrics } from './metrics.ts';
import { buildScene } from './scenes/index.ts';
import type { StepApi } from './types.ts';

export interface GcStats {
  /** gc events during the timed loop, by kind. */
  count: number;
  minor: number;
  major: number;
  other: number;
  /** Total gc pause (ms) during the timed loop. */
  totalMs: number;
  /** heapUsed after the loop minus before it, both after a forced gc (bytes): retained growth. */
  retainedBytes: number | null;
  /** heapUsed right after the loop minus right before it, no gc in between (bytes). */
  rawDeltaBytes: number;
}

export type WorkerResult =
  | {
      ok: true;
      engine: string;
      scene: string;
      settings: string;
      notes: string[];
      bodies: number;
      /** Steps timed (steps - 1 unless the time budget stopped the run). */
      timedSteps: number;
      plannedSteps: number;
      totalMs: number;
      msPerStep: number;
      setupMs: number;
      /** Step 0 alone (not timed in msPerStep): the cold step, before the JIT has tiered up. */
      firstStepMs: number;
      /**
       * Cumulative ms after each timed step (entry i = time of timed steps 1..i+1), so the runner
       * can compare every engine over the same steps when some runs stop early.
       */
      cumulativeMs: number[];
      metrics: Metrics;
      gc: GcStats;
    }
  | {
      ok: false;
      engine: string;
      scene: string;
      error: string;
      /** True when the engine cannot run this scene (error is the reason), not a crash. */
      unsupported?: boolean;
    };

const { values } = parseArgs({
  options: {
    engine: { type: 'string' },
    scene: { type: 'string' },
    small: { type: 'boolean', default: false },
    steps: { type: 'string' },
    budget: { type: 'string', default: '120' },
    // Steps 1..warmup run before the timed loop (JIT tiering, pools filling); 0 times from step 1.
    warmup: { type: 'string', default: '0' },
  },
});

function send(result: WorkerResult): void {
  if (process.send) process.send(result, () => process.exit(0));
  else {
    process.stdout.write(`${JSON.stringify(result)}\n`);
    process.exit(0);
  }
}

const gc = (globalThis as { gc?: () => void }).gc;

/** Untimed steps between the forced collection and the timed loop, when there is a warm-up. */
const SETTLE_STEPS = 10;

async function main(): Promise<void> {
  const engineId = values.engine ?? 'physical';
  const sceneName = values.scene ?? 'large_pyramid';
  const load = ENGINES[engineId];
  if (!load) throw new Error(`unknown engine ${engineId}`);
  const engine = await load();
  const scene = buildScene(sceneName, {
    small: values.small,
    ...(values.steps === undefined ? {} : { steps: Number(values.steps) }),
  });
  const budgetMs = Number(values.budget) * 1000;
  const unsupported = engine.unsupported?.[sceneName];
  if (unsupported !== undefined) {
    send({ ok: false, engine: engineId, scene: sceneName, error: unsupported, unsupported: true });
    return;
  }

  const t0 = performance.now();
  const world = engine.create(scene);
  const { createGroup, destroyGroup } = world;
  if (scene.createsGroups && (!createGroup || !destroyGroup)) {
    throw new Error(`${engineId} cannot create bodies while running`);
  }
  const noGroups = (): never => {
    throw new Error('this scene creates no groups');
  };
  const api: StepApi = {
    moveKinematicTo: world.moveKinematicTo.bind(world),
    createGroup: createGroup ? createGroup.bind(world) : noGroups,
    destroyGroup: destroyGroup ? destroyGroup.bind(world) : noGroups,
  };
  scene.onStep?.(0, api);
  const t1 = performance.now();
  world.step();
  const firstStepMs = performance.now() - t1;
  const setupMs = performance.now() - t0;
  const warmup = Math.min(Number(values.warmup), scene.steps - 2);
  // A forced full collection makes the next step of a JavaScript engine allocate again what the
  // collection threw away (measured: ~3.7 MB in the first step after it in large_pyramid, none
  // without it), so with a warm-up the collection comes SETTLE_STEPS before its end and the
  // loop starts after those steps; `retainedBytes` still counts from the collection.
  const settle = Math.min(SETTLE_STEPS, warmup);
  let step = 1;
  for (; step <= warmup - settle; step++) {
    scene.onStep?.(step, api);
    world.step();
  }
  gc?.();
  const heapBefore = process.memoryUsage().heapUsed;
  for (; step <= warmup; step++) {
    scene.onStep?.(step, api);
    world.step();
  }
  const heapLoopStart = process.memoryUsage().heapUsed;
  const gcStats: GcStats = {
    count: 0,
    minor: 0,
    major: 0,
    other: 0,
    totalMs: 0,
    retainedBytes: null,
    rawDeltaBytes: 0,
  };
  // Entries arrive after the synchronous loop; count those that started inside it.
  let timedFrom = Infinity;
  let timedTo = Infinity;
  const observer = new PerformanceObserver((list) => {
    for (const entry of list.getEntries()) {
      if (entry.startTime < timedFrom || entry.startTime > timedTo) continue;
      gcStats.count++;
      gcStats.totalMs += entry.duration;
      const kind = (entry as { detail?: { kind?: number } }).detail?.kind;
      // perf_hooks constants: NODE_PERFORMANCE_GC_MINOR = 1, MAJOR = 4, INCREMENTAL = 8, WEAKCB = 16.
      if (kind === 1) gcStats.minor++;
      else if (kind === 4) gcStats.major++;
      else gcStats.other++;
    }
  });
  observer.observe({ entryTypes: ['gc'] });

  const onStep = scene.onStep;
  let steps = 1 + warmup;
  // Preallocated, so recording a step's time allocates nothing inside the loop.
  const cumulative = new Float64Array(Math.max(0, scene.steps - 1 - warmup));
  const start = performance.now();
  timedFrom = start;
  for (; steps < scene.steps; steps++) {
    onStep?.(steps, api);
    world.step();
    const elapsed = performance.now() - start;
    cumulative[steps - 1 - warmup] = elapsed;
    if (elapsed > budgetMs) {
      steps++;
      break;
    }
  }
  timedTo = performance.now();
  const totalMs = timedTo - start;
  const heapAfterRaw = process.memoryUsage().heapUsed;
  // Let the observer deliver the loop's entries before we stop counting.
  await new Promise((resolve) => setTimeout(resolve, 0));
  observer.disconnect();
  gcStats.rawDeltaBytes = heapAfterRaw - heapLoopStart;
  if (gc) {
    gc();
    gcStats.retainedBytes = process.memoryUsage().heapUsed - heapBefore;
  }
  const timedSteps = steps - 1 - warmup;
  send({
    ok: true,
    engine: engineId,
    scene: sceneName,
    settings: engine.settings,
    notes: [...(scene.notes === undefined ? [] : [scene.notes]), ...world.notes],
    bodies: scene.bodies.length,
    timedSteps,
    plannedSteps: scene.steps - 1 - warmup,
    totalMs,
    msPerStep: totalMs / Math.max(1, timedSteps),
    setupMs,
    firstStepMs,
    cumulativeMs: Array.from(cumulative.subarray(0, timedSteps)),
    metrics: measure(scene, world),
    gc: gcStats,
  });
}

main().catch((error: unknown) => {
  send({
    ok: false,
    engine: values.engine ?? '?',
    scene: values.scene ?? '?',
    error: error instanceof Error ? error.message : String(error),
  });
});
