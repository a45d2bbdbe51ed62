import { PhysicalError, readOnly } from '../core/errors.ts';
import {
  describeValue,
  MAX_DURATION,
  MAX_FORCE,
  requireRange,
  requireVector,
} from '../core/validate.ts';
import type { Vec2Like } from '../math/vec2.ts';

/**
 * How long a force or torque acts, as in the thesis:
 * - `'constant'`: every step until it is removed ({@link Force.remove});
 * - `'instant'`: during the next step only (one frame);
 * - a number: for that many seconds of simulated time, then it removes itself. The total impulse is
 *   exactly `F * seconds` even when the duration is not a whole number of steps: the last step
 *   applies the remaining fraction.
 */
export type Duration = 'constant' | 'instant' | number;

/** Options of {@link Body.applyForce}. */
export interface ForceOptions {
  /** How long the force acts. Default `'instant'` (one step), like `applyForce` in Box2D or matter.js. */
  readonly duration?: Duration;
  /**
   * Point of application in world coordinates (m) at the time of the call. The point is attached to
   * the body (it moves and turns with it); the force's direction stays fixed in the world.
   * Default: the centre of mass, so the force makes no torque.
   */
  readonly point?: Vec2Like;
}

/** Options of {@link Body.applyTorque}. */
export interface TorqueOptions {
  /** How long the torque acts. Default `'instant'`. */
  readonly duration?: Duration;
}

// Tolerance for "the duration is used up": 30 steps of 1/60 s leave about 1e-16 s of a 0.5 s force,
// which must not become a 31st step.
const DURATION_EPSILON = 1e-9;

/**
 * A force (N) and/or torque (N m) acting on a body for a {@link Duration}. Created by
 * {@link Body.applyForce} and {@link Body.applyTorque}; keep it to change or remove it later.
 */
export class Force {
  /** @internal Force in world coordinates (N), behind {@link x} and {@link y}. */
  xValue = -0;
  /** @internal */
  yValue = -0;
  /** @internal Torque (N m), behind {@link torque}. */
  torqueValue = -0;
  /**
   * @internal Point of application in body-local coordinates (m); used only when `hasPoint`
   * (else the centre of mass).
   */
  localPointX = -0;
  /** @internal */
  localPointY = -0;
  /** @internal */
  hasPoint = false;
  /** @internal Behind {@link duration}. */
  durationValue: Duration;
  /** The duration it was created with. */
  get duration(): Duration {
    return this.durationValue;
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set duration(_value: never) {
    readOnly('duration', 'a force keeps the duration it was applied with');
  }
  /** @internal Seconds left, behind {@link remaining}; -1 for an `'instant'` force not yet applied. */
  remainingValue = -0;
  /** @internal Removal hook set by the owning body. */
  onRemove: ((force: Force) => void) | null = null;
  /** @internal Change hook set by the owning body (wakes it). */
  onChange: ((force: Force) => void) | null = null;

  /** Usually made by {@link Body.applyForce} or {@link Body.applyTorque}; a Force on no body does nothing. */
  constructor(x: number, y: number, torque: number, duration: Duration) {
    this.xValue = requireRange('x', x, -MAX_FORCE, MAX_FORCE, 'N');
    this.yValue = requireRange('y', y, -MAX_FORCE, MAX_FORCE, 'N');
    this.torqueValue = requireRange('torque', torque, -MAX_FORCE, MAX_FORCE, 'N m');
    this.durationValue = validateDuration(duration);
    this.remainingValue =
      duration === 'constant' ? Infinity : duration === 'instant' ? -1 : duration;
  }

  /** The force's x component in world coordinates (N). Setting it wakes the body. */
  get x(): number {
    return this.xValue;
  }

  set x(value: number) {
    this.xValue = requireRange('x', value, -MAX_FORCE, MAX_FORCE, 'N');
    this.onChange?.(this);
  }

  /** The force's y component in world coordinates (N). Setting it wakes the body. */
  get y(): number {
    return this.yValue;
  }

  set y(value: number) {
    this.yValue = requireRange('y', value, -MAX_FORCE, MAX_FORCE, 'N');
    this.onChange?.(this);
  }

  /** Torque (N m), positive turns +x towards +y (clockwise on a y-down screen). Setting it wakes the body. */
  get torque(): number {
    return this.torqueValue;
  }

  set torque(value: number) {
    this.torqueValue = requireRange('torque', value, -MAX_FORCE, MAX_FORCE, 'N m');
    this.onChange?.(this);
  }

  /**
   * Seconds left for a timed force; Infinity for `'constant'`; -1 for an `'instant'` force not yet
   * applied, 0 once used up. Setting it (seconds, from 0 to 1e9, or Infinity) extends or shortens
   * the force; 0 ends it at the next step.
   */
  get remaining(): number {
    return this.remainingValue;
  }

  set remaining(value: number) {
    if (value !== Infinity) requireRange('remaining', value, 0, MAX_DURATION, 's');
    this.remainingValue = value;
    this.onChange?.(this);
  }

  /** Changes the force vector (N, world). Wakes the body. */
  setVector(force: Vec2Like): void {
    requireVector('force', force, MAX_FORCE);
    this.xValue = force.x;
    this.yValue = force.y;
    this.onChange?.(this);
  }

  /** Changes the torque (N m). Wakes the body. */
  setTorque(torque: number): void {
    this.torque = torque;
  }

  /** Stops the force now. Removing a force twice is harmless. */
  remove(): void {
    this.onRemove?.(this);
  }

  /**
   * @internal Fraction of this step during which the force acts (0..1), and consumes that time.
   * Returns 0 once the force is used up.
   */
  consume(dt: number): number {
    if (this.remainingValue === Infinity) return 1;
    if (this.remainingValue < 0) {
      // 'instant': exactly one step.
      this.remainingValue = 0;
      return 1;
    }
    if (this.remainingValue <= DURATION_EPSILON) return 0;
    const fraction = this.remainingValue >= dt ? 1 : this.remainingValue / dt;
    this.remainingValue -= dt;
    if (this.remainingValue < DURATION_EPSILON) this.remainingValue = 0;
    return fraction;
  }

  /** True when the force has acted for its whole duration. */
  get isExpired(): boolean {
    return this.remainingValue === 0;
  }
}

export function validateDuration(duration: Duration): Duration {
  if (duration === 'constant' || duration === 'instant') return duration;
  if (typeof duration !== 'number') {
    throw new PhysicalError(
      'duration',
      `must be 'constant', 'instant' or a number of seconds, got ${describeValue(duration)}.`,
    );
  }
  requireRange('duration', duration, 0, MAX_DURATION, 's');
  if (duration === 0) throw new PhysicalError('duration', 'must be greater than zero, got 0.');
  return duration;
}
