import { World, regularPolygon, wall } from '@physical/engine';
import { defineScene } from '../scene.ts';

const WIDTH = 12;
const HEIGHT = 8;
/** The force acts for this long, then the polygon coasts (s). */
const PUSH = 1;
const MASS = 1;

/**
 * The thesis's first law: a polygon at rest in empty space (no gravity, no friction, no drag)
 * is pushed for one second, then left alone: it keeps the velocity the push gave it.
 */
export default defineScene({
  id: 'newton-inertia',
  title: 'Newton: inertia',
  description:
    'First law. A 1 kg hexagon is pushed for one second, then nothing acts on it: it goes on at the same speed in the same direction until a wall stops it.',
  parameters: [
    { name: 'force', label: 'Force (N)', min: 0.1, max: 5, step: 0.1, default: 1 },
    {
      name: 'direction',
      label: 'Direction (deg, 0 = right, 90 = up)',
      min: 0,
      max: 359,
      step: 1,
      default: 30,
    },
  ],
  camera: { x: 0, y: 0, width: WIDTH, height: HEIGHT },
  pixelsPerMeter: 40,
  steps: 150,
  build({ force, direction }) {
    const world = new World({
      gravity: { x: 0, y: 0 },
      restitutionThreshold: 0,
      enableSleep: false,
    });
    const corners = [
      { x: 0, y: 0 },
      { x: WIDTH, y: 0 },
      { x: WIDTH, y: HEIGHT },
      { x: 0, y: HEIGHT },
    ];
    for (let i = 0; i < 4; i++) {
      world.add(wall({ from: corners[i]!, to: corners[(i + 1) % 4]!, restitution: 0.8 }));
    }
    const radius = 0.5;
    const area = 0.5 * 6 * radius * radius * Math.sin(Math.PI / 3);
    const body = world.add(
      regularPolygon({
        position: { x: WIDTH / 2, y: HEIGHT / 2 },
        sides: 6,
        radius,
        density: MASS / area,
      }),
    );
    // Screen angles count counter-clockwise from +x; the world is y-down, so y flips.
    const radians = (direction * Math.PI) / 180;
    body.applyForce(
      { x: force * Math.cos(radians), y: -force * Math.sin(radians) },
      { duration: PUSH },
    );
    return world;
  },
  check(world, { force, direction }) {
    const body = world.bodies[4]!;
    const radians = (direction * Math.PI) / 180;
    const speed = (force * PUSH) / MASS;
    const v = body.linearVelocity;
    const error = Math.hypot(v.x - speed * Math.cos(radians), v.y + speed * Math.sin(radians));
    if (error > 1e-9 * speed)
      return `velocity (${v.x}, ${v.y}) after the push, expected ${speed} m/s at ${direction}\u00b0`;
    return null;
  },
});
