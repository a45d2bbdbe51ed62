import { World, box, wall } from '@physical/engine';
import { defineScene } from '../scene.ts';

const HEIGHT = 2;
const THICKNESS = 0.2;

/** A row of dominoes; the first is tipped over and the fall runs down the line. */
export default defineScene({
  id: 'dominoes',
  title: 'Dominoes',
  description:
    'Thin boxes stand in a row. The first is tipped; each one knocks over the next, down to the last.',
  parameters: [
    { name: 'count', label: 'Dominoes', min: 3, max: 25, step: 1, default: 12 },
    { name: 'spacing', label: 'Spacing (m)', min: 0.6, max: 1.8, step: 0.1, default: 1.2 },
  ],
  camera: { x: -2, y: -6, width: 20, height: 7 },
  pixelsPerMeter: 40,
  steps: 420,
  build({ count, spacing }) {
    const world = new World();
    world.add(wall({ from: { x: -5, y: 0 }, to: { x: 60, y: 0 } }));
    for (let i = 0; i < count; i++) {
      world.add(
        box({
          position: { x: i * spacing, y: -HEIGHT / 2 },
          width: THICKNESS,
          height: HEIGHT,
          friction: 0.5,
        }),
      );
    }
    // Tip the first one: a push near its top, toward the row.
    const first = world.bodies[1]!;
    first.applyImpulse({ x: 0.15, y: 0 }, { x: 0, y: -HEIGHT * 0.9 });
    return world;
  },
  check(world) {
    const last = world.bodies[world.bodies.length - 1]!;
    if (Math.abs(last.angle) < 0.5) {
      return `the last domino still stands (angle ${last.angle.toFixed(3)} rad)`;
    }
    return null;
  },
});
