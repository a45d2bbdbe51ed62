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
export const MIN_FORCE = 0;
export const MAX_FORCE = 10;

/**
 * What the learner sets for one square: its mass and the force on it, the cause; the
 * acceleration is the effect, measured from the motion.
 */
export interface SquareSettings {
  /** kg */
  readonly mass: number;
  /** N */
  readonly force: number;
}

/** One of the Forces screen's two tracks: a world with a square at the left end. */
export interface ForcesTrack {
  readonly world: World;
  readonly square: Body;
  readonly settings: SquareSettings;
  /** The force pushing the square while the run lasts (N). */
  readonly force: number;
  /** Simulated time (s) the square reached the stop at the end, or null while it has not. */
  finishedAt: number | null;
  /**
   * The acceleration measured over the last step, Δv / Δt (m/s^2), or null before the first
   * step; kept from the last step before the stop once the run is over.
   */
  acceleration: number | null;
  /** The square's velocity (m/s) at the end of the last step, for the next Δv. */
  lastVelocity: number;
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

/** Newton's second law: the acceleration (m/s^2) a force (N) gives a mass (kg), a = F / m. */
export function accelerationFor(force: number, mass: number): number {
  return force / mass;
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
  return trackOf(world, settings, { finishedAt: null, acceleration: null, lastVelocity: 0 });
}

/** What a track keeps beside its world: saved with each moment to step back to. */
export type TrackState = Pick<ForcesTrack, 'finishedAt' | 'acceleration' | 'lastVelocity'>;

/** The state of a track to save beside a snapshot of its world. */
export function trackState(track: ForcesTrack): TrackState {
  const { finishedAt, acceleration, lastVelocity } = track;
  return { finishedAt, acceleration, lastVelocity };
}

/**
 * The track around a world built by {@link createForcesTrack}, or restored from a snapshot of
 * one (new objects, in the same order: the stop first, then the square).
 */
function trackOf(world: World, settings: SquareSettings, state: TrackState): ForcesTrack {
  const square = world.bodies[1]!;
  const track: ForcesTrack = { world, square, settings, force: settings.force, ...state };
  // The acceleration as the velocity's change over each step. Not 2 x / t^2 from the ruler: the
  // integrator (semi-implicit Euler in 4 sub-steps of h = 1/240 s) moves the square
  // x = a t^2 / 2 + a h t / 2, so 2 x / t^2 = a (1 + h / t) read 2.13 m/s^2 for 2 at t = 4/60 s;
  // its velocity gains exactly a h each sub-step, so Δv / Δt is a from the first step on.
  // Listeners run after contactBegin: the step that meets the stop is not measured.
  world.on('move', (body) => {
    if (body !== square || track.finishedAt !== null) return;
    const velocity = square.linearVelocity.x;
    const dt = world.lastStepDuration;
    if (dt > 0) track.acceleration = (velocity - track.lastVelocity) / dt;
    track.lastVelocity = velocity;
  });
  return track;
}

/**
 * The track again around `world`, a restored snapshot of `track`'s world with the state saved
 * beside it (stepping back). A run still going on goes on: its force (the square's only one)
 * ends at the stop as {@link startTrack}'s does, and `onFinish` hears of it.
 */
export function adoptTrack(
  track: ForcesTrack,
  world: World,
  state: TrackState,
  onFinish: () => void = () => undefined,
): ForcesTrack {
  const next = trackOf(world, track.settings, state);
  const force = next.square.forces[0];
  if (force !== undefined && next.finishedAt === null) endAtStop(next, force, onFinish);
  return next;
}

/**
 * Applies the learner's constant force F to the square, to the right, until the square reaches the
 * stop at the end: there the run ends (the force is removed and the square rests against the
 * stop), so no force acts that the screen does not show. `onFinish` hears of it.
 */
export function startTrack(track: ForcesTrack, onFinish: () => void = () => undefined): Force {
  const force = track.square.applyForce({ x: track.force, y: 0 }, { duration: 'constant' });
  endAtStop(track, force, onFinish);
  return force;
}

/** Ends the run when the square meets the stop: the force removed, the square at rest. */
function endAtStop(track: ForcesTrack, force: Force, onFinish: () => void): void {
  const stop = track.world.on('contactBegin', (event) => {
    if (event.bodyA !== track.square && event.bodyB !== track.square) return;
    stop();
    force.remove();
    track.finishedAt = track.world.steps / 60;
    track.square.linearVelocity = { x: 0, y: 0 };
    track.square.sleep();
    onFinish();
  });
}

/** The acceleration measured from the motion (m/s^2), Δv / Δt over the last step; null at rest. */
export function measuredAcceleration(track: ForcesTrack): number | null {
  return track.acceleration;
}

/** The square's displacement from its start (m), as the ruler shows it. */
export function displacement(track: ForcesTrack): number {
  return track.square.position.x - START_X;
}
