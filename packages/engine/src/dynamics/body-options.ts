import { PhysicalError } from '../core/errors.ts';
import {
  MAX_ANGULAR_SPEED,
  MAX_DAMPING,
  MAX_GRAVITY_SCALE,
  MAX_INERTIA,
  MAX_MASS,
  MIN_INERTIA,
  MIN_MASS,
  requireNonNegative,
  requireRange,
} from '../core/validate.ts';
import type { Vec2Like } from '../math/vec2.ts';
import type { BodyEvents } from './events.ts';
import type { ShapeOptions } from './shape.ts';

// What a body is built from, and the checks its options and setters share: each names the
// user's option in its PhysicalError (core/validate.ts).

/**
 * - `'dynamic'`: moved by forces and collisions; needs a positive mass.
 * - `'static'`: never moves (walls, the ground); infinite mass.
 * - `'kinematic'`: moves only by the velocity you give it; pushes dynamic bodies, is not pushed.
 */
export type BodyType = 'dynamic' | 'static' | 'kinematic';

/** Describes a body. Every field is optional; units are SI (m, kg, s, rad). */
export interface BodyOptions<UserData = unknown> {
  /** Default `'dynamic'`. */
  readonly type?: BodyType;
  /** Position of the body origin in world coordinates (m). Default (0, 0). */
  readonly position?: Vec2Like;
  /** Rotation (rad). Positive turns +x towards +y: clockwise on a y-down screen. Default 0. */
  readonly angle?: number;
  /** Velocity of the centre of mass (m/s). Default (0, 0). */
  readonly linearVelocity?: Vec2Like;
  /** Angular velocity (rad/s). Default 0. */
  readonly angularVelocity?: number;
  /** The body's shapes; several make a compound body. */
  readonly shapes?: readonly ShapeOptions[];
  /**
   * Overrides the mass computed from the shapes' density (kg, > 0). The centre of mass stays
   * where the shapes put it; the moment of inertia scales with the mass unless also given.
   */
  readonly mass?: number;
  /** Overrides the moment of inertia about the centre of mass (kg m^2, > 0). */
  readonly inertia?: number;
  /** Multiplies the world's gravity for this body. Default 1; 0 makes it float. */
  readonly gravityScale?: number;
  /** Linear damping (1/s): dv/dt = -c v. Default 0. Use it for "slows down by itself", not for air. */
  readonly linearDamping?: number;
  /** Angular damping (1/s). Default 0. */
  readonly angularDamping?: number;
  /**
   * The thesis's drag: a force against the motion, F = -drag * |v| * v (N s^2/m^2), as air exerts
   * on a moving object. Default 0.
   */
  readonly drag?: number;
  /** Prevents rotation (infinite moment of inertia). Default false. */
  readonly fixedRotation?: boolean;
  /**
   * A bullet: continuous collision also against moving (dynamic and kinematic) bodies, not only
   * static ones, so a fast projectile cannot pass through a thin moving body. Costs a sweep test
   * per step while fast. Default false.
   */
  readonly bullet?: boolean;
  /** Lets the body fall asleep when it comes to rest. Default true. */
  readonly allowSleep?: boolean;
  /** Starts asleep (it wakes on contact, force or any change). Default false. */
  readonly asleep?: boolean;
  /** The thesis's `onMove`: called after each step in which the body moved. */
  readonly onMove?: BodyEvents['move'];
  /** The thesis's `onCollision`: called after each step in which the body was in a collision. */
  readonly onCollision?: BodyEvents['collision'];
  /** Anything the app wants to keep with the body (a colour, a game object). */
  readonly userData?: UserData;
}

/** @internal The body types, in the order a message lists them. */
export const BODY_TYPES: readonly BodyType[] = ['dynamic', 'static', 'kinematic'];

/** @internal */
export function requireMass(value: number): number {
  return requireRange('mass', value, MIN_MASS, MAX_MASS, 'kg');
}

/** @internal */
export function requireInertia(value: number): number {
  return requireRange('inertia', value, MIN_INERTIA, MAX_INERTIA, 'kg m^2');
}

/** @internal */
export function requireAngularSpeed(value: number): number {
  return requireRange('angularVelocity', value, -MAX_ANGULAR_SPEED, MAX_ANGULAR_SPEED, 'rad/s');
}

/** @internal */
export function requireGravityScale(value: number): number {
  return requireRange('gravityScale', value, -MAX_GRAVITY_SCALE, MAX_GRAVITY_SCALE);
}

/** @internal */
export function requireDamping(field: string, value: number): number {
  return requireNonNegative(field, value, MAX_DAMPING);
}

/** @internal Refuses `what` (an option or method name) on a body that is not dynamic. */
export function requireDynamic(type: BodyType, what: string): void {
  if (type !== 'dynamic') {
    throw new PhysicalError(
      what,
      `acts only on dynamic bodies; this body is ${type}. A static body never moves; move a kinematic body by setting its velocity.`,
    );
  }
}
