import type { BodyDesc, SceneDesc, ShapeDesc } from '../types.ts';
import { BOX2D_MATERIAL, dynamicBox, type SceneOptions } from './common.ts';

/** Box2D's CreateManyPyramids: 20 x 20 pyramids of base 10 (22,000 boxes) on 20 static segments. */
export function manyPyramids({ small }: SceneOptions): SceneDesc {
  const baseCount = 10;
  const extent = 0.5;
  const rowCount = small ? 5 : 20;
  const columnCount = small ? 5 : 20;
  const groundDeltaY = 2 * extent * (baseCount + 1);
  const groundWidth = 2 * extent * columnCount * (baseCount + 1);
  const segments: ShapeDesc[] = [];
  let groundY = 0;
  for (let i = 0; i < rowCount; i++) {
    segments.push({
      kind: 'segment',
      x1: -0.5 * groundWidth,
      y1: groundY,
      x2: 0.5 * groundWidth,
      y2: groundY,
    });
    groundY += groundDeltaY;
  }
  const bodies: BodyDesc[] = [{ type: 'static', x: 0, y: 0, shapes: segments }];
  const boxes: number[] = [];
  const tops: number[] = [];
  const baseWidth = 2 * extent * baseCount;
  let baseY = 0;
  for (let r = 0; r < rowCount; r++) {
    for (let c = 0; c < columnCount; c++) {
      const centerX = -0.5 * groundWidth + c * (baseWidth + 2 * extent) + 2 * extent;
      for (let i = 0; i < baseCount; i++) {
        const y = (2 * i + 1) * extent + baseY;
        for (let j = i; j < baseCount; j++) {
          const x = (i + 1) * extent + 2 * (j - i) * extent + centerX - 0.5;
          boxes.push(bodies.length);
          bodies.push(dynamicBox(x, y, extent));
        }
      }
      tops.push(bodies.length - 1);
    }
    baseY += groundDeltaY;
  }
  return {
    name: 'many_pyramids',
    steps: 200,
    gravity: { x: 0, y: -10 },
    sleep: false,
    material: BOX2D_MATERIAL,
    bodies,
    quality: { kind: 'pyramid', boxes, boxWidth: 2 * extent, tops },
  };
}
