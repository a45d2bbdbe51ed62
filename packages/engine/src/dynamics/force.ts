import { PhysicalError } from '../core/errors.ts';
import { requireFinite, requirePositive, requireVector } from '../core/validate.ts';
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
  /** Force in world coordinates (N). */
  x = 0;
  y = 0;
  /** Torque (N m), positive turns +x towards +y (clockwise on a y-down screen). */
  torque = 0;
  /** Point of application in body-local coordinates (m); used only when `hasPoint` (else the centre of mass). */
  localPointX = 0;
  localPointY = 0;
  hasPoint = false;
  /** The duration it was created with. */
  readonly duration: Duration;
  /** Seconds left for a timed force; Infinity for `'constant'`; one step for `'instant'`. */
  remaining = 0;
  /** @internal Removal hook set by the owning body. */
  onRemove: ((force: Force) => void) | null = null;
  /** @internal Change hook set by the owning body (wakes it). */
  onChange: ((force: Force) => void) | null = null;

  constructor(x: number, y: number, torque: number, duration: Duration) {
    this.x = x;
    this.y = y;
    this.torque = torque;
    this.duration = duration;
    this.remaining = duration === 'constant' ? Infinity : duration === 'instant' ? -1 : duration;
  }

  /** Changes the force vector (N, world). Wakes the body. */
  setVector(force: Vec2Like): void {
    requireVector('force', force);
    this.x = force.x;
    this.y = force.y;
    this.onChange?.(this);
  }

  /** Changes the torque (N m). Wakes the body. */
  setTorque(torque: number): void {
    this.torque = requireFinite('torque', torque);
    this.onChange?.(this);
  }

  /** Stops the force now. Removing a force twice is harmless. */
  remove(): void {
    this.onRemove?.(this);
  }

  /**
   * Fraction of this step during which the force acts (0..1), and consumes that time.
   * Returns 0 once the force is used up.
   */
  consume(dt: number): number {
    if (this.remaining === Infinity) return 1;
    if (this.remaining < 0) {
      // 'instant': exactly one step.
      this.remaining = 0;
      return 1;
    }
    if (this.remaining <= DURATION_EPSILON) return 0;
    const fraction = this.remaining >= dt ? 1 : this.remaining / dt;
    this.remaining -= dt;
    if (this.remaining < DURATION_EPSILON) this.remaining = 0;
    return fraction;
  }

  /** True when the force has acted for its whole duration. */
  get isExpired(): boolean {
    return this.remaining === 0;
  }
}

export function validateDuration(duration: Duration): Duration {
  if (duration === 'constant' || duration === 'instant') return duration;
  if (typeof duration !== 'number') {
    throw new PhysicalError(
      'duration',
      `must be 'constant', 'instant' or a number of seconds, got ${String(duration)}.`,
    );
  }
  return requirePositive('duration', duration);
}
