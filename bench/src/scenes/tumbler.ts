import type { BodyDesc, SceneDesc } from '../types.ts';
import { BOX2D_MATERIAL, box, dynamicBox, type SceneOptions } from './common.ts';

/**
 * Box2D's CreateTumbler: a 20 m square container (4 boxes, density 50) turned by a revolute motor at
 * 25 deg/s (max torque 1e8) around (0, 10), holding 45 x 45 boxes of 0.25 m. Sleep on.
 */
export function tumbler({ small }: SceneOptions): SceneDesc {
  const wall = { density: 50 };
  const container: BodyDesc = {
    type: 'dynamic',
    x: 0,
    y: 10,
    shapes: [
      { ...box(0.5, 10, 10, 0), material: wall },
      { ...box(0.5, 10, -10, 0), material: wall },
      { ...box(10, 0.5, 0, 10), material: wall },
      { ...box(10, 0.5, 0, -10), material: wall },
    ],
    motor: { speed: (Math.PI / 180) * 25, maxTorque: 1e8 },
  };
  const bodies: BodyDesc[] = [{ type: 'static', x: 0, y: 0, shapes: [] }, container];
  const boxes: number[] = [];
  const gridCount = small ? 20 : 45;
  let y = -0.2 * gridCount + 10;
  for (let i = 0; i < gridCount; i++) {
    let x = -0.2 * gridCount;
    for (let j = 0; j < gridCount; j++) {
      boxes.push(bodies.length);
      bodies.push(dynamicBox(x, y, 0.125));
      x += 0.4;
    }
    y += 0.4;
  }
  return {
    name: 'tumbler',
    steps: 750,
    gravity: { x: 0, y: -10 },
    sleep: true,
    material: BOX2D_MATERIAL,
    bodies,
    quality: { kind: 'tumbler', container: 1, boxes, innerHalf: 9.5 },
  };
}
