import type { BodyDesc, SceneDesc } from '../types.ts';
import { BOX2D_MATERIAL, dynamicBox } from './common.ts';

/**
 * The scaling scene (ours, not Box2D's): `count` boxes of 0.5 m on a grid 3 m apart in zero gravity,
 * drifting with small random velocities (seeded), so almost nothing touches. Sleep off, so every body
 * is simulated every step and the cost per body should stay flat as the count grows.
 */
export function sparse(count: number, steps: number): SceneDesc {
  let seed = 12345;
  const random = (): number => {
    seed = (Math.imul(seed, 1664525) + 1013904223) >>> 0;
    return seed / 4294967296;
  };
  const side = Math.ceil(Math.sqrt(count));
  const bodies: BodyDesc[] = [];
  for (let i = 0; i < count; i++) {
    const x = (i % side) * 3;
    const y = Math.floor(i / side) * 3;
    bodies.push({
      ...dynamicBox(x, y, 0.25),
      vx: (random() - 0.5) * 0.5,
      vy: (random() - 0.5) * 0.5,
      w: (random() - 0.5) * 0.5,
    });
  }
  return {
    name: `sparse_${count}`,
    steps,
    gravity: { x: 0, y: 0 },
    sleep: false,
    material: BOX2D_MATERIAL,
    bodies,
    quality: { kind: 'none' },
  };
}
