// `npm run bench`: Box2D v3's benchmark scenes in Physical and the peer engines. Every engine-scene
// pair runs in a fresh Node process (worker.ts); engines are interleaved within each scene, rounds
// repeat the whole sweep; the table gives median and min ms/step over rounds.
import { fork, spawnSync } from 'node:child_process';
import { existsSync, writeFileSync } from 'node:fs';
import { cpus } from 'node:os';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import { ENGINES, NOT_BY_DEFAULT } from './engines/index.ts';
import { SCENES, UNSUPPORTED } from './scenes/index.ts';
import type { SizeReport } from './size.ts';
import type { WorkerResult } from './worker.ts';

const { values } = parseArgs({
  options: {
    scenes: { type: 'string' },
    engines: { type: 'string' },
    rounds: { type: 'string' },
    quick: { type: 'boolean', default: false },
    json: { type: 'string' },
    browser: { type: 'boolean', default: false },
    budget: { type: 'string' },
    steps: { type: 'string' },
    'no-build': { type: 'boolean', default: false },
    'no-scaling': { type: 'boolean', default: false },
    help: { type: 'boolean', short: 'h', default: false },
  },
});

if (values.help) {
  process.stdout
    .write(`npm run bench -- [options]: Box2D v3's benchmark scenes in Physical and the peer engines.
  --scenes a,b      scenes to run (default: all)
  --engines a,b     engines to compare (default: all)
  --rounds N        sweeps over every scene and engine (default 3; 1 with --quick)
  --quick           a smoke run: 10 steps, one round
  --budget S        seconds each engine may spend on a scene (default 90)
  --steps N         every engine times the same first N steps of each scene
  --json FILE       also write the results as JSON
  --browser         also time a 1,000-box pile of Physical in Chromium
  --no-build        measure the engine's existing build (packages/engine/dist)
  --no-scaling      skip Physical's per-body cost scaling run
`);
  process.exit(0);
}

const log = (line = ''): void => void process.stdout.write(`${line}\n`);
const progress = (line: string): void => void process.stderr.write(`${line}\n`);

const quick = values.quick;
const rounds = Number(values.rounds ?? (quick ? 1 : 3));
const budgetSeconds = Number(values.budget ?? 90);
const QUICK_STEPS = 10;
// --steps N: every engine times the same first N steps of each scene (a shorter, like-for-like run).
const fixedSteps = values.steps === undefined ? null : Number(values.steps);
if (fixedSteps !== null && !(Number.isInteger(fixedSteps) && fixedSteps >= 1)) {
  throw new Error(`--steps must be a whole number of steps >= 1, got ${values.steps}`);
}
const allScenes = [...Object.keys(SCENES), ...Object.keys(UNSUPPORTED)].sort();
const sceneNames = values.scenes ? values.scenes.split(',').map((s) => s.trim()) : allScenes;
const engineIds = values.engines
  ? values.engines.split(',').map((s) => s.trim())
  : Object.keys(ENGINES).filter((e) => !NOT_BY_DEFAULT.has(e));
for (const s of sceneNames) {
  if (!SCENES[s] && !UNSUPPORTED[s]) throw new Error(`unknown scene ${s}; known: ${allScenes}`);
}
for (const e of engineIds) {
  if (!ENGINES[e]) throw new Error(`unknown engine ${e}; known: ${Object.keys(ENGINES)}`);
}
const runnable = sceneNames.filter((s) => SCENES[s]);

// ---- Physical is measured from its tsc build (packages/engine/dist), like an app would use it. ----
const root = fileURLToPath(new URL('../..', import.meta.url));
if (!values['no-build']) {
  progress('building @physical/engine (tsc) ...');
  const built = spawnSync('npm', ['run', 'build', '-w', '@physical/engine'], {
    cwd: root,
    encoding: 'utf8',
  });
  if (built.status !== 0) {
    const errors = `${built.stdout}${built.stderr}`
      .split('\n')
      .filter((l) => l.includes('error TS'))
      .slice(0, 5);
    log(`WARNING: the engine build reported errors (tsc still emits dist/ unless it cannot):`);
    for (const e of errors) log(`  ${e}`);
  }
}
if (!existsSync(`${root}/packages/engine/dist/index.js`)) {
  throw new Error('packages/engine/dist/index.js is missing: the engine build failed');
}

