import { Body, World, capsule, wall } from '@physical/engine';
import { seededRandom } from '../random.ts';
import { defineScene } from '../scene.ts';

/**
 * Capsules (pills: every point within a radius of a segment) beside rounded boxes and triangles:
 * any convex polygon can take a rounding radius, which makes it roll over edges and stack
 * softly. Mass and inertia include the rounded rim.
 */
export default defineScene({
  id: 'capsules-and-rounded-boxes',
  title: 'Capsules and rounded boxes',
  description:
    'Capsules, and boxes and triangles with rounded corners, pile up on a slope. Turn the rounding up and the polygons roll like pebbles.',
  parameters: [
    { name: 'rounding', label: 'Rounding (m)', min: 0, max: 0.3, step: 0.02, default: 0.1 },
    { name: 'count', label: 'Pieces', min: 5, max: 80, step: 5, default: 30 },
  ],
  camera: { x: -6, y: -11, width: 12, height: 11.5 },
  pixelsPerMeter: 40,
  steps: 360,
  build({ rounding, count }) {
    const world = new World();
    world.add(wall({ from: { x: -6, y: -11 }, to: { x: -6, y: -3 } }));
    world.add(wall({ from: { x: -6, y: -3 }, to: { x: 0, y: 0 } }));
    world.add(wall({ from: { x: 0, y: 0 }, to: { x: 6, y: 0 } }));
    world.add(wall({ from: { x: 6, y: 0 }, to: { x: 6, y: -11 } }));
    const random = seededRandom(11);
    for (let i = 0; i < count; i++) {
      const size = 0.3 + 0.3 * random();
      const position = { x: -4 + 1.6 * (i % 6), y: -4 - 1.2 * Math.floor(i / 6) };
      const angle = random() * Math.PI;
      if (i % 4 === 3) {
        world.add(capsule({ position, angle, length: 2 * size, radius: 0.2 }));
        continue;
      }
      const shape =
        i % 4 === 2
          ? {
              type: 'polygon' as const,
              vertices: [
                { x: 0, y: -size },
                { x: size, y: size * 0.7 },
                { x: -size, y: size * 0.7 },
              ],
              radius: rounding,
            }
          : { type: 'box' as const, width: 2 * size, height: 1.4 * size, radius: rounding };
      world.add(new Body({ position, angle, shapes: [shape] }));
    }
    return world;
  },
  check(world) {
    for (const body of world.bodies) {
      if (body.type !== 'dynamic') continue;
      const { x, y } = body.position;
      if (y > 0 || x > 6 || x < -6) return `a piece fell out (at ${x.toFixed(2)}, ${y.toFixed(2)})`;
    }
    return null;
  },
});
