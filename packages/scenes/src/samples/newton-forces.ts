import { World, box, wall } from '@physical/engine';
import { STEP, defineScene } from '../scene.ts';

/** The box the squares move in (m): walls just inside the camera, so a thrown square stays. */
const BOX = { left: -0.75, top: -1.25, right: 12.75, bottom: 3.25 };

/**
 * The thesis's second law: the same constant force on two squares of different mass on
 * frictionless tracks. a = F / m: the lighter one covers more ground, in proportion to 1 / m.
 * Walls close the track, so a square that arrives (or is thrown) stays on screen.
 */
export default defineScene({
  id: 'newton-forces',
  title: 'Newton: forces',
  description:
    'Second law. One force, two masses: each square accelerates at F/m and covers \u00bd (F/m) t\u00b2. Walls keep them, and any square you throw, on screen.',
  parameters: [
    { name: 'force', label: 'Force (N)', min: 0.5, max: 10, step: 0.5, default: 4 },
    {
      name: 'massA',
      label: 'Mass of the top square (kg)',
      min: 0.5,
      max: 5,
      step: 0.5,
      default: 1,
    },
    {
      name: 'massB',
      label: 'Mass of the bottom square (kg)',
      min: 0.5,
      max: 5,
      step: 0.5,
      default: 3,
    },
  ],
  camera: { x: -1, y: -1.5, width: 14, height: 5 },
  pixelsPerMeter: 40,
  steps: 120,
  build({ force, massA, massB }) {
    const world = new World({ gravity: { x: 0, y: 0 }, enableSleep: false });
    for (const [y, mass] of [
      [0, massA],
      [2, massB],
    ] as const) {
      const square = world.add(
        box({ position: { x: 0, y }, width: 1, height: 1, density: mass, fixedRotation: true }),
      );
      square.applyForce({ x: force, y: 0 }, { duration: 'constant' });
    }
    // Added after the squares, so they stay bodies 0 and 1.
    const { left, top, right, bottom } = BOX;
    for (const [from, to] of [
      [
        { x: left, y: top },
        { x: right, y: top },
      ],
      [
        { x: right, y: top },
        { x: right, y: bottom },
      ],
      [
        { x: right, y: bottom },
        { x: left, y: bottom },
      ],
      [
        { x: left, y: bottom },
        { x: left, y: top },
      ],
    ] as const) {
      world.add(wall({ from, to }));
    }
    return world;
  },
  check(world, { force, massA, massB }) {
    const t = world.steps * STEP;
    const masses = [massA, massB];
    for (let i = 0; i < 2; i++) {
      const expected = 0.5 * (force / masses[i]!) * t * t;
      const moved = world.bodies[i]!.position.x;
      // Semi-implicit Euler runs ahead of the closed form by (n + 1) / n: 0.8% at 120 steps.
      if (Math.abs(moved - expected) > 0.01 * expected) {
        return `square ${i} moved ${moved.toFixed(4)} m, \u00bd a t\u00b2 = ${expected.toFixed(4)} m`;
      }
    }
    return null;
  },
});
