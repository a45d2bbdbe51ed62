import type { BodyDesc, SceneDesc, ShapeDesc } from '../types.ts';
import { BOX2D_MATERIAL, box, type SceneOptions } from './common.ts';
import { hull } from '../types.ts';

/**
 * Box2D's CreateCompounds: 20 x 150 bodies, each two overlapping triangles, falling into a bin of
 * static boxes (floor of 81, walls of 100) with a 1,600 m segment below. Friction 0.5. Sleep on.
 */
export function compounds({ small }: SceneOptions): SceneDesc {
  const ground: ShapeDesc[] = [];
  let x = -40;
  for (let i = 0; i < 81; i++, x += 1) ground.push(box(0.55, 0.5, x, 0));
  for (const wx of [-40, 40]) {
    let y = 1;
    for (let i = 0; i < 100; i++, y += 1) ground.push(box(0.5, 0.55, wx, y));
  }
  ground.push({ kind: 'segment', x1: -800, y1: -80, x2: 800, y2: -80 });
  const bodies: BodyDesc[] = [{ type: 'static', x: 0, y: 0, shapes: ground }];

  const left: ShapeDesc = {
    kind: 'polygon',
    vertices: hull([
      [-1, 0],
      [0.5, 1],
      [0, 2],
    ]),
  };
  const right: ShapeDesc = {
    kind: 'polygon',
    vertices: hull([
      [1, 0],
      [-0.5, 1],
      [0, 2],
    ]),
  };
  const columnCount = small ? 10 : 20;
  const rowCount = small ? 40 : 150;
  const shift = 2;
  const extray = 0.25;
  let side = 0.25;
  const centerx = (shift * columnCount) / 2 - 1;
  const centery = 1.15 / 2;
  const yStart = 5;
  for (let i = 0; i < columnCount; i++) {
    const bx = i * shift - centerx;
    for (let j = 0; j < rowCount; j++) {
      const by = j * (shift + extray) + centery + yStart;
      bodies.push({ type: 'dynamic', x: bx + side, y: by, shapes: [left, right] });
      side = -side;
    }
  }
  return {
    name: 'compounds',
    steps: 500,
    gravity: { x: 0, y: -10 },
    sleep: true,
    material: { ...BOX2D_MATERIAL, friction: 0.5 },
    bodies,
    quality: { kind: 'none' },
  };
}
