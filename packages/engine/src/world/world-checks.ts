import { PhysicalError } from '../core/errors.ts';
import {
  MAX_ACCELERATION,
  MAX_TIME_STEP,
  MIN_TIME_STEP,
  requireBoolean,
  requireCoordinate,
  requireObject,
  requireRange,
  requireVector,
} from '../core/validate.ts';
import type { Vec2Like } from '../math/vec2.ts';
import {
  requireRestitutionThreshold,
  resolveKernel,
  resolveWorldOptions,
  validateSubSteps,
  type WorldOptions,
} from './world-options.ts';

// The rules `World` applies to its own inputs (options, dt, settings, query arguments), written
// once here: `World` calls them, and so does a page that drives a world living elsewhere (a worker
// world), which must refuse bad input with the same PhysicalError without shipping `World`'s
// solver, broad phase and contacts.

/** A world setting a page may change after construction. */
export type WorldSettingName = keyof WorldSettingValues;

/** The settings a world's page side can read and change, as a `World` holds them. */
export interface WorldSettingValues {
  gravity: { x: number; y: number };
  subSteps: number;
  restitutionThreshold: number;
  enableSleep: boolean;
}

/**
 * Checks world options as `new World(options)` does (the same {@link PhysicalError}, naming the
 * option), without building a world; returns the settings such a world starts with.
 */
export function checkWorldOptions(options: WorldOptions = {}): WorldSettingValues {
  const resolved = resolveWorldOptions(options);
  resolveKernel(options);
  return {
    gravity: { x: resolved.gravityX, y: resolved.gravityY },
    subSteps: resolved.subSteps,
    restitutionThreshold: resolved.restitutionThreshold,
    enableSleep: resolved.enableSleep,
  };
}

/**
 * Checks a step's `dt` (s) as `World.step(dt)` does: 0 (no step) or from the smallest to the
 * largest step the solver takes.
 */
export function checkTimeStep(dt: number): void {
  requireRange('dt', dt, 0, MAX_TIME_STEP, 's');
  if (dt !== 0 && dt < MIN_TIME_STEP) {
    throw new PhysicalError(
      'dt',
      `must be 0 or from ${MIN_TIME_STEP} to ${MAX_TIME_STEP} s, got ${dt}.`,
    );
  }
}

/**
 * Checks a value for a world setting as `world[name] = value` does, and returns the value the
 * world holds (gravity as a plain `{ x, y }`, read once).
 */
export function checkWorldSetting(name: WorldSettingName, value: unknown): unknown {
  switch (name) {
    case 'gravity': {
      const gravity = value as Vec2Like;
      requireVector('gravity', gravity, MAX_ACCELERATION);
      return { x: gravity.x, y: gravity.y };
    }
    case 'subSteps':
      return validateSubSteps(value as number);
    case 'restitutionThreshold':
      return requireRestitutionThreshold(value as number);
    case 'enableSleep':
      return requireBoolean('enableSleep', value);
    default:
      throw new PhysicalError(
        'name',
        `must be gravity, subSteps, restitutionThreshold or enableSleep, got ${String(name)}.`,
      );
  }
}

/** Checks a ray's ends (m) as `World.rayCast` and `rayCastAll` do. */
export function checkRay(from: Vec2Like, to: Vec2Like): void {
  requireVector('from', from);
  requireVector('to', to);
}

/** Checks a query box (m) as `World.bodiesInAABB` does. */
export function checkQueryBox(box: {
  readonly minX: number;
  readonly minY: number;
  readonly maxX: number;
  readonly maxY: number;
}): void {
  requireObject('box', box, 'a box { minX, minY, maxX, maxY } in metres');
  requireCoordinate('box.minX', box.minX);
  requireCoordinate('box.minY', box.minY);
  requireCoordinate('box.maxX', box.maxX);
  requireCoordinate('box.maxY', box.maxY);
}