// ---- Workers ----
const workerPath = fileURLToPath(new URL('./worker.ts', import.meta.url));

function runWorker(engine: string, scene: string, extra: string[] = []): Promise<WorkerResult> {
  return new Promise((resolve) => {
    const args = [
      '--engine',
      engine,
      '--scene',
      scene,
      '--budget',
      String(budgetSeconds),
      ...extra,
    ];
    if (quick) args.push('--small', '--steps', String(QUICK_STEPS));
    // The worker's --steps counts step 0 (untimed); a caller's own --steps in `extra` wins.
    else if (fixedSteps !== null && !extra.includes('--steps')) {
      args.push('--steps', String(fixedSteps + 1));
    }
    const child = fork(workerPath, args, {
      execArgv: ['--import', 'tsx', '--expose-gc'],
      stdio: ['ignore', 'ignore', 'pipe', 'ipc'],
    });
    let stderr = '';
    let result: WorkerResult | null = null;
    child.stderr?.on('data', (chunk: Buffer) => (stderr += chunk.toString()));
    child.on('message', (message) => (result = message as WorkerResult));
    // Building the world is not timed but counts here; allow it generously.
    const timer = setTimeout(() => child.kill('SIGKILL'), (budgetSeconds + 300) * 1000);
    child.on('exit', (code, signal) => {
      clearTimeout(timer);
      resolve(
        result ?? {
          ok: false,
          engine,
          scene,
          error: `worker exited (${signal ?? code}) without a result: ${stderr.trim().split('\n').slice(-3).join(' | ')}`,
        },
      );
    });
  });
}

type Ok = Extract<WorkerResult, { ok: true }>;
const results = new Map<string, WorkerResult[]>();
const key = (scene: string, engine: string): string => `${scene}\u0000${engine}`;

log(
  `Physical benchmark: Box2D v3's scenes (${quick ? 'QUICK smoke run: Box2D debug sizes' : 'full size'})`,
);
log(
  `machine: ${cpus()[0]?.model ?? '?'} x${cpus().length}, node ${process.version}; rounds ${rounds}; ` +
    `1/60 s steps, step 0 not timed, scene callbacks inside the timed loop; one fresh process per engine-scene-round; ` +
    `engines interleaved; per-run time budget ${budgetSeconds} s${quick ? `; ${QUICK_STEPS} steps per scene` : ''}`,
);
log();

for (let round = 1; round <= rounds; round++) {
  for (const scene of runnable) {
    for (const engine of engineIds) {
      const r = await runWorker(engine, scene);
      const list = results.get(key(scene, engine)) ?? [];
      list.push(r);
      results.set(key(scene, engine), list);
      progress(
        `round ${round}/${rounds} ${scene} ${engine}: ${r.ok ? `${r.msPerStep.toFixed(3)} ms/step (${r.timedSteps} steps)` : r.unsupported ? `unsupported: ${r.error}` : `FAILED ${r.error}`}`,
      );
    }
  }
}

// ---- Table ----
const median = (xs: number[]): number => {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m]! : (s[m - 1]! + s[m]!) / 2;
};

interface Row {
  scene: string;
  engine: string;
  medianMsPerStep: number | null;
  minMsPerStep: number | null;
  steps: number | null;
  ratio: number | null;
  quality: string;
}

