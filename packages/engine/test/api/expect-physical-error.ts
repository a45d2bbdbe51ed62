import { expect } from 'vitest';
import { PhysicalError } from '@physical/engine';

/** Runs `action`, expects a PhysicalError (not a TypeError, not success) and returns it. */
export function physicalErrorOf(action: () => unknown): PhysicalError {
  let thrown: unknown = undefined;
  let threw = false;
  try {
    action();
  } catch (error) {
    thrown = error;
    threw = true;
  }
  expect(threw, 'expected the call to throw').toBe(true);
  expect(thrown).toBeInstanceOf(PhysicalError);
  return thrown as PhysicalError;
}
