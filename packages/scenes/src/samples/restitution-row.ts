import { World, particle, wall } from '@physical/engine';
import { defineScene } from '../scene.ts';

interface Bounce {
  /** Restitution of the ball. */
  readonly e: number;
  /** Rebound speed over approach speed at the first bounce, or null before it. */
  measured: number | null;
}

/**
 * Balls dropped side by side, restitution from 0 to 1. Each first bounce leaves at e times the
 * speed it arrived with, so it climbs back to e^2 of the height.
 */
export default defineScene({
  id: 'restitution-row',
  title: 'Restitution row',
  description:
    'Balls with restitution e from 0 (left) to 1 (right) fall from the same height and bounce back to e\u00b2 of it.',
  parameters: [
    { name: 'count', label: 'Balls', min: 2, max: 11, step: 1, default: 6 },
    { name: 'height', label: 'Drop height (m)', min: 1, max: 8, step: 0.5, default: 4 },
  ],
  camera: { x: -0.5, y: -9, width: 12, height: 9.5 },
  pixelsPerMeter: 40,
  steps: 240,
  build({ count, height }) {
    // No threshold: every impact bounces, however slow (the default ignores impacts under 1 m/s).
    const world = new World({ restitutionThreshold: 0 });
    world.add(wall({ from: { x: -1, y: 0 }, to: { x: 12, y: 0 }, restitution: 0 }));
    const radius = 0.3;
    for (let i = 0; i < count; i++) {
      const e = i / (count - 1);
      const bounce: Bounce = { e, measured: null };
      world.add(
        particle<Bounce>({
          position: { x: 0.5 + (i * 10) / (count - 1), y: -height - radius },
          radius,
          restitution: e,
          userData: bounce,
          onCollision: (event) => {
            if (bounce.measured !== null || event.approachSpeed === 0) return;
            const body = event.bodyA.type === 'dynamic' ? event.bodyA : event.bodyB;
            bounce.measured = Math.max(0, -body.linearVelocity.y) / event.approachSpeed;
          },
        }),
      );
    }
    return world;
  },
  check(world) {
    for (const body of world.bodies) {
      const bounce = body.userData as Bounce | undefined;
      if (bounce === undefined) continue;
      if (bounce.measured === null) return `the ball with e = ${bounce.e} never bounced`;
      if (Math.abs(bounce.measured - bounce.e) > 0.02) {
        return `e = ${bounce.e.toFixed(2)} rebounded at ${bounce.measured.toFixed(3)} of its speed`;
      }
    }
    return null;
  },
});
