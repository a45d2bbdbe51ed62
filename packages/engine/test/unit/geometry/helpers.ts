// Helpers shared by the geometry tests.
import { PhysicalError } from '../../../src/core/errors.ts';
import { RayInput } from '../../../src/geometry/ray.ts';

/** Runs an action that must throw a PhysicalError, and returns it. */
export function catchError(action: () => unknown): PhysicalError {
  try {
    action();
  } catch (error) {
    if (error instanceof PhysicalError) return error;
    throw error;
  }
  throw new Error('expected a PhysicalError');
}

/** A ray from (ox, oy) along (tx, ty), clipped at maxFraction. */
export function ray(ox: number, oy: number, tx: number, ty: number, maxFraction = 1): RayInput {
  const input = new RayInput();
  input.originX = ox;
  input.originY = oy;
  input.translationX = tx;
  input.translationY = ty;
  input.maxFraction = maxFraction;
  return input;
}
