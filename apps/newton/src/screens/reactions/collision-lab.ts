import type { Body, CollisionEvent } from '@physical/engine';

/** A particle's state at one moment, copied (bodies change). */
export interface ParticleState {
  readonly label: string;
  /** kg */
  readonly mass: number;
  /** Position (m) and velocity (m/s), x right and y down the screen. */
  readonly x: number;
  readonly y: number;
  readonly vx: number;
  readonly vy: number;
}

/** Copies a body's state under its label. */
export function stateOf(body: Body, label: string): ParticleState {
  const { x, y } = body.position;
  const v = body.linearVelocity;
  return { label, mass: body.mass, x, y, vx: v.x, vy: v.y };
}

/** Momentum m v (kg m/s). */
export function momentumOf(state: ParticleState): { x: number; y: number } {
  return { x: state.mass * state.vx, y: state.mass * state.vy };
}

/** Kinetic energy m v^2 / 2 (J) of the motion of the centre (the lab's discs do not spin). */
export function kineticEnergyOf(state: ParticleState): number {
  return 0.5 * state.mass * (state.vx * state.vx + state.vy * state.vy);
}

/** Total momentum (kg m/s) of some particles: the vector sum. */
export function totalMomentumOf(states: readonly ParticleState[]): { x: number; y: number } {
  let x = 0;
  let y = 0;
  for (const state of states) {
    x += state.mass * state.vx;
    y += state.mass * state.vy;
  }
  return { x, y };
}

/** Total kinetic energy (J). */
export function totalKineticEnergyOf(states: readonly ParticleState[]): number {
  let sum = 0;
  for (const state of states) sum += kineticEnergyOf(state);
  return sum;
}

/** The two particles just before and just after their collision. */
export interface CollisionRecord {
  /** Simulated time (s) the collision began. */
  readonly time: number;
  readonly before: readonly ParticleState[];
  readonly after: readonly ParticleState[];
}

/** Impulses below this (N s) are no collision (resting contact noise). */
const TOUCH_IMPULSE = 1e-9;

/**
 * The collision lab's before and after: the states of the two chosen particles at the end of
 * the step before they first touched, and at the end of the last step they pushed on each other
 * (a perfectly inelastic pair stays in contact: "after" is once their push has stopped). Only
 * the pair's own impulses count: walls and the tilt act before or after, never inside the
 * record, so its totals show what the collision alone did. Call {@link beforeStep} and
 * {@link afterStep} around every step and {@link collided} from the world's collision events.
 */
export class CollisionRecorder {
  /** The newest collision of the pair, or null before the first. */
  record: CollisionRecord | null = null;
  private pair: readonly [Body, Body, string, string] | null = null;
  private previous: ParticleState[] | null = null;
  private touched = false;
  private touching = false;

  /** Chooses the pair (or none) and forgets the last record. */
  setPair(pair: readonly [Body, Body, string, string] | null): void {
    this.pair = pair;
    this.record = null;
    this.previous = null;
    this.touched = false;
    this.touching = false;
  }

  private states(): ParticleState[] | null {
    const pair = this.pair;
    return pair === null ? null : [stateOf(pair[0], pair[2]), stateOf(pair[1], pair[3])];
  }

  beforeStep(): void {
    this.previous = this.states();
    this.touched = false;
  }

  /** A collision event of the world: marks the step if it is the pair's. */
  collided(event: CollisionEvent): void {
    const pair = this.pair;
    if (pair === null || event.normalImpulse <= TOUCH_IMPULSE) return;
    const { bodyA, bodyB } = event;
    if ((bodyA === pair[0] && bodyB === pair[1]) || (bodyA === pair[1] && bodyB === pair[0])) {
      this.touched = true;
    }
  }

  /** After the step at `time` (s, its start): returns true when the record changed. */
  afterStep(time: number): boolean {
    if (!this.touched) {
      this.touching = false;
      return false;
    }
    const after = this.states()!;
    if (!this.touching || this.record === null) {
      this.record = { time, before: this.previous ?? after, after };
    } else {
      this.record = { ...this.record, after };
    }
    this.touching = true;
    this.touched = false;
    return true;
  }
}
