import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

// The engine's rule: a step allocates nothing in steady state (World.step and all it calls). Each
// scene runs in a child node (steady-allocation-probe.ts) with a 64 MB new space, so no collection
// falls inside the measured steps and the young generation's growth is what they allocated, and
// with V8's optimising compiler on the main thread, so which code is optimised after the warm-up
// depends on the steps run, not on the machine's load.
//
// The bound: 256 bytes a step, on average over 500 steps. What is left under it is a few heap
// numbers a step from code that runs once a step and is still in V8's baseline tiers (it is
// optimised after some thousands of steps; see dynamics/README.md, allocation). What the bound
// catches is garbage per body, per contact or per joint: a double passed to the kernel per swept
// body made ~2,800 bytes a step in the drum, a contact's materials read through getters ~1,000,
// and the hanging chain's 30 hinges, their inverse masses read through getters and the bias rate
// passed to each pin's error, ~1,970.

const root = fileURLToPath(new URL('../../../..', import.meta.url));
const probe = fileURLToPath(new URL('./steady-allocation-probe.ts', import.meta.url));

interface Measured {
  scene: string;
  steps: number;
  bytes: number;
  collections: number;
  bodies: number;
  awake: number;
}

const STEPS = 500;
const BYTES_PER_STEP = 256;

function measure(scene: string, warmup: number): Measured {
  const out = execFileSync(
    process.execPath,
    [
      '--expose-gc',
      '--max-semi-space-size=64',
      '--min-semi-space-size=64',
      '--no-concurrent-recompilation',
      '--import',
      'tsx',
      probe,
      scene,
      String(warmup),
      String(STEPS),
    ],
    { cwd: root, encoding: 'utf8', timeout: 240_000, env: { ...process.env, NODE_OPTIONS: '' } },
  );
  return JSON.parse(out.trim().split('\n').pop()!) as Measured;
}

describe('steady steps allocate (almost) nothing', () => {
  it(
    'a drum of 400 boxes turned by a motor, bodies tumbling, swept and making contacts',
    { timeout: 300_000 },
    () => {
      const m = measure('drum', 4000);
      expect(m.collections).toBe(0);
      // Still tumbling: the container and nearly every box awake.
      expect(m.awake).toBeGreaterThan(300);
      expect(m.bytes).toBeLessThan(STEPS * BYTES_PER_STEP);
    },
  );

  it('a resting 20-row pyramid (210 boxes)', { timeout: 300_000 }, () => {
    const m = measure('pyramid', 4000);
    expect(m.collections).toBe(0);
    expect(m.awake).toBe(210);
    expect(m.bytes).toBeLessThan(STEPS * BYTES_PER_STEP);
  });

  it(
    'a pile of 200 bodies that falls asleep and is woken by a push every 120 steps',
    { timeout: 300_000 },
    () => {
      const m = measure('waking', 4000);
      expect(m.collections).toBe(0);
      // Asleep again at the end: the measured steps woke it and let it sleep.
      expect(m.awake).toBe(0);
      expect(m.bytes).toBeLessThan(STEPS * BYTES_PER_STEP);
    },
  );

  it(
    'a hanging chain of 30 hinges with a heavy last link (the pin chains), its first links swept past their static anchor',
    { timeout: 300_000 },
    () => {
      const m = measure('chain', 4000);
      expect(m.collections).toBe(0);
      expect(m.awake).toBe(30);
      expect(m.bytes).toBeLessThan(STEPS * BYTES_PER_STEP);
    },
  );
});
