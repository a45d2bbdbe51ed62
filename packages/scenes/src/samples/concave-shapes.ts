import { World, polygon, wall } from '@physical/engine';
import { defineScene } from '../scene.ts';

/** A star with `points` tips: outer radius `outer`, inner `inner` (m). */
function star(points: number, outer: number, inner: number) {
  const vertices = [];
  for (let i = 0; i < 2 * points; i++) {
    const r = i % 2 === 0 ? outer : inner;
    const a = (Math.PI * i) / points - Math.PI / 2;
    vertices.push({ x: r * Math.cos(a), y: r * Math.sin(a) });
  }
  return vertices;
}

const OUTLINES = [
  star(5, 0.7, 0.3),
  // An L.
  [
    { x: -0.5, y: -0.7 },
    { x: -0.1, y: -0.7 },
    { x: -0.1, y: 0.3 },
    { x: 0.6, y: 0.3 },
    { x: 0.6, y: 0.7 },
    { x: -0.5, y: 0.7 },
  ],
  // A boomerang.
  [
    { x: -0.8, y: -0.5 },
    { x: 0, y: 0.1 },
    { x: 0.8, y: -0.5 },
    { x: 0.8, y: 0 },
    { x: 0, y: 0.6 },
    { x: -0.8, y: 0 },
  ],
];

/**
 * Concave polygons: `polygon({ vertices })` takes any simple outline and splits it into convex
 * parts (one body, several shapes), so stars hook and L-shapes interlock.
 */
export default defineScene({
  id: 'concave-shapes',
  title: 'Concave shapes',
  description:
    'Stars, L-shapes and boomerangs given as outlines: the engine splits each into convex parts of one body. They hook into each other as they pile up.',
  parameters: [
    { name: 'count', label: 'Pieces', min: 3, max: 40, step: 1, default: 15 },
    { name: 'friction', label: 'Friction', min: 0, max: 1, step: 0.1, default: 0.6 },
  ],
  camera: { x: -4.5, y: -14, width: 9, height: 14.5 },
  pixelsPerMeter: 40,
  steps: 360,
  build({ count, friction }) {
    const world = new World();
    world.add(wall({ from: { x: -4, y: -14 }, to: { x: -4, y: 0 } }));
    world.add(wall({ from: { x: -4, y: 0 }, to: { x: 4, y: 0 } }));
    world.add(wall({ from: { x: 4, y: 0 }, to: { x: 4, y: -14 } }));
    for (let i = 0; i < count; i++) {
      world.add(
        polygon({
          position: { x: -2.4 + 2.4 * (i % 3), y: -2 - 1.8 * Math.floor(i / 3) },
          angle: 0.4 * i,
          vertices: OUTLINES[i % OUTLINES.length]!,
          friction,
        }),
      );
    }
    return world;
  },
  check(world) {
    for (const body of world.bodies) {
      if (body.type !== 'dynamic') continue;
      const { x, y } = body.position;
      if (y > 0 || Math.abs(x) > 4)
        return `a piece left the bin (at ${x.toFixed(2)}, ${y.toFixed(2)})`;
    }
    const star = world.bodies[3]!;
    if (star.shapes.length < 2) return 'the star was not split into convex parts';
    return null;
  },
});
