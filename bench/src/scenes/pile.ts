import type { BodyDesc, SceneDesc } from '../types.ts';
import { BOX2D_MATERIAL, box, dynamicBox } from './common.ts';

/**
 * The browser scene (ours): 1,000 boxes of 0.5 m (25 columns x 40 rows, 0.6 m apart) falling into a
 * 20 m wide container (floor and two walls). Sleep on, as an app would have it.
 */
export function pile(count = 1000, steps = 600): SceneDesc {
  const bodies: BodyDesc[] = [
    {
      type: 'static',
      x: 0,
      y: 0,
      shapes: [box(10.5, 0.5, 0, -0.5), box(0.5, 15, -10, 15), box(0.5, 15, 10, 15)],
    },
  ];
  const columns = 25;
  for (let i = 0; i < count; i++) {
    const x = -7.2 + (i % columns) * 0.6;
    const y = 1 + Math.floor(i / columns) * 0.6;
    bodies.push(dynamicBox(x, y, 0.25));
  }
  return {
    name: `pile_${count}`,
    steps,
    gravity: { x: 0, y: -10 },
    sleep: true,
    material: BOX2D_MATERIAL,
    bodies,
    quality: { kind: 'none' },
  };
}
