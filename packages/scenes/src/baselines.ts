import { scenes } from './catalog.ts';
import { runScene } from './scene.ts';
import { hashWorld } from './state-hash.ts';

/** A sample's recorded outcome: its step count and the hash of every body's state after it. */
export interface Baseline {
  readonly steps: number;
  readonly bodies: number;
  readonly hash: string;
}

/** Runs every sample at its default values for its steps and hashes the result. */
export function measureBaselines(): Record<string, Baseline> {
  const result: Record<string, Baseline> = {};
  for (const scene of scenes) {
    const world = runScene(scene);
    result[scene.id] = { steps: scene.steps, bodies: world.bodies.length, hash: hashWorld(world) };
  }
  return result;
}

/** The command that rewrites the baselines, named in every failure message. */
export const UPDATE_COMMAND = 'npm run baselines:update';
