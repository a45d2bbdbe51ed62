import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { PhysicalError, restoreSnapshot, takeSnapshot, type World } from '@physical/engine';
import { buildWorld, worldSpec } from './snapshot-worlds.ts';

// Fuzz (issue #31): damaged snapshots. A valid snapshot of a random world (snapshot-worlds.ts)
// is damaged one to three times (a number replaced by a flipped-byte value, an extreme or a
// wrong type, a field deleted, two entries of a list swapped, a hole or undefined put in a list),
// then carried as JSON text or as a structured clone (which keeps holes and undefined). Restoring
// it either throws a PhysicalError (never a TypeError or a RangeError), or gives a world that
// steps 600 times and stays finite.

type Node = Record<string, unknown> | unknown[];

/** Every object and array inside `root`, with the keys they hold. */
function containers(root: unknown): Node[] {
  const out: Node[] = [];
  const visit = (v: unknown): void => {
    if (v === null || typeof v !== 'object') return;
    out.push(v as Node);
    for (const child of Object.values(v as object)) visit(child);
  };
  visit(root);
  return out;
}

/** A double with one of its 64 bits flipped: what a bad byte on disk or the wire makes. */
function flipBit(x: number, bit: number): number {
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  const byte = bit >> 3;
  view.setUint8(byte, view.getUint8(byte) ^ (1 << (bit & 7)));
  return view.getFloat64(0);
}

const REPLACEMENTS: readonly unknown[] = [
  NaN,
  Infinity,
  -1,
  0,
  1e300,
  -1e300,
  4.7e219,
  1e-300,
  'Infinity',
  '-0',
  'x',
  null,
  undefined,
  true,
  {},
  [],
  [1, 2],
];

const damage = fc.record({
  kind: fc.constantFrom('flip', 'replace', 'delete', 'swap', 'hole'),
  at: fc.nat(),
  key: fc.nat(),
  other: fc.nat(),
  bit: fc.integer({ min: 0, max: 63 }),
  value: fc.constantFrom(...REPLACEMENTS),
});

type Damage = typeof damage extends fc.Arbitrary<infer T> ? T : never;

/** Applies one damage to a container picked by `d.at` (in place). */
function apply(snapshot: unknown, d: Damage): void {
  const nodes = containers(snapshot);
  const node = nodes[d.at % nodes.length]!;
  const keys = Object.keys(node);
  if (keys.length === 0) return;
  const key = keys[d.key % keys.length]!;
  const record = node as Record<string, unknown>;
  switch (d.kind) {
    case 'flip': {
      const v = record[key];
      record[key] = typeof v === 'number' ? flipBit(v, d.bit) : d.value;
      return;
    }
    case 'replace':
      record[key] = d.value;
      return;
    case 'delete':
      Reflect.deleteProperty(record, key);
      return;
    case 'swap': {
      const other = keys[d.other % keys.length]!;
      [record[key], record[other]] = [record[other], record[key]];
      return;
    }
    case 'hole':
      if (Array.isArray(node)) Reflect.deleteProperty(node, key);
      else record[key] = undefined;
      return;
  }
}

function finite(world: World): boolean {
  return world.bodies.every(
    (b) =>
      Number.isFinite(b.position.x) &&
      Number.isFinite(b.position.y) &&
      Number.isFinite(b.angle) &&
      Number.isFinite(b.linearVelocity.x) &&
      Number.isFinite(b.linearVelocity.y) &&
      Number.isFinite(b.angularVelocity),
  );
}

describe('damaged snapshots', () => {
  it('restore throws a PhysicalError, or the world steps 600 times finite (JSON and structured clone)', () => {
    let restored = 0;
    let refused = 0;
    fc.assert(
      fc.property(
        worldSpec.map((s) => ({ ...s, pile: false, saveAt: s.saveAt % 90 })),
        fc.array(damage, { minLength: 1, maxLength: 3 }),
        fc.boolean(),
        (spec, damages, viaJson) => {
          const world = buildWorld(spec);
          for (let i = 0; i < spec.saveAt; i++) world.step(1 / 60);
          const snapshot: unknown = structuredClone(takeSnapshot(world));
          for (const d of damages) apply(snapshot, d);
          const carried: unknown = viaJson
            ? JSON.parse(JSON.stringify(snapshot) ?? 'null')
            : structuredClone(snapshot);
          let copy: World;
          try {
            copy = restoreSnapshot(carried as Parameters<typeof restoreSnapshot>[0]);
          } catch (error) {
            if (!(error instanceof PhysicalError)) throw error;
            expect(error.field).toMatch(/^snapshot|^format|^version/);
            refused++;
            return;
          }
          restored++;
          for (let i = 0; i < 600; i++) copy.step(1 / 60);
          if (!finite(copy)) throw new Error('the restored world went non-finite');
        },
      ),
      { numRuns: 150, seed: 31 },
    );
    // Both outcomes occur: damage that is refused, and damage a world could hold.
    expect(refused).toBeGreaterThan(0);
    expect(restored).toBeGreaterThan(0);
  }, 120_000);
});
