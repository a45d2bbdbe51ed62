import { World, particle } from '@physical/engine';
import { defineScene } from '../scene.ts';

const RADIUS = 0.5;
const MASS = 1;

/**
 * Newton's cradle laid flat: a row of touching, frictionless, perfectly elastic balls on a track,
 * struck from the left, seen from above (no gravity). The collisions pass the momentum along the row to the far end.
 * (The hanging version needs distance joints.)
 */
export default defineScene({
  id: 'newtons-cradle',
  title: "Newton's cradle",
  description:
    'A row of touching elastic balls on a frictionless track, hit by one more from the left: momentum and energy travel through the row.',
  parameters: [
    { name: 'count', label: 'Balls in the row', min: 2, max: 8, step: 1, default: 5 },
    { name: 'speed', label: 'Striker speed (m/s)', min: 0.5, max: 6, step: 0.5, default: 3 },
  ],
  camera: { x: -4, y: -4, width: 16, height: 5 },
  pixelsPerMeter: 40,
  steps: 120,
  build({ count, speed }) {
    // Seen from above: no gravity, so the track does no work and only the row's momentum counts.
    const world = new World({
      gravity: { x: 0, y: 0 },
      restitutionThreshold: 0,
      enableSleep: false,
    });
    const density = MASS / (Math.PI * RADIUS * RADIUS);
    const ball = (x: number, vx: number) =>
      world.add(
        particle({
          position: { x, y: -RADIUS },
          linearVelocity: { x: vx, y: 0 },
          radius: RADIUS,
          density,
          friction: 0,
          restitution: 1,
        }),
      );
    ball(-2.5, speed); // the striker
    for (let i = 0; i < count; i++) ball(i * 2 * RADIUS, 0);
    return world;
  },
  check(world, { speed }) {
    let momentum = 0;
    let energy = 0;
    for (const body of world.bodies) {
      momentum += body.mass * body.linearVelocity.x;
      energy += body.kineticEnergy;
    }
    const expected = MASS * speed;
    if (Math.abs(momentum - expected) > 1e-9 * expected) {
      return `momentum ${momentum} kg m/s, struck with ${expected}`;
    }
    const start = 0.5 * MASS * speed * speed;
    if (energy > start * (1 + 1e-9)) return `kinetic energy grew from ${start} J to ${energy} J`;
    if (energy < start * 0.95)
      return `lost ${(100 * (1 - energy / start)).toFixed(1)}% of the energy`;
    return null;
  },
});
