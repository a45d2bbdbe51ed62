import { PhysicalError } from './errors.ts';

// Validation at the entrance: every number a user hands the engine passes one of these,
// so a NaN or an infinity is reported where it came in instead of spreading through a step.

export function requireFinite(field: string, value: number): number {
  if (typeof value !== 'number' || !Number.isFinite(value)) {
    throw new PhysicalError(field, `must be a finite number, got ${String(value)}.`);
  }
  return value;
}

export function requirePositive(field: string, value: number): number {
  requireFinite(field, value);
  if (value <= 0) {
    throw new PhysicalError(field, `must be greater than zero, got ${value}.`);
  }
  return value;
}

export function requireNonNegative(field: string, value: number): number {
  requireFinite(field, value);
  if (value < 0) {
    throw new PhysicalError(field, `must be zero or more, got ${value}.`);
  }
  return value;
}

export function requireVector(
  field: string,
  value: { readonly x: number; readonly y: number },
): void {
  if (value === null || typeof value !== 'object') {
    throw new PhysicalError(field, `must be a vector { x, y } in metres, got ${String(value)}.`);
  }
  requireFinite(`${field}.x`, value.x);
  requireFinite(`${field}.y`, value.y);
}
