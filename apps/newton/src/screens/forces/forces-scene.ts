import { type Body, type Force, World, box, wall } from '@physical/engine';

/** Track length (m): the ruler runs from 0 at the square's start. */
export const TRACK_LENGTH = 12;
export const TRACK_HEIGHT = 2;
/** Side of the square (m). */
export const SQUARE_SIZE = 1;
/** Where the square's centre starts (m from the track's left end). */
export const START_X = 0.7;
export const MIN_MASS = 0.5;
export const MAX_MASS = 5;
export const MIN_ACCELERATION = 0;
export const MAX_ACCELERATION = 5;

/** What the learner sets for one square. */
export interface SquareSettings {
  /** kg */
  readonly mass: number;
  /** m/s^2 */
  readonly acceleration: number;
}

/** One of the Forces screen's two tracks: a world with a square at the left end. */
export interface ForcesTrack {
  readonly world: World;
  readonly square: Body;
  readonly settings: SquareSettings;
  /** The force that gives the square the desired acceleration: F = m a (N). */
  readonly force: number;
  /** Simulated time (s) the square reached the stop at the end, or null while it has not. */
  finishedAt: number | null;
  /** The acceleration measured over the whole run (2 x / t^2 at the stop), once finished. */
  finalAcceleration: number | null;
}

/** The range a mystery mass is drawn from (kg), in tenths: inside the range a learner can type. */
export const MYSTERY_MIN = 1;
export const MYSTERY_MAX = 4;
/** A guess within this fraction of the mystery mass is right (the ruler and clock are that good). */
export const MYSTERY_TOLERANCE = 0.05;

/** A mystery mass (kg): a random tenth of a kilogram between MYSTERY_MIN and MYSTERY_MAX. */
export function drawMysteryMass(random: () => number = Math.random): number {
  const tenths = Math.round(10 * MYSTERY_MIN + random() * 10 * (MYSTERY_MAX - MYSTERY_MIN));
  return Math.min(MYSTERY_MAX, Math.max(MYSTERY_MIN, tenths / 10));
}

/** Whether a guessed mass (kg) finds the mystery mass, within MYSTERY_TOLERANCE of it. */
export function isMysteryFound(guess: number, mass: number): boolean {
  return Math.abs(guess - mass) <= MYSTERY_TOLERANCE * mass;
}

/** Newton's second law solved for the force (N) from a mass (kg) and an acceleration (m/s^2). */
export function forceFor(mass: number, acceleration: number): number {
  return mass * acceleration;
}

/** The square's opacity: the heavier, the more opaque (0.25 at the lightest, 1 at the heaviest). */
export function opacityFor(mass: number): number {
  const t = (mass - MIN_MASS) / (MAX_MASS - MIN_MASS);
  return 0.25 + 0.75 * Math.min(1, Math.max(0, t));
}

/** Length (m) of the force arrow: it grows in proportion to the force. */
export function arrowLength(force: number): number {
  return 0.3 * force;
}

/** Builds a frictionless, gravity-free track with the square at rest at the left. */
export function createForcesTrack(settings: SquareSettings): ForcesTrack {
  const world = new World({ gravity: { x: 0, y: 0 }, enableSleep: false });
  // A stop at the right end so the square stays in view.
  world.add(
    wall({
      from: { x: TRACK_LENGTH, y: 0 },
      to: { x: TRACK_LENGTH, y: TRACK_HEIGHT },
      friction: 0,
      restitution: 0,
    }),
  );
  const square = world.add(
    box({
      position: { x: START_X, y: TRACK_HEIGHT / 2 },
      width: SQUARE_SIZE,
      height: SQUARE_SIZE,
      density: settings.mass / (SQUARE_SIZE * SQUARE_SIZE),
      friction: 0,
      restitution: 0,
      fixedRotation: true,
    }),
  );
  square.mass = settings.mass;
  return {
    world,
    square,
    settings,
    force: forceFor(settings.mass, settings.acceleration),
    finishedAt: null,
    finalAcceleration: null,
  };
}

/**
 * Applies the constant force F = m a to the square, to the right, until the square reaches the
 * stop at the end: there the run ends (the force is removed and the square rests against the
 * stop), so no force acts that the screen does not show. `onFinish` hears of it.
 */
export function startTrack(track: ForcesTrack, onFinish: () => void = () => undefined): Force {
  const force = track.square.applyForce({ x: track.force, y: 0 }, { duration: 'constant' });
  const stop = track.world.on('contactBegin', (event) => {
    if (event.bodyA !== track.square && event.bodyB !== track.square) return;
    stop();
    force.remove();
    track.finishedAt = track.world.steps / 60;
    track.finalAcceleration = (2 * displacement(track)) / track.finishedAt ** 2;
    track.square.linearVelocity = { x: 0, y: 0 };
    track.square.sleep();
    onFinish();
  });
  return force;
}

/**
 * The acceleration measured from the motion since the start, 2 x / t^2 (m/s^2), as a student
 * would from the ruler and the clock (from rest under a constant force); null at t = 0.
 */
export function measuredAcceleration(track: ForcesTrack, time: number): number | null {
  if (track.finishedAt !== null) return track.finalAcceleration;
  if (time <= 0) return null;
  return (2 * displacement(track)) / (time * time);
}

/** The square's displacement from its start (m), as the ruler shows it. */
export function displacement(track: ForcesTrack): number {
  return track.square.position.x - START_X;
}
