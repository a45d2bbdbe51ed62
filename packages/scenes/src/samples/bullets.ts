import { World, box, particle } from '@physical/engine';
import { defineScene } from '../scene.ts';

const WALL_X = 8;
/** A second wall behind the guns: the rebounding balls stay in view, bouncing between the two. */
const BACK_WALL_X = -0.5;
const WALL_THICKNESS = 0.05;

/**
 * Small fast balls fired at a wall 5 cm thick. At 1/60 s per step a ball at 300 m/s moves 5 m
 * per step, a hundred times the wall's thickness: only continuous collision stops it. A second
 * thin wall behind the guns catches the rebounds, so they bounce to and fro, slower each time.
 */
export default defineScene({
  id: 'bullets',
  title: 'Bullets against a thin wall',
  description:
    'Balls of 10 cm radius fired at up to hundreds of m/s at a 5 cm wall, and bouncing back onto a second one. Continuous collision finds the moment of impact between steps: none passes through.',
  parameters: [
    { name: 'speed', label: 'Speed (m/s)', min: 10, max: 500, step: 10, default: 300 },
    { name: 'count', label: 'Bullets', min: 1, max: 10, step: 1, default: 6 },
  ],
  camera: { x: -1, y: -6, width: 11, height: 7 },
  pixelsPerMeter: 40,
  steps: 120,
  build({ speed, count }) {
    const world = new World({ gravity: { x: 0, y: 0 } });
    for (const x of [WALL_X, BACK_WALL_X]) {
      world.add(
        box({ type: 'static', position: { x, y: -2.5 }, width: WALL_THICKNESS, height: 6 }),
      );
    }
    for (let i = 0; i < count; i++) {
      world.add(
        particle({
          position: { x: 0, y: -0.3 - (i * 4.4) / Math.max(1, count - 1) },
          radius: 0.1,
          density: 20,
          restitution: 0.3,
          // Each a little faster than the last, so they reach the wall at different moments.
          linearVelocity: { x: speed * (1 - 0.05 * i), y: 0 },
        }),
      );
    }
    return world;
  },
  check(world) {
    for (let i = 2; i < world.bodies.length; i++) {
      const x = world.bodies[i]!.position.x;
      if (x > WALL_X) return `bullet ${i - 1} passed through the wall (x = ${x.toFixed(2)} m)`;
      if (x < BACK_WALL_X) {
        return `bullet ${i - 1} passed through the back wall (x = ${x.toFixed(2)} m)`;
      }
    }
    return null;
  },
});
