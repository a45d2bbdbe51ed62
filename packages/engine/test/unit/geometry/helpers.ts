// Helpers shared by the geometry tests.
import { expect } from 'vitest';
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

/** Points from a flat list of coordinates: x0, y0, x1, y1, ... */
export function points(...coordinates: number[]): { x: number; y: number }[] {
  const list: { x: number; y: number }[] = [];
  for (let i = 0; i < coordinates.length; i += 2) {
    list.push({ x: coordinates[i]!, y: coordinates[i + 1]! });
  }
  return list;
}

/** `actual` within a relative `tolerance` of `expected`. */
export function expectRelative(actual: number, expected: number, tolerance = 1e-12): void {
  expect(Math.abs(actual - expected) / Math.abs(expected)).toBeLessThan(tolerance);
}
