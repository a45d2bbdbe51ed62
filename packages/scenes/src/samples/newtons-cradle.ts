import { type Body, World, box, distanceJoint, particle } from '@physical/engine';
import { defineScene } from '../scene.ts';

const RADIUS = 0.25;
const LENGTH = 2;
const BALLS = 5;

interface Bob {
  /** Where the ball hangs at rest (x, m). */
  readonly restX: number;
}

/**
 * Newton's cradle: five equal, perfectly elastic balls, each hung on a rod (a distance joint)
 * from a bar, touching in a row. Pull some out and let go: as many fly out of the other end, to
 * the same height, and the middle ones stay put.
 */
export default defineScene({
  id: 'newtons-cradle',
  title: "Newton's cradle",
  description:
    'Five elastic balls hang on rods (distance joints). Swing one in and one swings out at the other end, to the same height: momentum and energy pass through the row.',
  parameters: [
    { name: 'pulled', label: 'Balls pulled', min: 1, max: 4, step: 1, default: 1 },
    { name: 'angle', label: 'Pulled to (deg)', min: 5, max: 60, step: 5, default: 30 },
  ],
  camera: { x: -3, y: -0.6, width: 6, height: 3.2 },
  pixelsPerMeter: 80,
  // Release to impact is a quarter swing, impact to the top of the far swing another: about 1.4 s.
  steps: 85,
  build({ pulled, angle }) {
    const world = new World({ enableSleep: false, restitutionThreshold: 0 });
    const bar = world.add(
      box({ type: 'static', position: { x: 0, y: -0.05 }, width: 3, height: 0.1 }),
    );
    const theta = (angle * Math.PI) / 180;
    for (let i = 0; i < BALLS; i++) {
      const restX = (i - (BALLS - 1) / 2) * 2 * RADIUS;
      // The first `pulled` balls swing out to the left together, as if held as one.
      const position =
        i < pulled
          ? { x: restX - LENGTH * Math.sin(theta), y: LENGTH * Math.cos(theta) }
          : { x: restX, y: LENGTH };
      const ball: Body = world.add(
        particle<Bob>({
          position,
          radius: RADIUS,
          restitution: 1,
          friction: 0,
          userData: { restX },
        }),
      );
      world.addJoint(
        distanceJoint({ bodyA: bar, bodyB: ball, anchorA: { x: restX, y: 0 }, anchorB: position }),
      );
    }
    return world;
  },
  check(world, { pulled, angle }) {
    const balls = world.bodies.slice(1);
    const reach = LENGTH * Math.sin((angle * Math.PI) / 180);
    const moved = balls.map((ball) => ball.position.x - (ball.userData as Bob).restX);
    // The last `pulled` balls swing out; the others hang still (within 5 cm).
    for (let i = 0; i < BALLS; i++) {
      const out = i >= BALLS - pulled;
      if (out && moved[i]! < 0.8 * reach) {
        return `ball ${i} swung out ${moved[i]!.toFixed(3)} m, expected about ${reach.toFixed(3)} m`;
      }
      if (!out && Math.abs(moved[i]!) > 0.05) return `ball ${i} moved ${moved[i]!.toFixed(3)} m`;
    }
    return null;
  },
});
