import { type Body, World, particle, wall } from '@physical/engine';
import { DYNAMIC_PALETTE } from '@physical/canvas';
import type { Tilt } from '../../sensors/device-tilt.ts';

/**
 * Gravity (m/s^2). Tilting the tray by θ gives every particle the force m g sin θ along it: the
 * same acceleration g sin θ for every mass, as balls on a tilted tray have.
 */
export const GRAVITY = 9.81;
export const MIN_RADIUS = 0.15;
export const MAX_RADIUS = 0.45;
/** kg/m^2: one density for all, so a particle's size shows its mass. */
export const PARTICLE_DENSITY = 1;
/** Default bounciness of collisions (the slider's start). */
export const DEFAULT_ELASTICITY = 0.8;

/** What the app keeps about a particle besides the body. */
export interface ParticleInfo {
  /** Its name in tables and the CSV: A, B, C, ... in the order they were added. */
  readonly label: string;
  /**
   * Its colour, an index into the canvas's `DYNAMIC_PALETTE`: from its label, so the particle
   * keeps it when a rewind brings it back.
   */
  readonly color: number;
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
  /** False: the tilt pushes nothing (the tray lies flat whatever the phone does). */
  tiltOn: boolean;
  /** False: the walls and shelves let the particles through (no impulse from them). */
  wallsOn: boolean;
  /** Restitution of particle collisions, 0 (they stick) to 1 (perfectly elastic). */
  elasticity: number;
  /** Particles added so far (names the next one). */
  added: number;
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
  return {
    world,
    width,
    height,
    particles: new Map(),
    tilt: { x: 0, y: 0 },
    tiltOn: true,
    wallsOn: true,
    elasticity,
    added: 0,
  };
}

/**
 * The acceleration (m/s^2) along the tray for a tilt (each component the sine of the lean):
 * g sin θ, the same for every mass, at most g in any direction (a diagonal full tilt is g, not
 * 1.41 g).
 */
export function trayAcceleration(tilt: Tilt): { x: number; y: number } {
  const size = Math.hypot(tilt.x, tilt.y);
  const scale = size > 1 ? GRAVITY / size : GRAVITY;
  return { x: scale * tilt.x, y: scale * tilt.y };
}

/** The name of the `index`th particle (from 0): A to Z, then A2, B2, ... */
export function particleLabel(index: number): string {
  const letter = String.fromCharCode(65 + (index % 26));
  const round = Math.floor(index / 26);
  return round === 0 ? letter : `${letter}${round + 1}`;
}

/** The colour (palette index) of the particle named `label`: the next colour for each next name. */
export function particleColor(label: string): number {
  const letter = label.charCodeAt(0) - 65;
  const round = label.length > 1 ? Number(label.slice(1)) - 1 : 0;
  const index = letter + 26 * round;
  return Number.isInteger(index) && index >= 0 ? index % DYNAMIC_PALETTE.length : 0;
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
  const label = particleLabel(scene.added++);
  scene.particles.set(body, { label, color: particleColor(label), lastImpulse: null });
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

/**
 * Sets the tilt: the world's gravity becomes the tray's g sin θ (zero while the tilt is
 * switched off), so each particle feels m g sin θ.
 */
export function setTilt(scene: ReactionsScene, tilt: Tilt): void {
  scene.tilt = tilt;
  applyTilt(scene.world, tilt, scene.tiltOn);
}

/**
 * Makes `world`'s gravity the tray's g sin θ for `tilt` (zero when `on` is false). The world
 * changes (and its sleeping particles wake) only when the gravity is a new one.
 */
export function applyTilt(world: World, tilt: Tilt, on: boolean): void {
  world.gravity = on ? trayAcceleration(tilt) : { x: 0, y: 0 };
}

/** Switches the tilt's push on or off (off: no force along the tray, whatever the tilt). */
export function setTiltOn(scene: ReactionsScene, on: boolean): void {
  scene.tiltOn = on;
  setTilt(scene, scene.tilt);
}

/**
 * Switches the walls and shelves on or off. Off, they collide with nothing: particles pass
 * through and leave the box, and no wall adds or takes momentum.
 */
export function setWallsOn(scene: ReactionsScene, on: boolean): void {
  scene.wallsOn = on;
  for (const body of scene.world.bodies) {
    if (body.type !== 'static') continue;
    for (const shape of body.shapes) shape.filter = { mask: on ? 0xffffffff : 0 };
  }
}

/** Removes every particle (the names start again at A). */
export function clearParticles(scene: ReactionsScene): void {
  for (const body of scene.particles.keys()) scene.world.remove(body);
  scene.particles.clear();
  scene.added = 0;
}

/** Lightest and heaviest particle the lab takes (kg). */
export const MIN_MASS = 0.05;
export const MAX_MASS = 10;
/** Fastest velocity component the lab takes (m/s). */
export const MAX_SPEED = 10;

/**
 * The radius (m) that shows a mass (kg): grows with the mass (as the square root, like a disc of
 * one density) within what fits in the box.
 */
export function radiusForMass(mass: number): number {
  return Math.min(0.6, Math.max(MIN_RADIUS, 0.3 * Math.sqrt(mass)));
}

/**
 * Gives a particle an exact mass (kg): its disc is resized to show it ({@link radiusForMass}) and
 * its density set so the mass is exact.
 */
export function setParticleMass(body: Body, mass: number): void {
  const shape = body.shapes[0]!;
  const radius = radiusForMass(mass);
  const { restitution, friction } = shape;
  // The new disc first: a body is never left without a shape.
  body.addShape({
    type: 'circle',
    radius,
    density: mass / (Math.PI * radius * radius),
    restitution,
    friction,
  });
  body.removeShape(shape);
  body.mass = mass;
}

/** The setup of one particle of the collision lab. */
export interface LabParticle {
  /** kg */
  readonly mass: number;
  /** Velocity (m/s), x right and y down the screen. */
  readonly vx: number;
  readonly vy?: number;
}

/**
 * The collision lab: removes every particle and puts the given ones (two, usually) on the box's
 * middle line, spread evenly from left to right, with their masses and velocities. The
 * returned bodies are named A, B, ...
 */
export function setUpLab(scene: ReactionsScene, setups: readonly LabParticle[]): Body[] {
  clearParticles(scene);
  const bodies: Body[] = [];
  setups.forEach((setup, index) => {
    const x = (scene.width * (index + 1)) / (setups.length + 1);
    const body = spawnParticle(scene, { x, y: scene.height / 2 }, () => 0.5);
    setParticleMass(body, setup.mass);
    body.linearVelocity = { x: setup.vx, y: setup.vy ?? 0 };
    bodies.push(body);
  });
  return bodies;
}

/**
 * The scene around a world restored from a snapshot of this scene's world (`restoreSnapshot`):
 * the bodies keep their index, so `labels[i]` (the label of the particle that was at index i,
 * or null for a wall) names them again.
 */
export function adoptWorld(
  scene: ReactionsScene,
  world: World,
  labels: readonly (string | null)[],
  added: number,
): ReactionsScene {
  const particles = new Map<Body, ParticleInfo>();
  world.bodies.forEach((body, index) => {
    const label = labels[index];
    if (label !== null && label !== undefined) {
      particles.set(body, { label, color: particleColor(label), lastImpulse: null });
    }
  });
  return { ...scene, world, particles, added };
}

/** The label of each body of the scene's world by index (null for walls). */
export function labelsByIndex(scene: ReactionsScene): (string | null)[] {
  return scene.world.bodies.map((body) => scene.particles.get(body)?.label ?? null);
}
