import { Body, World, wall } from '@physical/engine';
import type { ShapeOptions } from '@physical/engine';
import { defineScene } from '../scene.ts';

/** L, T and U outlines, each one rigid body made of convex boxes. */
const OUTLINES: readonly (readonly ShapeOptions[])[] = [
  [
    { type: 'box', width: 0.4, height: 1.6, offset: { x: -0.4, y: 0 } },
    { type: 'box', width: 1.2, height: 0.4, offset: { x: 0, y: 0.6 } },
  ],
  [
    { type: 'box', width: 1.6, height: 0.4, offset: { x: 0, y: -0.6 } },
    { type: 'box', width: 0.4, height: 1.2, offset: { x: 0, y: 0.2 } },
  ],
  [
    { type: 'box', width: 1.6, height: 0.4, offset: { x: 0, y: 0.6 } },
    { type: 'box', width: 0.4, height: 1.2, offset: { x: -0.6, y: -0.2 } },
    { type: 'box', width: 0.4, height: 1.2, offset: { x: 0.6, y: -0.2 } },
  ],
];

/**
 * Non-convex bodies built from convex parts: a body takes several shapes and moves as one, with
 * mass, centre of mass and inertia combined from its parts.
 */
export default defineScene({
  id: 'compound-shapes',
  title: 'Compound shapes',
  description:
    'L, T and U pieces, each one rigid body made of two or three boxes, fall into a bin and interlock.',
  parameters: [
    { name: 'count', label: 'Pieces', min: 3, max: 30, step: 1, default: 12 },
    { name: 'spin', label: 'Starting turn (deg)', min: 0, max: 90, step: 5, default: 30 },
  ],
  camera: { x: -4.5, y: -14, width: 9, height: 14.5 },
  pixelsPerMeter: 40,
  steps: 360,
  build({ count, spin }) {
    const world = new World();
    world.add(wall({ from: { x: -4, y: -14 }, to: { x: -4, y: 0 } }));
    world.add(wall({ from: { x: -4, y: 0 }, to: { x: 4, y: 0 } }));
    world.add(wall({ from: { x: 4, y: 0 }, to: { x: 4, y: -14 } }));
    for (let i = 0; i < count; i++) {
      world.add(
        new Body({
          position: { x: -2 + 2 * (i % 3), y: -2 - 2 * Math.floor(i / 3) },
          angle: ((i % 2 === 0 ? 1 : -1) * spin * Math.PI) / 180,
          shapes: OUTLINES[i % OUTLINES.length]!,
        }),
      );
    }
    return world;
  },
  check(world) {
    for (const body of world.bodies) {
      if (body.type !== 'dynamic') continue;
      const { x, y } = body.position;
      if (y > 0 || Math.abs(x) > 4)
        return `a piece left the bin (at ${x.toFixed(2)}, ${y.toFixed(2)})`;
      if (Math.hypot(body.linearVelocity.x, body.linearVelocity.y) > 0.5) {
        return `a piece is still moving at ${body.linearVelocity.y.toFixed(2)} m/s after the fall`;
      }
    }
    return null;
  },
});
