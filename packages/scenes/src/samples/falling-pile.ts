import { World, box, particle, regularPolygon, wall } from '@physical/engine';
import { seededRandom } from '../random.ts';
import { defineScene } from '../scene.ts';

/** The getting-started scene: a pile of boxes, balls and polygons falling into a bin. */
export default defineScene({
  id: 'falling-pile',
  title: 'Falling pile',
  description:
    'Boxes, balls and polygons fall into a bin, pile up and fall asleep (dimmed with the sleep overlay). Tap one to kick it.',
  parameters: [
    { name: 'count', label: 'Bodies', min: 10, max: 400, step: 10, default: 80 },
    { name: 'bounce', label: 'Restitution', min: 0, max: 0.9, step: 0.1, default: 0.2 },
  ],
  camera: { x: -6.5, y: -15, width: 13, height: 15.5 },
  pixelsPerMeter: 40,
  steps: 360,
  build({ count, bounce }) {
    const world = new World();
    world.add(wall({ from: { x: -6, y: -15 }, to: { x: -6, y: 0 } }));
    world.add(wall({ from: { x: -6, y: 0 }, to: { x: 6, y: 0 } }));
    world.add(wall({ from: { x: 6, y: 0 }, to: { x: 6, y: -15 } }));
    const random = seededRandom(1);
    for (let i = 0; i < count; i++) {
      const position = {
        x: -5 + (i % 10) * 1.1 + 0.2 * random(),
        y: -2 - 1.1 * Math.floor(i / 10),
      };
      const size = 0.25 + 0.2 * random();
      const kind = i % 3;
      world.add(
        kind === 0
          ? box({ position, width: 2 * size, height: 2 * size, restitution: bounce })
          : kind === 1
            ? particle({ position, radius: size, restitution: bounce })
            : regularPolygon({ position, sides: 5 + (i % 4), radius: size, restitution: bounce }),
      );
    }
    return world;
  },
  check(world) {
    for (const body of world.bodies) {
      if (body.type !== 'dynamic') continue;
      const { x, y } = body.position;
      if (y > 0 || Math.abs(x) > 6) return `a body fell out (at ${x.toFixed(2)}, ${y.toFixed(2)})`;
    }
    return null;
  },
});
