import { type Body, type Force, World, regularPolygon, wall } from '@physical/engine';

/** Size of the polygon: distance from its centre to a vertex (m). */
export const POLYGON_RADIUS = 0.5;
/** The polygon's mass (kg): 1 kg makes the acceleration read the same as the force. */
export const POLYGON_MASS = 1;
/** Force magnitudes the dialog offers (N). */
export const MIN_FORCE = 0.1;
export const MAX_FORCE = 5;

/** The floor under the body: ice has no friction, wood slows a gliding body down. */
export type Surface = 'ice' | 'wood';
/** Kinetic friction coefficient of each surface against the body. */
export const SURFACE_FRICTION: Record<Surface, number> = { ice: 0, wood: 0.05 };
/** m/s^2: friction on the floor is mu m g. */
export const GRAVITY = 9.81;
/** The walls' names, in the order of {@link InertiaScene.walls}. */
export const WALL_NAMES = ['top', 'right', 'bottom', 'left'] as const;

/** What the learner chooses for the Inertia screen. */
export interface InertiaOptions {
  /** Bounciness of the walls, 0 (the body stops at a wall) to 1 (perfectly elastic). Default 1. */
  readonly elasticity?: number;
  /** The floor. Default ice (no friction). */
  readonly surface?: Surface;
  /** Sides of the polygon; random (5 or 6) when left out. */
  readonly sides?: 5 | 6;
}

/** The Inertia screen's world: four walls around a regular polygon at rest in the centre. */
export interface InertiaScene {
  readonly world: World;
  readonly body: Body;
  readonly width: number;
  readonly height: number;
  readonly sides: 5 | 6;
  /** The walls: top, right, bottom, left. */
  readonly walls: readonly Body[];
  /** Wall bounciness (0..1), shown and set on screen: nothing about the motion is hidden. */
  elasticity: number;
  surface: Surface;
  /** The floor's friction force on the body (zero on ice or at rest). */
  readonly friction: Force;
}

/** Area of a regular polygon with `sides` sides and circumradius `radius`. */
export function regularPolygonArea(sides: number, radius: number): number {
  return 0.5 * sides * radius * radius * Math.sin((2 * Math.PI) / sides);
}

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

/**
 * The scene around a world built by {@link createInertiaScene}, or restored from a snapshot of
 * one (the same bodies and forces in the same order, new objects): the walls are its first four
 * bodies, the polygon the fifth, the floor's friction the polygon's first force.
 */
function sceneOf(
  world: World,
  settings: Pick<InertiaScene, 'width' | 'height' | 'sides' | 'elasticity' | 'surface'>,
): InertiaScene {
  const body = world.bodies[4]!;
  const scene: InertiaScene = {
    world,
    body,
    ...settings,
    walls: world.bodies.slice(0, 4),
    friction: body.forces[0]!,
  };
  // After each step the body moved in, the friction for the next step.
  world.on('move', (moved) => {
    if (moved === body) updateFloorFriction(scene);
  });
  return scene;
}

/**
 * The scene again around `world`, a restored snapshot of `scene`'s world (stepping back): the
 * walls' bounciness and the floor as the learner has them now, not as they were.
 */
export function adoptWorld(scene: InertiaScene, world: World): InertiaScene {
  const { width, height, sides, elasticity, surface } = scene;
  const next = sceneOf(world, { width, height, sides, elasticity, surface });
  setElasticity(next, scene.elasticity);
  return next;
}

/**
 * Where the polygon is and how it moves as the lab reports it (m, m/s): from the floor's left
 * end, x to the right and y up, the way the directions on screen count (90° is up).
 */
export function labMotion(scene: InertiaScene): { x: number; y: number; vx: number; vy: number } {
  const { position, linearVelocity } = scene.body;
  return {
    x: position.x,
    y: scene.height - position.y,
    vx: linearVelocity.x,
    vy: linearVelocity.y === 0 ? 0 : -linearVelocity.y,
  };
}

/**
 * Returns the body to the centre, at rest (PhET's "return the object"): the force the learner
 * set is theirs to stop; this only moves the body back.
 */
export function returnBody(scene: InertiaScene): void {
  const { body } = scene;
  body.position = { x: scene.width / 2, y: scene.height / 2 };
  body.linearVelocity = { x: 0, y: 0 };
  scene.friction.setVector({ x: 0, y: 0 });
  body.wake();
}

/**
 * The forces on the body as the learner sees them (N, y-down): the applied one, the floor's
 * friction, the walls' push (their normal force over the last step, while it touches one) and
 * the sum of all three. A body pinned against a wall by the force reads a sum of zero.
 */
export function forcesOn(
  scene: InertiaScene,
  applied: { x: number; y: number } | null,
): { applied: Vec; friction: Vec; wall: Vec; net: Vec } {
  const a = applied ?? { x: 0, y: 0 };
  const friction = { x: scene.friction.x, y: scene.friction.y };
  const wall = { x: 0, y: 0 };
  const dt = scene.world.lastStepDuration;
  if (dt > 0) {
    scene.world.forEachContact((contact) => {
      // The event's impulse acts on body B along the normal, and its opposite on A.
      const sign = contact.bodyB === scene.body ? 1 : contact.bodyA === scene.body ? -1 : 0;
      wall.x += (sign * contact.normalImpulse * contact.normalX) / dt;
      wall.y += (sign * contact.normalImpulse * contact.normalY) / dt;
    });
  }
  return {
    applied: a,
    friction,
    wall,
    net: { x: a.x + friction.x + wall.x, y: a.y + friction.y + wall.y },
  };
}

interface Vec {
  x: number;
  y: number;
}

/** Sets the walls' bounciness (0..1) on walls and body. */
export function setElasticity(scene: InertiaScene, elasticity: number): void {
  scene.elasticity = elasticity;
  for (const item of scene.world.bodies) {
    for (const shape of item.shapes) shape.restitution = elasticity;
  }
}

/** Chooses the floor. */
export function setSurface(scene: InertiaScene, surface: Surface): void {
  scene.surface = surface;
  updateFloorFriction(scene);
  scene.body.wake();
}

/**
 * Kinetic friction from the floor, mu m g against the velocity, for the next step. A body it
 * would stop within the step (and with no other force) is stopped and put to sleep.
 */
export function updateFloorFriction(scene: InertiaScene, dt = 1 / 60): void {
  const { body } = scene;
  const mu = SURFACE_FRICTION[scene.surface];
  const v = body.linearVelocity;
  const speed = Math.hypot(v.x, v.y);
  if (mu === 0 || speed === 0) {
    if (scene.friction.x !== 0 || scene.friction.y !== 0) scene.friction.setVector({ x: 0, y: 0 });
    return;
  }
  const size = mu * body.mass * GRAVITY;
  if (speed <= (size / body.mass) * dt && body.forces.length <= 1) {
    scene.friction.setVector({ x: 0, y: 0 });
    body.linearVelocity = { x: 0, y: 0 };
    body.sleep();
    return;
  }
  scene.friction.setVector({ x: (-size * v.x) / speed, y: (-size * v.y) / speed });
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

/** Speeds below this (m/s) read as rest: a body pressed on a wall jitters by less. */
export const REST_SPEED = 0.005;

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