const rows: Row[] = [];
const sinks = new Map<string, number>();
const standing = new Map<string, boolean>();
const steps = new Map<string, number>();
for (const scene of runnable) {
  for (const engine of engineIds) {
    const ok = (results.get(key(scene, engine)) ?? []).filter((r): r is Ok => r.ok);
    if (ok.length && ok[0]!.metrics.topSink !== undefined) {
      sinks.set(key(scene, engine), median(ok.map((r) => r.metrics.topSink!)));
      steps.set(key(scene, engine), Math.min(...ok.map((r) => r.timedSteps)));
      standing.set(
        key(scene, engine),
        ok.every((r) => r.metrics.nan === 0 && r.metrics.maxLateral! <= r.metrics.lateralLimit!),
      );
    }
  }
}
const SINK_TOLERANCE = 0.001;
// Box2D v2's polygons carry a 0.01 m skin (b2_polygonRadius), so touching boxes push apart and a v2
// stack stands taller than it was built: its "sink" is negative by construction, not by stiffness.
// The best-peer baseline is therefore taken over the engines without a skin.
const SKIN_ENGINES = new Set(['box2d-wasm', '@box2d/core', 'planck']);

function qualityOf(scene: string, engine: string, runs: Ok[]): string {
  const problems = new Set<string>();
  for (const r of runs) {
    const m = r.metrics;
    if (m.nan > 0) problems.add(`NaN in ${m.nan} bodies`);
    if (m.maxLateral !== undefined && m.maxLateral > m.lateralLimit!) {
      problems.add(`a box moved ${m.maxLateral.toFixed(3)} m sideways (> ${m.lateralLimit} m)`);
    }
    if (m.outside !== undefined && m.outside > 0) {
      problems.add(`${m.outside} boxes outside the container`);
    }
  }
  const sink = sinks.get(key(scene, engine));
  if (sink !== undefined) {
    let best = Infinity;
    let bestEngine = '';
    for (const other of engineIds) {
      if (other === engine || SKIN_ENGINES.has(other) || !standing.get(key(scene, other))) continue;
      // Compare sinks only between runs that timed the same number of steps.
      if (steps.get(key(scene, other)) !== steps.get(key(scene, engine))) continue;
      const s = sinks.get(key(scene, other));
      if (s !== undefined && s < best) {
        best = s;
        bestEngine = other;
      }
    }
    if (best < Infinity && sink > best + SINK_TOLERANCE) {
      problems.add(
        `top box sank ${sink.toFixed(3)} m > best peer ${best.toFixed(3)} m (${bestEngine})`,
      );
    }
  }
  return problems.size ? [...problems].join('; ') : 'ok';
}

// Like for like: within a scene every compared engine's ms/step covers the same first K timed
// steps, K being the fewest that any of them timed within its budget (a scene's early steps are
// cheaper than its later ones, so runs cut at different points are not comparable). A peer too slow
// to time half as many steps as Physical would cut the window to the scene's first moments for
// everyone: it is shown over its own steps, without a ratio.
interface Window {
  steps: number;
  planned: number;
  compared: Set<string>;
}
function windowOf(scene: string): Window | null {
  const reached = new Map<string, number>();
  let planned = 0;
  for (const engine of engineIds) {
    const ok = (results.get(key(scene, engine)) ?? []).filter((r): r is Ok => r.ok);
    if (!ok.length) continue;
    reached.set(engine, Math.min(...ok.map((r) => r.timedSteps)));
    planned = Math.max(planned, ...ok.map((r) => r.plannedSteps));
  }
  if (reached.size === 0) return null;
  const physicalSteps = reached.get('physical');
  const floor = physicalSteps === undefined ? 0 : physicalSteps / 2;
  const compared = new Set([...reached].filter(([, n]) => n >= floor).map(([e]) => e));
  const steps = Math.min(...[...compared].map((e) => reached.get(e)!));
  return { steps, planned, compared };
}
/** ms/step of one run over its first `steps` timed steps. */
const msOver = (r: Ok, steps: number): number =>
  steps >= r.timedSteps ? r.msPerStep : r.cumulativeMs[steps - 1]! / steps;

