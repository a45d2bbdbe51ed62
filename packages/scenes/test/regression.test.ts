import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { hashWorld, runScene, sceneValues, scenes } from '@physical/scenes';
import { type Baseline, UPDATE_COMMAND } from '../src/baselines.ts';

const baselines = JSON.parse(
  readFileSync(new URL('../baselines.json', import.meta.url), 'utf8'),
) as Record<string, Baseline>;

describe('regression: every sample reproduces its committed state hash', () => {
  it('has a baseline for exactly the samples there are', () => {
    expect(
      Object.keys(baselines).sort(),
      `samples and baselines differ: run ${UPDATE_COMMAND}`,
    ).toEqual(scenes.map((scene) => scene.id).sort());
  });

  for (const scene of scenes) {
    it(
      `${scene.id}: same hash twice in a row, equal to the baseline, and its physical check holds`,
      { timeout: 60_000 },
      () => {
        const values = sceneValues(scene);
        const world = runScene(scene, values);
        const hash = hashWorld(world);
        expect(hashWorld(runScene(scene, values)), 'a second run must hash the same').toBe(hash);
        const baseline = baselines[scene.id];
        // Received: this run; expected: the committed baseline.
        expect(
          `${scene.steps} steps, ${hash}`,
          `sample "${scene.id}" changed its outcome after ${scene.steps} steps. If the change is ` +
            `intended (an engine change you can explain), run ${UPDATE_COMMAND} and commit ` +
            `packages/scenes/baselines.json with the explanation.`,
        ).toBe(
          baseline === undefined ? 'no baseline' : `${baseline.steps} steps, ${baseline.hash}`,
        );
        expect(scene.check(world, values), `the physical check of "${scene.id}"`).toBeNull();
      },
    );
  }
});
