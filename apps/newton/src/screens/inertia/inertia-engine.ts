// What the Inertia screen needs of the engine and the canvas, in a chunk of its own that the
// screen imports once it is on the page: on a school phone (Slow 4G, 4x CPU) the screen's
// controls are drawn and answer a tap while this (the engine, its WebAssembly kernel and the
// canvas element, most of the first screen's bytes) is still arriving.
import { World, regularPolygon, wall } from '@physical/engine';
import { ENGINE_SNAPSHOTS } from '../../lab/engine-snapshots.ts';
import {
  POLYGON_MASS,
  POLYGON_RADIUS,
  regularPolygonArea,
  sceneOf,
  type InertiaOptions,
  type InertiaScene,
} from './inertia-scene.ts';

export { ARROW_COLORS, drawArrow } from '@physical/canvas';
export { PhysicalCanvas } from '@physical/react';
export { ENGINE_SNAPSHOTS };

/**
 * Builds the scene in a `width` x `height` metre box (y-down): no gravity in the plane, no drag,
 * frictionless walls with the chosen bounciness (perfectly elastic by default) and the chosen
 * floor. The body does not spin, so the readouts show its motion plainly; it sleeps while at
 * rest with no force on it, so nothing redraws.
 */
export function createInertiaScene(
  width: number,
  height: number,
  options: InertiaOptions = {},
  random: () => number = Math.random,
): InertiaScene {
  const elasticity = options.elasticity ?? 1;
  // Every bounce is resolved with the chosen restitution, however slow (threshold 0).
  const world = new World({ gravity: { x: 0, y: 0 }, restitutionThreshold: 0, enableSleep: false });
  const corners = [
    { x: 0, y: 0 },
    { x: width, y: 0 },
    { x: width, y: height },
    { x: 0, y: height },
  ];
  for (let i = 0; i < 4; i++) {
    // Wall and body carry the same values, so any mixing rule gives them.
    world.add(
      wall({
        from: corners[i]!,
        to: corners[(i + 1) % 4]!,
        friction: 0,
        restitution: elasticity,
      }),
    );
  }
  const sides = options.sides ?? (random() < 0.5 ? 5 : 6);
  const body = world.add(
    regularPolygon({
      position: { x: width / 2, y: height / 2 },
      angle: -Math.PI / 2,
      sides,
      radius: POLYGON_RADIUS,
      density: POLYGON_MASS / regularPolygonArea(sides, POLYGON_RADIUS),
      restitution: elasticity,
      friction: 0,
      drag: 0,
      linearDamping: 0,
      angularDamping: 0,
      fixedRotation: true,
    }),
  );
  // The floor's friction: the polygon's first force, set anew after every step.
  body.applyForce({ x: 0, y: 0 }, { duration: 'constant' });
  body.sleep();
  return sceneOf(world, { width, height, sides, elasticity, surface: options.surface ?? 'ice' });
}
