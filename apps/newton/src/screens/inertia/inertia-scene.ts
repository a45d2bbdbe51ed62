import { type Body, type Force, World, regularPolygon, wall } from '@physical/engine';

/** Size of the polygon: distance from its centre to a vertex (m). */
export const POLYGON_RADIUS = 0.5;
/** The polygon's mass (kg): 1 kg makes the acceleration read the same as the force. */
export const POLYGON_MASS = 1;
/** Force magnitudes the dialog offers (N). */
export const MIN_FORCE = 0.1;
export const MAX_FORCE = 5;

/** The Inertia screen's world: four walls around a regular polygon at rest in the centre. */
export interface InertiaScene {
  readonly world: World;
  readonly body: Body;
  readonly width: number;
  readonly height: number;
  readonly sides: 5 | 6;
  readonly restitution: number;
  readonly friction: number;
}

/** Area of a regular polygon with `sides` sides and circumradius `radius`. */
export function regularPolygonArea(sides: number, radius: number): number {
  return 0.5 * sides * radius * radius * Math.sin((2 * Math.PI) / sides);
}

/**
 * Builds the scene in a `width` x `height` metre box (y-down): no gravity, no drag, and the
 * polygon's restitution and friction drawn from [0, 1] with `random`.
 */
export function createInertiaScene(
  width: number,
  height: number,
  random: () => number = Math.random,
): InertiaScene {
  const world = new World({ gravity: { x: 0, y: 0 }, restitutionThreshold: 0, enableSleep: false });
  const corners = [
    { x: 0, y: 0 },
    { x: width, y: 0 },
    { x: width, y: height },
    { x: 0, y: height },
  ];
  for (let i = 0; i < 4; i++) {
    // Walls take their material from the body: friction 1 and restitution 0 mix to the body's.
    world.add(wall({ from: corners[i]!, to: corners[(i + 1) % 4]!, friction: 1, restitution: 0 }));
  }
  const sides = random() < 0.5 ? 5 : 6;
  const restitution = random();
  const friction = random();
  const body = world.add(
    regularPolygon({
      position: { x: width / 2, y: height / 2 },
      angle: -Math.PI / 2,
      sides,
      radius: POLYGON_RADIUS,
      density: POLYGON_MASS / regularPolygonArea(sides, POLYGON_RADIUS),
      restitution,
      friction,
      drag: 0,
      linearDamping: 0,
      angularDamping: 0,
    }),
  );
  return { world, body, width, height, sides, restitution, friction };
}

/**
 * The force vector (N, y-down world) for a direction in degrees counter-clockwise from +x as the
 * learner sees it on screen (0 = right, 90 = up) and a magnitude.
 */
export function forceVector(angleDegrees: number, magnitude: number): { x: number; y: number } {
  const radians = (angleDegrees * Math.PI) / 180;
  const x = magnitude * Math.cos(radians);
  const y = -magnitude * Math.sin(radians);
  // Exact zeros for the axis directions (no 6e-17 components).
  return { x: Math.abs(x) < 1e-12 ? 0 : x, y: Math.abs(y) < 1e-12 ? 0 : y };
}

/** Starts a constant force on the polygon; `.remove()` it to stop. */
export function applyConstantForce(
  scene: InertiaScene,
  angleDegrees: number,
  magnitude: number,
): Force {
  return scene.body.applyForce(forceVector(angleDegrees, magnitude), { duration: 'constant' });
}

/** Direction of motion in degrees counter-clockwise from +x on screen, in [0, 360). */
export function screenAngle(vector: { x: number; y: number }): number {
  const degrees = (Math.atan2(-vector.y, vector.x) * 180) / Math.PI;
  return degrees < 0 ? degrees + 360 : degrees;
}

/** A world size with the canvas's aspect: the short side 6 m, the long side at most 12 m. */
export function sceneSizeFor(
  cssWidth: number,
  cssHeight: number,
): { width: number; height: number } {
  const short = 6;
  if (!(cssWidth > 0 && cssHeight > 0)) return { width: short, height: short * 1.25 };
  const aspect = cssWidth / cssHeight;
  return aspect >= 1
    ? { width: Math.min(short * aspect, 2 * short), height: short }
    : { width: short, height: Math.min(short / aspect, 2 * short) };
}
