import type { BodyDesc, SceneDesc, ShapeDesc } from '../types.ts';
import { type SceneOptions } from './common.ts';

const POINT_COUNT = 360;

/**
 * Box2D's CreateSpinner: a static loop of 360 points on a circle of radius 40 around (0, 32)
 * (friction 0.1), a paddle (rounded box 0.4 x 20 half-extents + 0.2 radius, friction 0) at
 * (0, 12) on a revolute motor of 5 rad/s with unlimited torque and sleep off, and 6,076 small
 * bodies (499 in debug) cycling capsule (centres 0.5 m apart, r 0.25) / circle (r 0.35) / square
 * (0.7 m), density 0.25, friction 0.1, restitution 0.1, on a 0.5 m grid from (-23, 2): they start
 * overlapping. Box2D's loop is a chain (one-sided smooth segments); here it is 360 plain segments.
 */
export function spinner({ small }: SceneOptions): SceneDesc {
  const loop: ShapeDesc[] = [];
  const step = (-2 * Math.PI) / POINT_COUNT;
  const points: [number, number][] = [];
  for (let i = 0; i < POINT_COUNT; i++) {
    points.push([40 * Math.cos(i * step), 40 * Math.sin(i * step) + 32]);
  }
  const loopMaterial = { friction: 0.1 };
  for (let i = 0; i < POINT_COUNT; i++) {
    const [x1, y1] = points[i]!;
    const [x2, y2] = points[(i + 1) % POINT_COUNT]!;
    loop.push({ kind: 'segment', x1, y1, x2, y2, material: loopMaterial });
  }
  const bodies: BodyDesc[] = [
    { type: 'static', x: 0, y: 0, shapes: loop },
    {
      type: 'dynamic',
      x: 0,
      y: 12,
      enableSleep: false,
      // FLT_MAX, Box2D's "unlimited" torque.
      motor: { speed: 5, maxTorque: 3.4e38 },
      shapes: [
        {
          kind: 'box',
          hw: 0.4,
          hh: 20,
          cx: 0,
          cy: 0,
          angle: 0,
          radius: 0.2,
          material: { friction: 0 },
        },
      ],
    },
  ];
  const material = { density: 0.25, friction: 0.1, restitution: 0.1 };
  const shapes: ShapeDesc[] = [
    { kind: 'capsule', x1: -0.25, y1: 0, x2: 0.25, y2: 0, radius: 0.25, material },
    { kind: 'circle', radius: 0.35, cx: 0, cy: 0, material },
    { kind: 'box', hw: 0.35, hh: 0.35, cx: 0, cy: 0, angle: 0, material },
  ];
  const count = small ? 499 : 2 * 3038;
  let x = -23;
  let y = 2;
  for (let i = 0; i < count; i++) {
    bodies.push({ type: 'dynamic', x, y, shapes: [shapes[i % 3]!] });
    x += 0.5;
    if (x >= 23) {
      x = -23;
      y += 0.5;
    }
  }
  return {
    name: 'spinner',
    steps: 500,
    gravity: { x: 0, y: -10 },
    sleep: true,
    material: { density: 1, friction: 0.6, restitution: 0 },
    bodies,
    quality: { kind: 'none' },
    notes: 'the loop chain is 360 two-sided segments (Box2D: a chain of one-sided smooth segments)',
  };
}
