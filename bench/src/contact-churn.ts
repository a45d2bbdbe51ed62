// Contacts made and ended per step (issue 30, item 4), with the step time beside them, for
// Physical only: `npm run bench:churn -- --scenes tumbler,rain`. Every scene runs in this one
// process, after a fresh build of the engine (`npm run build -w @physical/engine`). With
// `--pairs`, it also counts how many of the contacts made were pairs ended the step before (the
// churn that keeping a parted pair, KEEP_GAP in contact-manager.ts, is for), from the live pairs
// read after each step outside the timed call; a pair made and ended within one step is not seen.
import { performance } from 'node:perf_hooks';
import { parseArgs } from 'node:util';
import { physical, physicalWorldOf } from './engines/physical.ts';
import { buildScene } from './scenes/index.ts';
import type { StepApi } from './types.ts';

/** The counters ContactManager keeps (internal: read through World.internals). */
interface Churn {
  readonly made: number;
  readonly destroyed: number;
  readonly count: number;
  readonly slots: { readonly shapes: Int32Array };
}

/** The live contacts' shape pairs, each as one number. */
function livePairs(manager: Churn): Set<number> {
  const pairs = new Set<number>();
  const shapes = manager.slots.shapes;
  for (let slot = 0; slot < manager.count; slot++) {
    pairs.add(shapes[2 * slot]! * 0x100000 + shapes[2 * slot + 1]!);
  }
  return pairs;
}

const { values } = parseArgs({
  options: {
    scenes: { type: 'string', default: 'tumbler,rain' },
    steps: { type: 'string' },
    pairs: { type: 'boolean', default: false },
  },
});

function median(list: number[]): number {
  const sorted = [...list].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 === 1 ? sorted[mid]! : 0.5 * (sorted[mid - 1]! + sorted[mid]!);
}

for (const name of values.scenes.split(',')) {
  const scene = buildScene(name, {
    small: false,
    ...(values.steps === undefined ? {} : { steps: Number(values.steps) }),
  });
  const bench = physical.create(scene);
  const world = physicalWorldOf(bench)!;
  const manager = (world as unknown as { internals(): { contactManager: Churn } }).internals()
    .contactManager;
  const api: StepApi = {
    moveKinematicTo: bench.moveKinematicTo.bind(bench),
    createGroup: (group) => bench.createGroup!(group),
    destroyGroup: (handle) => bench.destroyGroup!(handle),
  };
  const ms: number[] = [];
  let made = 0;
  let ended = 0;
  let contacts = 0;
  let remade = 0;
  let madeSeen = 0;
  let before = new Set<number>();
  let endedLast = new Set<number>();
  for (let step = 0; step < scene.steps; step++) {
    const made0 = manager.made;
    const ended0 = manager.destroyed;
    scene.onStep?.(step, api);
    const t = performance.now();
    bench.step();
    ms.push(performance.now() - t);
    // Step 0 makes every first contact: counted apart.
    if (step > 0) {
      made += manager.made - made0;
      ended += manager.destroyed - ended0;
      contacts += manager.count;
    }
    if (values.pairs) {
      const after = livePairs(manager);
      const endedNow = new Set<number>();
      for (const pair of before) if (!after.has(pair)) endedNow.add(pair);
      if (step > 0) {
        for (const pair of after) {
          if (before.has(pair)) continue;
          madeSeen++;
          if (endedLast.has(pair)) remade++;
        }
      }
      before = after;
      endedLast = endedNow;
    }
  }
  const n = scene.steps - 1;
  const timed = ms.slice(1);
  process.stdout.write(
    `${name}: ${n} steps; per step ${(made / n).toFixed(0)} contacts made, ` +
      `${(ended / n).toFixed(0)} ended, ${(contacts / n).toFixed(0)} alive; ` +
      `median ${median(timed).toFixed(2)} ms/step; first step ${ms[0]!.toFixed(1)} ms ` +
      `(${(ms[0]! / median(timed)).toFixed(1)}x the median)\n`,
  );
  if (values.pairs) {
    process.stdout.write(
      `  of the ${madeSeen} contacts made (seen after their step), ${remade} ` +
        `(${((100 * remade) / Math.max(madeSeen, 1)).toFixed(1)} %) were pairs ended the step before\n`,
    );
  }
}
