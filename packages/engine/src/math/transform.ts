import { cosSin } from './trigonometry.ts';

// Where cosSin writes: a typed array, so no number is boxed in the step's loops.
const rotation = new Float64Array(2);

/**
 * A rigid transform: translation (x, y) in metres and rotation stored as cosine c and sine s.
 * Storing c and s rather than the angle means kernels never call trigonometric functions.
 * Maps a local point p to world as (c px - s py + x, s px + c py + y).
 */
export class Transform {
  // -0 and the fraction below: doubles from the first transform on (see the comment in Body).
  x = -0;
  y = -0;
  c = 0.5;
  s = -0;

  constructor() {
    this.c = 1;
  }

  set(x: number, y: number, angle: number): this {
    this.x = x;
    this.y = y;
    cosSin(angle, rotation);
    this.c = rotation[0]!;
    this.s = rotation[1]!;
    return this;
  }

  /**
   * Places the transform so that the body-local point (localX, localY), the centre of mass, lands
   * on the world point (centerX, centerY), turned by `angle` (rad).
   */
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
    this.c = c;
    this.s = s;
    this.x = centerX - (c * localX - s * localY);
    this.y = centerY - (s * localX + c * localY);
    return this;
  }

  copy(other: Transform): this {
    this.x = other.x;
    this.y = other.y;
    this.c = other.c;
    this.s = other.s;
    return this;
  }
}