for (const scene of sceneNames) {
  if (UNSUPPORTED[scene]) {
    rows.push({
      scene,
      engine: 'physical',
      medianMsPerStep: null,
      minMsPerStep: null,
      steps: null,
      ratio: null,
      quality: UNSUPPORTED[scene],
    });
    continue;
  }
  const window = windowOf(scene);
  const physicalRuns = (results.get(key(scene, 'physical')) ?? []).filter((r): r is Ok => r.ok);
  const physicalMedian =
    physicalRuns.length && window ? median(physicalRuns.map((r) => msOver(r, window.steps))) : null;
  for (const engine of engineIds) {
    const runs = results.get(key(scene, engine)) ?? [];
    const ok = runs.filter((r): r is Ok => r.ok);
    if (!ok.length) {
      const failed = runs.find((r) => !r.ok);
      rows.push({
        scene,
        engine,
        medianMsPerStep: null,
        minMsPerStep: null,
        steps: null,
        ratio: null,
        quality:
          failed && !failed.ok
            ? failed.unsupported
              ? `unsupported: ${failed.error}`
              : `failed: ${failed.error}`
            : 'failed: no runs',
      });
      continue;
    }
    const compared = window !== null && window.compared.has(engine);
    const steps = compared ? window.steps : Math.min(...ok.map((r) => r.timedSteps));
    const perStep = ok.map((r) => msOver(r, steps));
    const med = median(perStep);
    const planned = window?.planned ?? ok[0]!.plannedSteps;
    const cut = !compared
      ? `not compared: timed only ${steps}/${planned} steps in the ${budgetSeconds} s budget`
      : steps < planned
        ? `cut to the first ${steps}/${planned} steps, as every compared engine`
        : null;
    const quality = qualityOf(scene, engine, ok);
    rows.push({
      scene,
      engine,
      medianMsPerStep: med,
      minMsPerStep: Math.min(...perStep),
      steps,
      ratio: compared && physicalMedian ? med / physicalMedian : null,
      quality:
        (cut === null ? quality : quality === 'ok' ? cut : `${cut}; ${quality}`) +
        (ok.length < runs.length ? ` (${runs.length - ok.length} runs failed)` : ''),
    });
  }
}

const fmt = (x: number | null, digits = 3): string => (x === null ? '-' : x.toFixed(digits));
const header = [
  'scene',
  'engine',
  'median ms/step',
  'min ms/step',
  'steps',
  'ratio to Physical',
  'quality',
];
const body = rows.map((r) => [
  r.scene,
  r.engine,
  fmt(r.medianMsPerStep),
  fmt(r.minMsPerStep),
  r.steps === null ? '-' : String(r.steps),
  r.ratio === null ? '-' : `${r.ratio.toFixed(2)}x`,
  r.quality,
]);
const widths = header.map((h, i) =>
  Math.max(h.length, ...body.map((b) => (i === 6 ? 0 : b[i]!.length))),
);
const line = (cells: string[]): string =>
  cells.map((c, i) => (i === cells.length - 1 ? c : c.padEnd(widths[i]!))).join(' | ');
log(line(header));
log(widths.map((w, i) => (i === widths.length - 1 ? '---' : '-'.repeat(w))).join('-|-'));
for (const b of body) log(line(b));
log();
log(
  'ratio to Physical = peer median / Physical median over the same steps: above 1 means the peer is slower than Physical.',
);

// ---- Warm-up: the cold first step against the median step ----
const firstStep: { scene: string; firstStepMs: number; msPerStep: number; ratio: number }[] = [];
for (const scene of runnable) {
  const ok = (results.get(key(scene, 'physical')) ?? []).filter((r): r is Ok => r.ok);
  if (!ok.length) continue;
  const first = median(ok.map((r) => r.firstStepMs));
  const med = median(ok.map((r) => r.msPerStep));
  firstStep.push({ scene, firstStepMs: first, msPerStep: med, ratio: first / med });
}
if (firstStep.length) {
  log(
    `Physical's first step (step 0, cold JIT) / its mean timed step: ${firstStep.map((f) => `${f.scene} ${f.firstStepMs.toFixed(1)} ms = ${f.ratio.toFixed(1)}x`).join(', ')}`,
  );
}

