import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

// Removal releases everything: a removed body and its userData become garbage (nothing in the
// world still points at them: not the solver's per-step lists, the contact pool, the island
// search, the sensors' lists), and a world emptied of 100,000 bodies added in batches weighs
// about what an empty one does (the room sized for them is released).

const root = fileURLToPath(new URL('../../../..', import.meta.url));
const probe = fileURLToPath(new URL('./removal-memory-probe.ts', import.meta.url));

interface Measured {
  watched: number;
  collectedBodies: number;
  collectedData: number;
  empty: number;
  after: number;
  bodies: number;
}

/** Runs the probe in a child node with --expose-gc (tsx runs the TypeScript sources). */
function measure(total: number, batch: number): Measured {
  const out = execFileSync(
    process.execPath,
    ['--expose-gc', '--import', 'tsx', probe, String(total), String(batch)],
    { cwd: root, encoding: 'utf8', timeout: 240_000, env: { ...process.env, NODE_OPTIONS: '' } },
  );
  return JSON.parse(out.trim().split('\n').pop()!) as Measured;
}

describe('removing bodies releases them', () => {
  it(
    '100,000 bodies added and removed in batches: all collected, the heap within 20 % of the empty world',
    { timeout: 300_000 },
    () => {
      const m = measure(100_000, 10_000);
      expect(m.bodies).toBe(2); // the ground and the sensor
      expect(m.watched).toBe(20_000);
      expect(m.collectedBodies).toBe(m.watched);
      expect(m.collectedData).toBe(m.watched);
      expect(m.after / m.empty).toBeLessThan(1.2);
    },
  );
});
