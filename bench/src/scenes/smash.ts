import type { BodyDesc, SceneDesc } from '../types.ts';
import { BOX2D_MATERIAL, box, dynamicBox, type SceneOptions } from './common.ts';

/**
 * Box2D's CreateSmash: zero gravity; an 8 x 8 m box of density 8 at (-20, 0) launched at 40 m/s into a
 * 120 x 80 block of 0.4 m boxes created asleep. Sleep on, continuous on.
 */
export function smash({ small }: SceneOptions): SceneDesc {
  const bodies: BodyDesc[] = [
    {
      type: 'dynamic',
      x: -20,
      y: 0,
      vx: 40,
      shapes: [{ ...box(4, 4), material: { density: 8 } }],
    },
  ];
  const d = 0.4;
  const columns = small ? 20 : 120;
  const rows = small ? 10 : 80;
  for (let i = 0; i < columns; i++) {
    for (let j = 0; j < rows; j++) {
      bodies.push({ ...dynamicBox(i * d + 30, (j - rows / 2) * d, 0.5 * d), asleep: true });
    }
  }
  return {
    name: 'smash',
    steps: 300,
    gravity: { x: 0, y: 0 },
    sleep: true,
    material: BOX2D_MATERIAL,
    bodies,
    quality: { kind: 'none' },
  };
}