// ---- Pyramid sinks ----
for (const scene of runnable.filter((s) => s.includes('pyramid'))) {
  const parts = engineIds
    .filter((e) => sinks.has(key(scene, e)))
    .map((e) => `${e} ${sinks.get(key(scene, e))!.toFixed(4)}`);
  log(`top-box sink (m, + = down, worst pyramid) ${scene}: ${parts.join(', ')}`);
}
if (runnable.some((s) => s.includes('pyramid'))) {
  log(
    `(sink check: <= the best standing peer's sink + ${SINK_TOLERANCE} m, among peers that timed as many steps; v2-family engines (${[...SKIN_ENGINES].join(', ')}) ` +
      'are left out of the baseline: their 0.01 m polygon skin lifts a stack, so their sink is negative by construction)',
  );
}
const angles = engineIds
  .map((e) => {
    const ok = (results.get(key('tumbler', e)) ?? []).filter((r): r is Ok => r.ok);
    return ok.length && ok[0]!.metrics.containerAngleDeg !== undefined
      ? `${e} ${(((ok[0]!.metrics.containerAngleDeg % 360) + 360) % 360).toFixed(1)} (${ok[0]!.timedSteps + 1} steps)`
      : null;
  })
  .filter((s) => s !== null);
if (angles.length) {
  const expected = (((quick ? QUICK_STEPS : 750) / 60) * 25) % 360;
  log(
    `tumbler container angle at the end (deg mod 360, y-up; 25 deg/s over the full run gives ${expected.toFixed(1)}): ${angles.join(', ')}`,
  );
}
log();

// ---- Settings and approximations ----
function settingsWithoutRun(all: WorkerResult[]): string {
  const failed = all.filter((r) => !r.ok);
  if (failed.length === 0) return 'not run';
  if (failed.every((r) => r.unsupported)) {
    return `no supported scene run (${failed.map((r) => r.scene).join(', ')})`;
  }
  const crash = failed.find((r) => !r.unsupported) ?? failed[0]!;
  return `did not load: ${crash.error}`;
}

log(
  'Engine settings (each at its documented/default settings; scene materials and sleep as Box2D):',
);
for (const engine of engineIds) {
  const all = runnable.flatMap((s) => results.get(key(s, engine)) ?? []);
  const ok = all.find((r): r is Ok => r.ok);
  log(`- ${engine}: ${ok ? ok.settings : settingsWithoutRun(all)}`);
  for (const scene of runnable) {
    const r = (results.get(key(scene, engine)) ?? []).find((x): x is Ok => x.ok);
    if (r && r.notes.length) log(`    ${scene}: ${r.notes.join('; ')}`);
  }
}
log(
  '- Scenes: tumbler uses a revolute motor (25 deg/s, max torque 1e8) where the engine has motors, ' +
    'else a kinematic body at 25 deg/s; joint_grid circles ignore one another where the engine has ' +
    'collision filters (every engine here); washer hit events only exist in box2d3-wasm; ' +
    "spinner's paddle likewise (5 rad/s, unlimited torque), and its capsules and rounded paddle are " +
    'approximated where an engine lacks them (see the notes above).',
);
log();

// ---- Allocation ----
const gcLine = (r: Ok): string =>
  `${r.gc.count} gc (${r.gc.minor} minor, ${r.gc.major} major, ${r.gc.other} other), ${r.gc.totalMs.toFixed(1)} ms in gc, ` +
  `heap +${(r.gc.rawDeltaBytes / 1048576).toFixed(2)} MB over the loop, ` +
  `retained after forced gc ${r.gc.retainedBytes === null ? '?' : `${(r.gc.retainedBytes / 1024).toFixed(0)} KB`}`;
log(
  'Allocation during the timed loop (PerformanceObserver "gc" entries; heapUsed, node --expose-gc), last round:',
);
for (const scene of runnable) {
  const r = (results.get(key(scene, 'physical')) ?? []).filter((x): x is Ok => x.ok).at(-1);
  if (r) log(`- physical ${scene} (${r.timedSteps} steps): ${gcLine(r)}`);
}
if (runnable.includes('large_pyramid')) {
  for (const engine of engineIds.filter((e) => e !== 'physical')) {
    const r = (results.get(key('large_pyramid', engine)) ?? []).filter((x): x is Ok => x.ok).at(-1);
    if (r) log(`- ${engine} large_pyramid: ${gcLine(r)}`);
  }
}
log();

