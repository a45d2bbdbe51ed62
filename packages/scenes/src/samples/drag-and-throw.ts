import {
  type Body,
  type MouseJoint,
  type Vec2Like,
  World,
  box,
  mouseJoint,
  particle,
  wall,
} from '@physical/engine';
import { defineScene } from '../scene.ts';

const WIDTH = 10;
const HEIGHT = 8;

/**
 * Grabs `body` at `point` (m) with a mouse joint: a soft, bounded pull toward a target you move
 * with the pointer (`joint.target = point`). Remove the joint to let go: the body keeps the
 * velocity it had, so a quick flick throws it.
 */
export function grab(body: Body, point: Vec2Like): MouseJoint {
  const world = body.world!;
  return world.addJoint(
    mouseJoint({ body, target: point, maxForce: 1000 * body.mass, hertz: 8, dampingRatio: 0.7 }),
  );
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
    // The demonstration: grab the first crate, pull it up and to the right for a quarter of a
    // second, let go (the joint removes itself when the time is up).
    const crate = world.bodies[4]!;
    const joint = grab(crate, crate.position);
    joint.target = { x: crate.position.x + speed * 0.15, y: crate.position.y - speed * 0.2 };
    let steps = 0;
    world.on('move', (body) => {
      if (body === crate && ++steps === 15) world.removeJoint(joint);
    });
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
