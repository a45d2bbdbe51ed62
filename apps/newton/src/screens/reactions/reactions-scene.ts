import { type Body, type Force, World, particle, wall } from '@physical/engine';
import type { Tilt } from '../../sensors/device-tilt.ts';

/** Force (N) on every particle when the device is tilted fully (|tilt| = 1). */
export const PUSH_FORCE = 1;
export const MIN_RADIUS = 0.15;
export const MAX_RADIUS = 0.45;
/** kg/m^2: one density for all, so a particle's size shows its mass. */
export const PARTICLE_DENSITY = 1;
/** Default bounciness of collisions (the slider's start). */
export const DEFAULT_ELASTICITY = 0.8;

/** What the app keeps about a particle besides the body. */
export interface ParticleInfo {
  readonly push: Force;
  /** Normal impulse (N s) of the particle's last collision, or null before the first. */
  lastImpulse: number | null;
}

/** The Reactions screen's world: walls around and inside, particles the learner adds. */
export interface ReactionsScene {
  readonly world: World;
  readonly width: number;
  readonly height: number;
  readonly particles: Map<Body, ParticleInfo>;
  tilt: Tilt;
  /** Restitution of particle collisions, 0 (they stick) to 1 (perfectly elastic). */
  elasticity: number;
}

/** Builds the walls of a `width` x `height` metre box (y-down), with two slanted walls inside. */
export function createReactionsScene(
  width: number,
  height: number,
  elasticity = DEFAULT_ELASTICITY,
): ReactionsScene {
  // Set here, not left to the engine's defaults: slow bounces below 5 cm/s are resolved as rest.
  const world = new World({ gravity: { x: 0, y: 0 }, restitutionThreshold: 0.05 });
  const corners = [
    { x: 0, y: 0 },
    { x: width, y: 0 },
    { x: width, y: height },
    { x: 0, y: height },
  ];
  for (let i = 0; i < 4; i++) {
    world.add(wall({ from: corners[i]!, to: corners[(i + 1) % 4]!, friction: 0.3 }));
  }
  // Two shelves inside: something else to bounce off.
  world.add(
    wall({
      from: { x: width * 0.15, y: height * 0.3 },
      to: { x: width * 0.45, y: height * 0.38 },
      friction: 0.3,
    }),
  );
  world.add(
    wall({
      from: { x: width * 0.55, y: height * 0.68 },
      to: { x: width * 0.85, y: height * 0.6 },
      friction: 0.3,
    }),
  );
  for (const body of world.bodies) for (const shape of body.shapes) shape.restitution = elasticity;
  return { world, width, height, particles: new Map(), tilt: { x: 0, y: 0 }, elasticity };
}

/**
 * The push (N) on each particle for a tilt: the same force for every mass, at most
 * {@link PUSH_FORCE} in any direction (a diagonal full tilt is 1 N, not 1.41 N).
 */
export function pushFor(tilt: Tilt): { x: number; y: number } {
  const size = Math.hypot(tilt.x, tilt.y);
  const scale = size > 1 ? PUSH_FORCE / size : PUSH_FORCE;
  return { x: scale * tilt.x, y: scale * tilt.y };
}

/** Sets the bounciness (0..1) of every particle and wall. */
export function setElasticity(scene: ReactionsScene, elasticity: number): void {
  scene.elasticity = elasticity;
  for (const body of scene.world.bodies)
    for (const shape of body.shapes) shape.restitution = elasticity;
}

/** The total momentum of the particles (kg m/s). */
export function totalMomentum(scene: ReactionsScene): { x: number; y: number } {
  let x = 0;
  let y = 0;
  for (const body of scene.particles.keys()) {
    x += body.mass * body.linearVelocity.x;
    y += body.mass * body.linearVelocity.y;
  }
  return { x, y };
}

/**
 * Adds a particle at `point` (moved inside the box if needed) with a random radius (so a random
 * mass) and the scene's bounciness, pushed by the current tilt.
 */
export function spawnParticle(
  scene: ReactionsScene,
  point: { x: number; y: number },
  random: () => number = Math.random,
): Body {
  const radius = MIN_RADIUS + (MAX_RADIUS - MIN_RADIUS) * random();
  const restitution = scene.elasticity;
  const x = Math.min(Math.max(point.x, radius + 0.01), scene.width - radius - 0.01);
  const y = Math.min(Math.max(point.y, radius + 0.01), scene.height - radius - 0.01);
  const body = scene.world.add(
    particle({
      position: { x, y },
      radius,
      density: PARTICLE_DENSITY,
      restitution,
      friction: 0.3,
    }),
  );
  const push = body.applyForce(pushFor(scene.tilt), { duration: 'constant' });
  scene.particles.set(body, { push, lastImpulse: null });
  return body;
}

/**
 * The most of the box the particles may cover. Randomly placed discs cannot all lie apart much
 * beyond this, and an overfull box (holding the Add key repeats it 30 times a second) would push
 * particles through its walls: 100 particles in a 4 x 7.5 m box reached 260 m/s.
 */
export const MAX_FILL = 0.45;

/** Area (m^2) the particles cover. */
export function filledArea(scene: ReactionsScene): number {
  let area = 0;
  for (const body of scene.particles.keys()) {
    for (const shape of body.shapes) {
      if (shape.geometry.kind === 'circle') area += Math.PI * shape.geometry.radius ** 2;
    }
  }
  return area;
}

/** True when the largest particle would take the particles past {@link MAX_FILL} of the box. */
export function isFull(scene: ReactionsScene): boolean {
  return filledArea(scene) + Math.PI * MAX_RADIUS ** 2 > MAX_FILL * scene.width * scene.height;
}

/**
 * A spot for a new particle that touches nothing yet, from up to 40 random tries in the middle of
 * the box; the last try when none is free.
 */
export function freeSpot(
  scene: ReactionsScene,
  random: () => number = Math.random,
): { x: number; y: number } {
  let spot = { x: scene.width / 2, y: scene.height / 2 };
  for (let i = 0; i < 40; i++) {
    spot = {
      x: scene.width * (0.15 + 0.7 * random()),
      y: scene.height * (0.15 + 0.7 * random()),
    };
    const around = scene.world.overlapShape(
      { type: 'circle', radius: MAX_RADIUS },
      { position: spot },
    );
    if (around.length === 0) break;
  }
  return spot;
}

/** Sets the tilt: every particle's push changes to the same new force. */
export function setTilt(scene: ReactionsScene, tilt: Tilt): void {
  scene.tilt = tilt;
  const push = pushFor(tilt);
  for (const info of scene.particles.values()) info.push.setVector(push);
}

/** Removes every particle. */
export function clearParticles(scene: ReactionsScene): void {
  for (const body of scene.particles.keys()) scene.world.remove(body);
  scene.particles.clear();
}