// Target 3 is about the steady state: the first steps also tier up the JIT (code that runs in
// V8's interpreter boxes every fractional number, and a late first use of a branch deoptimizes a
// function back into it: in tumbler until ~300 steps) and fill the pools, so these runs let 300
// steps pass untimed and then count gc over the next 1,000. Tumbler is the issue's scene of
// contacts made and ended every step; large_pyramid the one of many resting contacts.
const WARMUP = 300;
const STEADY_STEPS = 1000;
const STEADY_SCENES = ['large_pyramid', 'tumbler'];
interface SteadyState {
  scene: string;
  warmupSteps: number;
  steps: number;
  gc: Ok['gc'];
  met: boolean;
}
const steadyStates: SteadyState[] = [];
for (const scene of STEADY_SCENES.filter((name) => runnable.includes(name))) {
  if (!engineIds.includes('physical')) break;
  const warmupSteps = quick ? 2 : WARMUP;
  // Its own budget: the count of steps is the point here, not the time they take.
  const r = await runWorker('physical', scene, [
    '--warmup',
    String(warmupSteps),
    '--steps',
    String(1 + warmupSteps + (quick ? 20 : STEADY_STEPS)),
    '--budget',
    '900',
  ]);
  if (r.ok) {
    const retained = r.gc.retainedBytes;
    const met = r.gc.count === 0 && retained !== null && retained < 256 * 1024;
    steadyStates.push({ scene, warmupSteps, steps: r.timedSteps, gc: r.gc, met });
    log(
      `Steady state (physical ${scene}, ${warmupSteps} steps of warm-up, then ${r.timedSteps} steps): ${gcLine(r)}; ` +
        `target (no gc, retained growth < 256 KB): ${met ? 'met' : 'NOT met'}`,
    );
  } else log(`Steady state run failed (${scene}): ${r.error}`);
}
if (steadyStates.length > 0) log();
/** The large_pyramid row under its old JSON name. */
const steadyState = steadyStates.find((row) => row.scene === 'large_pyramid') ?? null;

// ---- Scaling ----
interface ScalingRow {
  bodies: number;
  msPerStep: number;
  usPerBodyStep: number;
}
const scaling: ScalingRow[] = [];
if (!values['no-scaling'] && engineIds.includes('physical')) {
  const sizes = [1000, 4000, 16000];
  const samples = new Map<number, number[]>();
  for (let round = 1; round <= rounds; round++) {
    for (const n of sizes) {
      const r = await runWorker('physical', `sparse_${n}`, quick ? [] : ['--steps', '200']);
      progress(`scaling round ${round} ${n}: ${r.ok ? r.msPerStep.toFixed(3) : r.error}`);
      if (r.ok) samples.set(n, [...(samples.get(n) ?? []), r.msPerStep]);
    }
  }
  log(
    `Scaling (physical, sparse scene: boxes 3 m apart, zero gravity, small random velocities, sleep off; ${quick ? QUICK_STEPS : 200} steps, median of ${rounds}):`,
  );
  for (const n of sizes) {
    const s = samples.get(n);
    if (!s) continue;
    const ms = median(s);
    scaling.push({ bodies: n, msPerStep: ms, usPerBodyStep: (ms * 1000) / n });
    log(
      `- ${n} bodies: ${ms.toFixed(3)} ms/step, ${((ms * 1000) / n).toFixed(3)} us per body-step`,
    );
  }
  const a = scaling.find((s) => s.bodies === 1000);
  const b = scaling.find((s) => s.bodies === 16000);
  if (a && b) {
    const ratio = b.usPerBodyStep / a.usPerBodyStep;
    log(
      `- per-body cost 16k/1k: ${ratio.toFixed(2)} (target <= 1.3: ${ratio <= 1.3 ? 'met' : 'NOT met'})`,
    );
  }
  log();
}

