import { type Body, type Vec2Like, World, box, particle, wall } from '@physical/engine';
import { defineScene } from '../scene.ts';

const WIDTH = 10;
const HEIGHT = 8;

/**
 * Moves a dragged body toward the pointer by setting its velocity: it arrives in `reach` seconds,
 * still collides on the way, and when let go keeps the velocity it had, so a quick flick throws it.
 * Call it once per frame while the pointer is down.
 */
export function dragToward(body: Body, target: Vec2Like, reach = 0.08): void {
  const center = body.centerOfMass;
  body.linearVelocity = { x: (target.x - center.x) / reach, y: (target.y - center.y) / reach };
  body.angularVelocity *= 0.9; // tame the spin while held
}

/** A walled room of crates and balls to pick up and throw (press, drag, release). */
export default defineScene({
  id: 'drag-and-throw',
  title: 'Drag and throw',
  description:
    'Press a crate or a ball, drag it and let go while moving: it flies off with the velocity of your hand. The first crate is thrown for you.',
  parameters: [
    { name: 'count', label: 'Things', min: 2, max: 30, step: 1, default: 12 },
    { name: 'throw', label: 'First throw (m/s)', min: 0, max: 30, step: 1, default: 12 },
  ],
  camera: { x: -0.5, y: -8.5, width: 11, height: 9 },
  pixelsPerMeter: 40,
  steps: 240,
  build({ count, throw: speed }) {
    const world = new World();
    const corners = [
      { x: 0, y: -HEIGHT },
      { x: WIDTH, y: -HEIGHT },
      { x: WIDTH, y: 0 },
      { x: 0, y: 0 },
    ];
    for (let i = 0; i < 4; i++) world.add(wall({ from: corners[i]!, to: corners[(i + 1) % 4]! }));
    for (let i = 0; i < count; i++) {
      const position = { x: 1 + (i % 8) * 1.1, y: -0.5 - 1.2 * Math.floor(i / 8) };
      world.add(
        i % 2 === 0
          ? box({ position, width: 0.8, height: 0.8, restitution: 0.2 })
          : particle({ position, radius: 0.4, restitution: 0.5 }),
      );
    }
    // The demonstration throw: up and to the right, as a flick of the pointer would.
    world.bodies[4]!.linearVelocity = { x: speed * 0.6, y: -speed * 0.8 };
    return world;
  },
  check(world) {
    for (const body of world.bodies) {
      if (body.type !== 'dynamic') continue;
      const { x, y } = body.position;
      if (x < 0 || x > WIDTH || y < -HEIGHT || y > 0) {
        return `a body left the room (at ${x.toFixed(2)}, ${y.toFixed(2)})`;
      }
    }
    return null;
  },
});
