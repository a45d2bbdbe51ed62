import { PhysicalError } from '../core/errors.ts';
import {
  describeValue,
  MAX_ACCELERATION,
  MAX_DAMPING_RATIO,
  MAX_DURATION,
  MAX_HERTZ,
  MAX_SPEED,
  optionalBoolean,
  optionalObject,
  requireFinite,
  requireNonNegative,
  requirePositive,
  requireVector,
} from '../core/validate.ts';
import type { Vec2Like } from '../math/vec2.ts';

/** Options of a {@link World}. Every field is optional; units are SI. */
export interface WorldOptions {
  /**
   * Gravity (m/s^2). The world is y-down like the screen, so the default (0, 9.81) pulls down the
   * screen. Any vector works, including zero (space, or a top-down table).
   */
  readonly gravity?: Vec2Like;
  /**
   * Sub-steps per step, 1..64 (default 4). More sub-steps make stiff stacks and fast, heavy
   * contacts more accurate at proportional cost.
   */
  readonly subSteps?: number;
  /**
   * Below this approach speed (m/s) collisions do not bounce (default 0.05 m/s, the speed under
   * which a body counts as resting). A contact already pushing never bounces whatever the speed,
   * so this only has to cover the first touch of a resting body, whose approach is what gravity
   * adds in one sub-step (0.04 m/s at 60 Hz and 4 sub-steps): with 0, stacks of bouncy boxes
   * jitter apart. e = 1 is elastic at any faster speed (an elastic gas keeps its energy within
   * 1e-5 over a minute). Set 0 for restitution at every speed (bodies without gravity).
   */
  readonly restitutionThreshold?: number;
  /** Stiffness of the soft contact (Hz, default 30). Rarely needs changing. */
  readonly contactHertz?: number;
  /** Damping ratio of the soft contact (default 10: strongly damped, so no bounce from overlap). */
  readonly contactDampingRatio?: number;
  /** Fastest speed (m/s) at which overlapping shapes are pushed apart (default 3). */
  readonly maxContactPushSpeed?: number;
  /** Speed limit for any body (m/s, default 400): keeps a runaway body finite. */
  readonly maxLinearSpeed?: number;
  /** Lets resting bodies sleep (default true). Sleeping bodies cost nothing until woken. */
  readonly enableSleep?: boolean;
  /** Seconds a body must rest before it sleeps (default 0.5). */
  readonly timeToSleep?: number;
  /** Continuous collision of fast bodies against static shapes (default true). */
  readonly enableContinuous?: boolean;
  /**
   * Which build of the contact passes runs (default `'auto'`). Both builds come from one source
   * and give bit-identical results; only speed and what the page must allow differ.
   *
   * - `'auto'`: WebAssembly from the first step, compiled at run time from bytes shipped inside
   *   the engine. A Content-Security-Policy must allow `'wasm-unsafe-eval'` in `script-src` for
   *   it; without it the browser refuses (and reports a `securitypolicyviolation`). Where
   *   WebAssembly cannot compile, the JavaScript build runs if the page imported
   *   `@physical/engine/javascript-kernel`; if not, `new World()` throws a `PhysicalError` on
   *   `kernel` naming that import.
   * - `'javascript'`: the JavaScript build only, with no attempt at WebAssembly, so a page
   *   under a strict policy (`script-src 'self'`) reports no violation. Needs
   *   `import '@physical/engine/javascript-kernel'` first (else a `PhysicalError` says so).
   *   Large scenes step slower (see the guide "WebAssembly and Content-Security-Policy").
   */
  readonly kernel?: 'auto' | 'javascript';
}

/**
 * @internal Default restitution threshold (m/s): the sleep speed (core/constants.ts SLEEP_SPEED). Box2D's
 * 1 m/s took two thirds of an elastic gas's energy in a minute; 0 lets a pyramid of e = 0.5 boxes
 * bounce itself apart (the first touch of each resting box bounces off gravity's approach).
 */
export const DEFAULT_RESTITUTION_THRESHOLD = 0.05;

/** @internal Validated options with defaults. */
export interface ResolvedWorldOptions {
  gravityX: number;
  gravityY: number;
  subSteps: number;
  restitutionThreshold: number;
  contactHertz: number;
  contactDampingRatio: number;
  maxContactPushSpeed: number;
  maxLinearSpeed: number;
  enableSleep: boolean;
  timeToSleep: number;
  enableContinuous: boolean;
}

/** @internal */
export function resolveWorldOptions(options: WorldOptions): ResolvedWorldOptions {
  optionalObject('options', options, 'an object of world options');
  const gravity = options.gravity ?? { x: 0, y: 9.81 };
  requireVector('gravity', gravity, MAX_ACCELERATION);
  const resolved: ResolvedWorldOptions = {
    gravityX: gravity.x,
    gravityY: gravity.y,
    subSteps: validateSubSteps(options.subSteps ?? 4),
    restitutionThreshold: requireNonNegative(
      'restitutionThreshold',
      options.restitutionThreshold ?? DEFAULT_RESTITUTION_THRESHOLD,
    ),
    contactHertz: requirePositive('contactHertz', options.contactHertz ?? 30, MAX_HERTZ),
    contactDampingRatio: requireNonNegative(
      'contactDampingRatio',
      options.contactDampingRatio ?? 10,
      MAX_DAMPING_RATIO,
    ),
    maxContactPushSpeed: requirePositive(
      'maxContactPushSpeed',
      options.maxContactPushSpeed ?? 3,
      MAX_SPEED,
    ),
    maxLinearSpeed: requirePositive('maxLinearSpeed', options.maxLinearSpeed ?? 400, MAX_SPEED),
    enableSleep: optionalBoolean('enableSleep', options.enableSleep, true),
    timeToSleep: requireNonNegative('timeToSleep', options.timeToSleep ?? 0.5, MAX_DURATION),
    enableContinuous: optionalBoolean('enableContinuous', options.enableContinuous, true),
  };
  requireRestitutionThreshold(resolved.restitutionThreshold);
  return resolved;
}

/** @internal The `kernel` option, validated (default `'auto'`). */
export function resolveKernel(options: WorldOptions): 'auto' | 'javascript' {
  const value: unknown = options.kernel;
  if (value === undefined || value === 'auto' || value === 'javascript') return value ?? 'auto';
  throw new PhysicalError('kernel', `must be 'auto' or 'javascript', got ${describeValue(value)}.`);
}

/** @internal The approach speed below which contacts do not bounce (m/s), 0 to MAX_SPEED. */
export function requireRestitutionThreshold(value: number): number {
  return requireNonNegative('restitutionThreshold', value, MAX_SPEED);
}

/** @internal */
export function validateSubSteps(value: number): number {
  requireFinite('subSteps', value);
  if (!Number.isInteger(value) || value < 1 || value > 64) {
    throw new PhysicalError('subSteps', `must be a whole number from 1 to 64, got ${value}.`);
  }
  return value;
}
