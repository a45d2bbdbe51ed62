import type { SceneDesc } from '../types.ts';
import type { SceneOptions } from './common.ts';
import { compounds } from './compounds.ts';
import { junkyard } from './junkyard.ts';
import { largePyramid } from './large-pyramid.ts';
import { manyPyramids } from './many-pyramids.ts';
import { smash } from './smash.ts';
import { sparse } from './sparse.ts';
import { spinner } from './spinner.ts';
import { tumbler } from './tumbler.ts';
import { washer } from './washer.ts';

/** Box2D v3's scenes that Physical can build today, in Box2D's order. */
export const SCENES: Record<string, (options: SceneOptions) => SceneDesc> = {
  compounds,
  junkyard,
  large_pyramid: largePyramid,
  many_pyramids: manyPyramids,
  smash,
  spinner,
  tumbler,
  washer,
};

/** Box2D v3's scenes that need features Physical does not have yet. */
export const UNSUPPORTED: Record<string, string> = {
  joint_grid: 'needs joints/capsules (not yet in Physical): 19,800 revolute joints',
  rain: 'needs joints and filtering (not yet in Physical): capsule ragdolls with revolute joints',
};

/** Builds a scene by name; `sparse_<n>` is the scaling scene with n bodies. */
export function buildScene(name: string, options: SceneOptions & { steps?: number }): SceneDesc {
  const match = /^sparse_(\d+)$/.exec(name);
  if (match) return sparse(Number(match[1]), options.steps ?? 200);
  const builder = SCENES[name];
  if (!builder) throw new Error(`unknown scene ${name}`);
  const scene = builder(options);
  return options.steps === undefined ? scene : { ...scene, steps: options.steps };
}
