import type { BodyDesc, SceneDesc } from '../types.ts';
import { BOX2D_MATERIAL, box, dynamicBox, type SceneOptions } from './common.ts';

/** Box2D's CreateLargePyramid: 5,050 unit boxes (base 100) on a 200 x 2 m ground. Sleep off. */
export function largePyramid({ small }: SceneOptions): SceneDesc {
  const baseCount = small ? 20 : 100;
  const bodies: BodyDesc[] = [{ type: 'static', x: 0, y: -1, shapes: [box(100, 1)] }];
  const boxes: number[] = [];
  const a = 0.5;
  for (let i = 0; i < baseCount; i++) {
    const y = (2 * i + 1) * a;
    for (let j = i; j < baseCount; j++) {
      const x = (i + 1) * a + 2 * (j - i) * a - a * baseCount;
      boxes.push(bodies.length);
      bodies.push(dynamicBox(x, y, a));
    }
  }
  return {
    name: 'large_pyramid',
    steps: 500,
    gravity: { x: 0, y: -10 },
    sleep: false,
    material: BOX2D_MATERIAL,
    bodies,
    quality: { kind: 'pyramid', boxes, boxWidth: 2 * a, tops: [bodies.length - 1] },
  };
}
