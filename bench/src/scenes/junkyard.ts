import type { BodyDesc, SceneDesc, ShapeDesc } from '../types.ts';
import { BOX2D_MATERIAL, box, type SceneOptions } from './common.ts';
import { DT, hull } from '../types.ts';

/**
 * Box2D's CreateJunkyard: 200 x 40 irregular pentagons in a bin of static boxes (floor of 161, walls
 * of 50), pushed by a kinematic 4 x 8 m box moved to x = 60 sin(0.2 t) every step. Sleep on.
 */
export function junkyard({ small }: SceneOptions): SceneDesc {
  const ground: ShapeDesc[] = [];
  let x = -80;
  for (let i = 0; i < 161; i++, x += 1) ground.push(box(0.55, 0.5, x, 0));
  for (const wx of [-80, 80]) {
    let y = 1;
    for (let i = 0; i < 50; i++, y += 1) ground.push(box(0.5, 0.55, wx, y));
  }
  const bodies: BodyDesc[] = [{ type: 'static', x: 0, y: 0, shapes: ground }];

  const radius = 0.25;
  const phi = Math.PI * (Math.sqrt(5) - 1);
  const points: [number, number][] = [];
  for (let i = 0; i < 5; i++) {
    points.push([radius * Math.cos(phi * i), radius * Math.sin(phi * i)]);
  }
  const pentagon: ShapeDesc = { kind: 'polygon', vertices: hull(points) };
  const columnCount = 200;
  const rowCount = small ? 2 : 40;
  let side = -0.1;
  for (let i = 0; i < columnCount; i++) {
    const px = 1.5 * (2 * i - columnCount) * radius;
    for (let j = 0; j < rowCount; j++) {
      bodies.push({ type: 'dynamic', x: px + side, y: 4 * j * radius + 15, shapes: [pentagon] });
      side = -side;
    }
  }
  const pusher = bodies.length;
  bodies.push({ type: 'kinematic', x: 0, y: 0, shapes: [box(2, 4, 0, 4)] });
  return {
    name: 'junkyard',
    steps: 800,
    gravity: { x: 0, y: -10 },
    sleep: true,
    material: BOX2D_MATERIAL,
    bodies,
    onStep: (step, api) => {
      api.moveKinematicTo(pusher, 60 * Math.sin(0.2 * DT * step), 0, 0);
    },
    quality: { kind: 'none' },
  };
}
