import type { BodyDesc, JointDesc, SceneDesc } from '../types.ts';
import { BOX2D_MATERIAL, type SceneOptions } from './common.ts';

/**
 * Box2D's CreateJointGrid: a 100 x 100 lattice of circles (r 0.4 m, 1 m apart) joined to their
 * neighbours by revolute joints at the midpoints (19,800 joints), hanging from 7 static circles in
 * the middle of the top row. The circles ignore one another (a collision filter): a pure joint
 * solver test. Sleep off.
 */
export function jointGrid({ small }: SceneOptions): SceneDesc {
  const n = small ? 20 : 100;
  const circle = { kind: 'circle' as const, radius: 0.4, cx: 0, cy: 0 };
  const bodies: BodyDesc[] = [];
  const joints: JointDesc[] = [];
  for (let k = 0; k < n; k++) {
    for (let i = 0; i < n; i++) {
      const pinned = k >= n / 2 - 3 && k <= n / 2 + 3 && i === 0;
      const index = bodies.length;
      bodies.push({ type: pinned ? 'static' : 'dynamic', x: k, y: -i, shapes: [circle] });
      if (i > 0) joints.push({ a: index - 1, b: index, x: k, y: -i + 0.5 });
      if (k > 0) joints.push({ a: index - n, b: index, x: k - 0.5, y: -i });
    }
  }
  return {
    name: 'joint_grid',
    steps: 500,
    gravity: { x: 0, y: -10 },
    sleep: false,
    material: BOX2D_MATERIAL,
    bodies,
    joints,
    shapesCollide: false,
    quality: { kind: 'none' },
  };
}
