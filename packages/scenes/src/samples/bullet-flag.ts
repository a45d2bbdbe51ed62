import { type Body, World, box, particle, wall } from '@physical/engine';
import { defineScene } from '../scene.ts';

const SPEED = 300;
const PLATE_X = 6;
const PLATE_THICKNESS = 0.05;
const PLATE_LENGTH = 1;
/** Launch distance from the plate: the shot reaches it during its first step. */
const RANGE = 2.6;
const ROW_GAP = 1.4;
const BACKSTOP_X = 9.5;
const STEP = 1 / 60;

/** What a shot records about its plate. */
interface Shot {
  readonly row: number;
  /** Position and speed at the start of the last step. */
  x: number;
  y: number;
  speed: number;
  /** Steps in which the shot crossed its plate while still fast. */
  passes: number;
}

/**
 * Continuous collision stops every fast body at static shapes; only a bullet is also swept
 * against moving bodies. Each small ball is fired at a free plate 5 cm thick that slides across
 * its path: moving 5 m per step, a plain ball can step over the plate's new position; a bullet is
 * swept against it and stops there.
 */
export default defineScene({
  id: 'bullet-flag',
  title: 'The bullet flag',
  description:
    'Balls of 2 cm at 300 m/s against free plates 5 cm thick sliding across their path. With Bullet = 1 each ball strikes its plate; at 0 the plain balls get through the moving plates.',
  parameters: [
    { name: 'bullet', label: 'Bullet (0 = off, 1 = on)', min: 0, max: 1, step: 1, default: 1 },
    { name: 'count', label: 'Shots', min: 1, max: 6, step: 1, default: 4 },
    { name: 'plateSpeed', label: 'Plate speed (m/s)', min: 0, max: 40, step: 5, default: 30 },
  ],
  camera: { x: 2.5, y: -9, width: 8, height: 9.5 },
  pixelsPerMeter: 40,
  steps: 30,
  build({ bullet, count, plateSpeed }) {
    const world = new World({ gravity: { x: 0, y: 0 } });
    // A backstop behind the plates: continuous collision stops every shot at a static wall, so
    // the ones that got through wait there.
    world.add(wall({ from: { x: BACKSTOP_X, y: 0 }, to: { x: BACKSTOP_X, y: -ROW_GAP * 6 } }));
    // A floor that catches the sliding plates, so they stay in view.
    world.add(wall({ from: { x: 2.5, y: 0.3 }, to: { x: BACKSTOP_X, y: 0.3 } }));
    for (let i = 0; i < count; i++) {
      const y = -0.8 - i * ROW_GAP;
      // The launcher, just behind the shot.
      world.add(
        box({ type: 'static', position: { x: PLATE_X - RANGE - 0.4, y }, width: 0.6, height: 0.3 }),
      );
      // The shot meets the plate between 0.15 and 0.45 m from its middle at the end of the first
      // step, the pose a bullet is swept against (Box2D v3's order).
      const offset = 0.15 + 0.1 * (i % 4);
      const plate = world.add(
        box({
          position: { x: PLATE_X, y: y - offset - 0.5 * plateSpeed * STEP },
          width: PLATE_THICKNESS,
          height: PLATE_LENGTH,
          linearVelocity: { x: 0, y: plateSpeed },
        }),
      );
      const shot: Shot = { row: i, x: PLATE_X - RANGE, y, speed: SPEED, passes: 0 };
      world.add(
        particle<Shot>({
          position: { x: shot.x, y },
          radius: 0.02,
          density: 2,
          bullet: bullet === 1,
          linearVelocity: { x: SPEED, y: 0 },
          userData: shot,
          onMove: (body) => recordPass(body, plate, shot),
        }),
      );
    }
    return world;
  },
  check(world, { count }) {
    let through = 0;
    for (const body of world.bodies) {
      const shot = body.userData as Shot | undefined;
      if (shot !== undefined && shot.passes > 0) through++;
    }
    return through === 0 ? null : `${through} of ${count} shots passed through their plates`;
  },
});

/**
 * Counts a pass-through: a step begun faster than 100 m/s whose motion, seen in the plate's
 * frame at the end of the step, crosses the plate's mid-line within its length.
 */
function recordPass(body: Body, plate: Body, shot: Shot): void {
  const before = plate.getLocalPoint({ x: shot.x, y: shot.y });
  const after = plate.getLocalPoint(body.position);
  if (shot.speed > 100 && before.x < 0 !== after.x < 0) {
    const y = before.y + (-before.x / (after.x - before.x)) * (after.y - before.y);
    if (Math.abs(y) < PLATE_LENGTH / 2) shot.passes++;
  }
  shot.x = body.position.x;
  shot.y = body.position.y;
  shot.speed = Math.hypot(body.linearVelocity.x, body.linearVelocity.y);
}
