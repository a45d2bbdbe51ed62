import { Body, World, box } from '@physical/engine';
import { seededRandom } from '../random.ts';
import { defineScene } from '../scene.ts';

const HALF = 4;
const WALL = 0.25;

/**
 * A square drum turning at a constant rate (a kinematic body: it moves as told and pushes, but
 * nothing pushes it) with a load of small boxes tumbling inside. After Box2D's benchmark scene.
 */
export default defineScene({
  id: 'tumbler',
  title: 'Tumbler',
  description:
    'A kinematic drum turns at a set rate; the boxes inside are lifted and tumble, and none may escape.',
  parameters: [
    { name: 'count', label: 'Boxes', min: 10, max: 300, step: 10, default: 120 },
    { name: 'rate', label: 'Turn rate (deg/s)', min: -90, max: 90, step: 5, default: 30 },
  ],
  camera: { x: -6.5, y: -6.5, width: 13, height: 13 },
  pixelsPerMeter: 40,
  steps: 300,
  build({ count, rate }) {
    const world = new World();
    const inner = HALF - WALL;
    world.add(
      new Body({
        type: 'kinematic',
        angularVelocity: (rate * Math.PI) / 180,
        shapes: [
          { type: 'box', width: 2 * HALF, height: 2 * WALL, offset: { x: 0, y: -inner - WALL } },
          { type: 'box', width: 2 * HALF, height: 2 * WALL, offset: { x: 0, y: inner + WALL } },
          { type: 'box', width: 2 * WALL, height: 2 * HALF, offset: { x: -inner - WALL, y: 0 } },
          { type: 'box', width: 2 * WALL, height: 2 * HALF, offset: { x: inner + WALL, y: 0 } },
        ],
      }),
    );
    const random = seededRandom(7);
    const columns = Math.ceil(Math.sqrt(count));
    const pitch = (2 * inner - 0.6) / columns;
    for (let i = 0; i < count; i++) {
      const size = Math.min(0.35, 0.8 * pitch) * (0.6 + 0.4 * random());
      const column = i % columns;
      const row = Math.floor(i / columns);
      world.add(
        box({
          position: {
            x: -inner + 0.3 + pitch * (column + 0.5),
            y: -inner + 0.3 + pitch * (row + 0.5),
          },
          width: size,
          height: size,
        }),
      );
    }
    return world;
  },
  check(world) {
    const drum = world.bodies[0]!;
    const local = { x: 0, y: 0 };
    for (let i = 1; i < world.bodies.length; i++) {
      drum.getLocalPoint(world.bodies[i]!.position, local);
      if (Math.abs(local.x) > HALF - WALL || Math.abs(local.y) > HALF - WALL) {
        return `box ${i} escaped the drum (at ${local.x.toFixed(2)}, ${local.y.toFixed(2)} in the drum's frame)`;
      }
    }
    return null;
  },
});
