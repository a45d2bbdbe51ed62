// The program the cross-engine test bundles once and runs in V8 and in QuickJS: the engine and
// every sample, stepped from their default values, reporting state hashes along the way.
import { STEP, bodyStates, hashWorld, sceneValues, scenes } from '@physical/scenes';
import type { World } from '@physical/engine';
// QuickJS has no WebAssembly: its worlds run the contact passes' JavaScript build.
import '@physical/engine/javascript-kernel';
import { buildHeldOutScene } from './held-out-scene.ts';

/** The id the held-out scene runs under. */
export const HELD_OUT = 'held-out';

/** The sample ids and their regression step counts, as `id:steps` joined by commas. */
export function samples(): string {
  return scenes.map((scene) => `${scene.id}:${scene.steps}`).join(',');
}

function build(id: string): World {
  if (id === HELD_OUT) return buildHeldOutScene();
  const scene = scenes.find((candidate) => candidate.id === id);
  if (scene === undefined) throw new Error(`no sample ${id}`);
  return scene.build(sceneValues(scene));
}

/**
 * Builds the scene `id` and steps it `steps` times at 1/60 s. Returns the state hash after every
 * `every` steps and after the last, then every body's final state as the hex bits of its
 * float64s (so a difference can be counted per coordinate), as one line of text.
 */
export function run(id: string, steps: number, every: number): string {
  const world = build(id);
  const hashes: string[] = [];
  for (let i = 1; i <= steps; i++) {
    world.step(STEP);
    if (i % every === 0 || i === steps) hashes.push(`${i}:${hashWorld(world)}`);
  }
  const words = new Uint32Array(bodyStates(world).buffer);
  const bits: string[] = [];
  for (let i = 0; i < words.length; i += 2) {
    bits.push(
      words[i + 1]!.toString(16).padStart(8, '0') + words[i]!.toString(16).padStart(8, '0'),
    );
  }
  return `${hashes.join(' ')}|${bits.join(' ')}`;
}