// ---- Size ----
const { measureSize } = await import('./size.ts');
const size = await measureSize();
const kb = (bytes: number): string => `${(bytes / 1024).toFixed(1)} KB`;
const sizeLine = (r: SizeReport): string =>
  `${kb(r.minifiedBytes)} minified, ${kb(r.gzippedBytes)} gzipped; target <= 40 KB: ` +
  `gzipped ${r.gzippedBytes <= 40960 ? 'met' : 'NOT met'}, minified ${r.minifiedBytes <= 40960 ? 'met' : 'NOT met'}`;
log(
  'Size: bundled by esbuild from packages/engine/src (ESM, minified, tree-shaken; gzip is node:zlib level 9)',
);
log(`- whole library (index.ts, every export kept): ${sizeLine(size.library)}`);
log(
  `- an app without joints or snapshots (World, box, particle, wall, polygon, Force): ${sizeLine(size.appWithoutJointsOrSnapshots)}`,
);

// ---- Rollback: snapshot and restore ----
const { measureSnapshots } = await import('./snapshot.ts');
const snapshots = measureSnapshots(quick ? 10 : 120, quick ? 3 : 15);
log(
  `Rollback (physical, ${snapshots.bodies} moving bodies, ${snapshots.joints} revolute joints, ${snapshots.contacts} contacts, saved after ${snapshots.stepsBefore} steps; median of ${snapshots.rounds}):`,
);
log(
  `- takeSnapshot ${snapshots.takeMedianMs.toFixed(2)} ms, restoreSnapshot ${snapshots.restoreMedianMs.toFixed(2)} ms; ` +
    `as JSON: ${(snapshots.jsonBytes / 1024).toFixed(0)} KB, stringify ${snapshots.stringifyMedianMs.toFixed(2)} ms, parse ${snapshots.parseMedianMs.toFixed(2)} ms`,
);
const { frontEndLines, measureFrontEnd } = await import('./size.ts');
for (const line of frontEndLines(await measureFrontEnd())) log(line);
log();

// ---- Browser ----
let browser: unknown = null;
if (values.browser) {
  try {
    const { runBrowser } = await import('./browser.ts');
    const r = await runBrowser();
    browser = r;
    log(
      `Browser (Chromium, ${r.userAgent.match(/Chrome\/[\d.]+/)?.[0] ?? '?'}; Physical from packages/engine/dist bundled by esbuild; ` +
        `1,000-box pile, ${r.steps} timed steps): median ${r.medianMs.toFixed(3)} ms/step, mean ${r.meanMs.toFixed(3)}, ` +
        `min ${r.minMs.toFixed(3)}${r.nan ? `, NaN in ${r.nan} bodies` : ''} (timer resolution in the page is coarse, ~0.1 ms)`,
    );
  } catch (error) {
    browser = { error: String(error) };
    log(`Browser: failed: ${String(error)}`);
  }
}

if (values.json) {
  const settings: Record<string, string> = {};
  for (const engine of engineIds) {
    const ok = runnable
      .flatMap((s) => results.get(key(s, engine)) ?? [])
      .find((r): r is Ok => r.ok);
    if (ok) settings[engine] = ok.settings;
  }
  writeFileSync(
    values.json,
    `${JSON.stringify(
      {
        rows: rows.map(
          ({ scene, engine, medianMsPerStep, minMsPerStep, steps, ratio, quality }) => ({
            scene,
            engine,
            medianMsPerStep,
            minMsPerStep,
            steps,
            quality,
            // This engine's median over Physical's, over the same steps: below 1 the peer is faster.
            ratioToPhysical: ratio,
          }),
        ),
        firstStep,
        rounds,
        quick,
        settings,
        scaling,
        steadyState,
        steadyStates,
        size,
        snapshots,
        browser,
      },
      null,
      2,
    )}\n`,
  );
  log(`wrote ${values.json}`);
}
