import type { SceneDesc } from '../types.ts';
import type { SceneOptions } from './common.ts';
import { compounds } from './compounds.ts';
import { jointGrid } from './joint-grid.ts';
import { junkyard } from './junkyard.ts';
import { largePyramid } from './large-pyramid.ts';
import { manyPyramids } from './many-pyramids.ts';
import { rain } from './rain.ts';
import { smash } from './smash.ts';
import { sparse } from './sparse.ts';
import { spinner } from './spinner.ts';
import { tumbler } from './tumbler.ts';
import { washer } from './washer.ts';

/** Box2D v3's scenes, in Box2D's order. */
export const SCENES: Record<string, (options: SceneOptions) => SceneDesc> = {
  compounds,
  joint_grid: jointGrid,
  junkyard,
  large_pyramid: largePyramid,
  many_pyramids: manyPyramids,
  rain,
  smash,
  spinner,
  tumbler,
  washer,
};

/** Box2D v3's scenes that need features Physical does not have yet. */
export const UNSUPPORTED: Record<string, string> = {};

/** Builds a scene by name; `sparse_<n>` is the scaling scene with n bodies. */
export function buildScene(name: string, options: SceneOptions & { steps?: number }): SceneDesc {
  const match = /^sparse_(\d+)$/.exec(name);
  if (match) return sparse(Number(match[1]), options.steps ?? 200);
  const builder = SCENES[name];
  if (!builder) throw new Error(`unknown scene ${name}`);
  const scene = builder(options);
  return options.steps === undefined ? scene : { ...scene, steps: options.steps };
}
