// The collision lab's ranges, without the engine: the preset links (app/presets.ts, in the
// first screen's code) clamp to them before any engine code has arrived.

/** Lightest and heaviest particle the lab takes (kg). */
export const MIN_MASS = 0.05;
export const MAX_MASS = 10;
/** Fastest velocity component the lab takes (m/s). */
export const MAX_SPEED = 10;
