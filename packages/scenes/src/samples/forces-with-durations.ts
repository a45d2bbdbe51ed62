import { World, box } from '@physical/engine';
import { STEP, defineScene } from '../scene.ts';

const MASS = 1;

/**
 * The thesis's three kinds of force side by side, on three equal blocks in empty space: an
 * instant force (one step), a force for N seconds, and a constant force. The same F gives
 * impulses F dt, F N and F t, so speeds F dt / m, F N / m and F t / m.
 */
export default defineScene({
  id: 'forces-with-durations',
  title: 'Forces with durations',
  description:
    'Top: an instant force (one step). Middle: the same force for N seconds. Bottom: the same force, constant. Each block keeps the momentum it was given.',
  parameters: [
    { name: 'force', label: 'Force (N)', min: 0.5, max: 5, step: 0.5, default: 2 },
    { name: 'duration', label: 'Middle force lasts (s)', min: 0.1, max: 3, step: 0.1, default: 1 },
  ],
  camera: { x: -1, y: -1, width: 16, height: 7 },
  pixelsPerMeter: 40,
  steps: 180,
  build({ force, duration }) {
    // No sleep: the instant block drifts at 3 cm/s, under the sleep threshold of 5 cm/s, and a
    // sleeping body stops.
    const world = new World({ gravity: { x: 0, y: 0 }, enableSleep: false });
    const block = (y: number) =>
      world.add(box({ position: { x: 0, y }, width: 1, height: 1, density: MASS }));
    block(0).applyForce({ x: force, y: 0 }); // instant: the default duration is one step
    block(2.5).applyForce({ x: force, y: 0 }, { duration }); // N seconds, then it ends itself
    block(5).applyForce({ x: force, y: 0 }, { duration: 'constant' }); // until removed
    return world;
  },
  check(world, { force, duration }) {
    const elapsed = world.steps * STEP;
    const expected = [
      (force * STEP) / MASS,
      (force * Math.min(duration, elapsed)) / MASS,
      (force * elapsed) / MASS,
    ];
    const names = ['instant', 'timed', 'constant'];
    for (let i = 0; i < 3; i++) {
      const speed = world.bodies[i]!.linearVelocity.x;
      if (Math.abs(speed - expected[i]!) > 1e-9 * Math.max(1, expected[i]!)) {
        return `${names[i]} force: ${speed} m/s, expected ${expected[i]} m/s`;
      }
    }
    return null;
  },
});
