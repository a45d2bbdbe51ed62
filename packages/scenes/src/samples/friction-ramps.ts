import { World, box } from '@physical/engine';
import { defineScene } from '../scene.ts';

/** Friction coefficients of the five ramps, top to bottom. */
const FRICTIONS = [0, 0.2, 0.4, 0.6, 0.8];
const RAMP_LENGTH = 6;
const RAMP_THICKNESS = 0.2;
const SIZE = 0.5;

interface Slider {
  readonly friction: number;
  readonly start: { readonly x: number; readonly y: number };
}

/**
 * Five ramps at the same angle, each with a block of a different friction coefficient. A block
 * stays put when mu >= tan(angle) (Coulomb), and slides otherwise.
 */
export default defineScene({
  id: 'friction-ramps',
  title: 'Friction ramps',
  description:
    'Blocks with friction 0 to 0.8 on ramps at the same angle: those with \u03bc below tan(angle) slide, the others stick.',
  parameters: [{ name: 'angle', label: 'Angle (deg)', min: 5, max: 45, step: 1, default: 25 }],
  camera: { x: -5, y: -1, width: 12, height: 16 },
  pixelsPerMeter: 40,
  steps: 180,
  build({ angle }) {
    const world = new World();
    const theta = (angle * Math.PI) / 180;
    // A positive angle turns +x toward +y: on a y-down screen the ramp falls to the right.
    const along = { x: Math.cos(theta), y: Math.sin(theta) };
    const normal = { x: Math.sin(theta), y: -Math.cos(theta) }; // the ramp's upper side
    FRICTIONS.forEach((friction, i) => {
      const center = { x: 0, y: 2.8 * i };
      world.add(
        box({
          type: 'static',
          position: center,
          angle: theta,
          width: RAMP_LENGTH,
          height: RAMP_THICKNESS,
          friction,
        }),
      );
      // A block 1 m below the ramp's upper end, resting on its surface.
      const lift = RAMP_THICKNESS / 2 + SIZE / 2;
      const start = {
        x: center.x - along.x * (RAMP_LENGTH / 2 - 1) + normal.x * lift,
        y: center.y - along.y * (RAMP_LENGTH / 2 - 1) + normal.y * lift,
      };
      world.add(
        box<Slider>({
          position: start,
          angle: theta,
          width: SIZE,
          height: SIZE,
          friction, // both surfaces alike: the pair mixes to sqrt(mu * mu) = mu
          userData: { friction, start },
        }),
      );
    });
    return world;
  },
  check(world, { angle }) {
    const slope = Math.tan((angle * Math.PI) / 180);
    for (const body of world.bodies) {
      const slider = body.userData as Slider | undefined;
      if (slider === undefined) continue;
      const moved = Math.hypot(body.position.x - slider.start.x, body.position.y - slider.start.y);
      // Within 0.08 of the limit the outcome depends on the solver's softness: not asserted.
      if (slider.friction < slope - 0.08 && moved < 0.5) {
        return `\u03bc = ${slider.friction} should slide at ${angle}\u00b0 but moved ${moved.toFixed(3)} m`;
      }
      if (slider.friction > slope + 0.08 && moved > 0.05) {
        return `\u03bc = ${slider.friction} should stick at ${angle}\u00b0 but moved ${moved.toFixed(3)} m`;
      }
    }
    return null;
  },
});
