/**
 * Thrown for invalid input to the engine. The message names the field, the value and what to do;
 * `field` holds the field's path (for example `"shapes[0].radius"`) so tools can point at it.
 */
export class PhysicalError extends Error {
  /** Path of the offending field, for example `"density"` or `"shapes[1].vertices"`. */
  readonly field: string;

  constructor(field: string, message: string) {
    super(`${field}: ${message}`);
    this.name = 'PhysicalError';
    this.field = field;
  }
}

/**
 * @internal The setter of a field that is read-only in the typings: plain JavaScript cannot
 * write it either (the world would then disagree with itself), it gets this error instead.
 */
export function readOnly(field: string, why: string): never {
  throw new PhysicalError(field, `is read-only: ${why}`);
}
