/** A 2D vector. Positions are in metres, velocities in m/s, forces in newtons. */
export interface Vec2 {
  x: number;
  y: number;
}

/** Any object with numeric `x` and `y`, accepted wherever the engine takes a vector. */
export interface Vec2Like {
  readonly x: number;
  readonly y: number;
}
