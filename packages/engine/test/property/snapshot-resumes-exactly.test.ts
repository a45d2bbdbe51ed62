import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { restoreSnapshot, takeSnapshot, type WorldSnapshot } from '@physical/engine';
import { buildWorld, stateHash, worldSpec } from './snapshot-worlds.ts';

// Property (issue #28): every snapshot resumes bit for bit. Random worlds using every feature
// (snapshot-worlds.ts) are saved at a random step and restored twice, through JSON text and
// through a structured clone (postMessage, IndexedDB); the original and both copies then step
// 600 times with equal state hashes after every step (a lost warm start can heal within a few
// steps, so a check every so often could miss it), and end with the same snapshot text. Saving
// leaves the original as it was: a twin world that is never saved agrees with it too.

const STEPS = 600;
const DT = 1 / 60;

describe('snapshots resume exactly', () => {
  it('a copy restored at a random step (JSON or structured clone) steps 600 times like the original and a twin never saved', () => {
    fc.assert(
      fc.property(worldSpec, (spec) => {
        const world = buildWorld(spec);
        const twin = buildWorld(spec);
        for (let i = 0; i < spec.saveAt; i++) {
          world.step(DT);
          twin.step(DT);
        }
        const snapshot = takeSnapshot(world);
        const viaJson = restoreSnapshot(JSON.parse(JSON.stringify(snapshot)) as WorldSnapshot);
        const viaClone = restoreSnapshot(structuredClone(snapshot));
        for (let i = 0; i < STEPS; i++) {
          world.step(DT);
          twin.step(DT);
          viaJson.step(DT);
          viaClone.step(DT);
          const hash = stateHash(world);
          if (
            stateHash(viaJson) !== hash ||
            stateHash(viaClone) !== hash ||
            stateHash(twin) !== hash
          ) {
            throw new Error(`saved at step ${spec.saveAt}, differs ${i + 1} steps later`);
          }
        }
        const text = JSON.stringify(takeSnapshot(world));
        expect(JSON.stringify(takeSnapshot(viaJson))).toBe(text);
        expect(JSON.stringify(takeSnapshot(viaClone))).toBe(text);
      }),
      { numRuns: 12, seed: 20261127 },
    );
  }, 120_000);
});
