import { cosSin } from '../math/trigonometry.ts';
import type { Transform } from '../math/transform.ts';
import { B_C, B_S, B_X, B_Y, type BodyStore } from './body-memory.ts';

// Where cosSin writes: a typed array, so no number is boxed.
const rotation = new Float64Array(2);

/**
 * A body's transform as a view of its numbers in the body memory (body-memory.ts): x, y, c, s at
 * the body's stride, so the narrow phase, the handles and every query read the one copy. It
 * takes the place of a `Transform` wherever one is read (the same fields and methods, with the
 * same arithmetic as math/transform.ts, operation for operation, so every result is
 * bit-identical).
 */
export class BodyTransform {
  constructor(
    /** @internal The store holding the body's numbers. */
    public store: BodyStore,
    /** @internal The body's first index in `store.data`. */
    public base: number,
  ) {}

  get x(): number {
    return this.store.data[this.base + B_X]!;
  }
  set x(value: number) {
    this.store.data[this.base + B_X] = value;
  }
  get y(): number {
    return this.store.data[this.base + B_Y]!;
  }
  set y(value: number) {
    this.store.data[this.base + B_Y] = value;
  }
  get c(): number {
    return this.store.data[this.base + B_C]!;
  }
  set c(value: number) {
    this.store.data[this.base + B_C] = value;
  }
  get s(): number {
    return this.store.data[this.base + B_S]!;
  }
  set s(value: number) {
    this.store.data[this.base + B_S] = value;
  }

  /** As Transform.set. */
  set(x: number, y: number, angle: number): this {
    const d = this.store.data;
    const b = this.base;
    d[b + B_X] = x;
    d[b + B_Y] = y;
    cosSin(angle, rotation);
    d[b + B_C] = rotation[0]!;
    d[b + B_S] = rotation[1]!;
    return this;
  }

  /** As Transform.setFromCenter: the body-local point (localX, localY) lands on (centerX, centerY). */
  setFromCenter(
    centerX: number,
    centerY: number,
    angle: number,
    localX: number,
    localY: number,
  ): this {
    cosSin(angle, rotation);
    const c = rotation[0]!;
    const s = rotation[1]!;
    const d = this.store.data;
    const b = this.base;
    d[b + B_C] = c;
    d[b + B_S] = s;
    d[b + B_X] = centerX - (c * localX - s * localY);
    d[b + B_Y] = centerY - (s * localX + c * localY);
    return this;
  }

  copy(other: Transform | BodyTransform): this {
    const d = this.store.data;
    const b = this.base;
    d[b + B_X] = other.x;
    d[b + B_Y] = other.y;
    d[b + B_C] = other.c;
    d[b + B_S] = other.s;
    return this;
  }
}
