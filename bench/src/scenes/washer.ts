import type { BodyDesc, SceneDesc, ShapeDesc } from '../types.ts';
import { BOX2D_MATERIAL, dynamicBox, type SceneOptions } from './common.ts';
import { hull } from '../types.ts';

/**
 * Box2D's CreateWasher: a kinematic ring (36 quads between r 16 and 18, 4 paddles r 14..16) at (0, 10)
 * spinning 25 deg/s with drift (0.001, -0.002) m/s, around 90 x 90 boxes of 0.2 m (hit events on).
 */
export function washer({ small }: SceneOptions): SceneDesc {
  const r0 = 14;
  const r1 = 16;
  const r2 = 18;
  const angle = Math.PI / 18;
  const rot = (a: number, v: [number, number]): [number, number] => [
    Math.cos(a) * v[0] - Math.sin(a) * v[1],
    Math.sin(a) * v[0] + Math.cos(a) * v[1],
  ];
  const ring: ShapeDesc[] = [];
  let u1: [number, number] = [1, 0];
  for (let i = 0; i < 36; i++) {
    const u2: [number, number] = i === 35 ? [1, 0] : rot(angle, u1);
    const a1 = rot(-0.1 * angle, u1);
    const a2 = rot(0.1 * angle, u2);
    ring.push({
      kind: 'polygon',
      vertices: hull([
        [r1 * a1[0], r1 * a1[1]],
        [r2 * a1[0], r2 * a1[1]],
        [r1 * a2[0], r1 * a2[1]],
        [r2 * a2[0], r2 * a2[1]],
      ]),
    });
    if (i % 9 === 0) {
      ring.push({
        kind: 'polygon',
        vertices: hull([
          [r0 * u1[0], r0 * u1[1]],
          [r1 * u1[0], r1 * u1[1]],
          [r0 * u2[0], r0 * u2[1]],
          [r1 * u2[0], r1 * u2[1]],
        ]),
      });
    }
    u1 = u2;
  }
  const bodies: BodyDesc[] = [
    { type: 'static', x: 0, y: 0, shapes: [] },
    {
      type: 'kinematic',
      x: 0,
      y: 10,
      w: (Math.PI / 180) * 25,
      vx: 0.001,
      vy: -0.002,
      shapes: ring,
    },
  ];
  const gridCount = small ? 20 : 90;
  const a = 0.1;
  let y = -1.1 * a * gridCount + 10;
  for (let i = 0; i < gridCount; i++) {
    let x = -1.1 * a * gridCount;
    for (let j = 0; j < gridCount; j++) {
      bodies.push({ ...dynamicBox(x, y, a), hitEvents: true });
      x += 2.1 * a;
    }
    y += 2.1 * a;
  }
  return {
    name: 'washer',
    steps: 500,
    gravity: { x: 0, y: -10 },
    sleep: true,
    material: BOX2D_MATERIAL,
    bodies,
    quality: { kind: 'none' },
  };
}
