// The Forces screen's settings' ranges, without the engine: the preset links (app/presets.ts,
// in the first screen's code) clamp to them before any engine code has arrived.

/** Lightest and heaviest square (kg). */
export const MIN_MASS = 0.5;
export const MAX_MASS = 5;
/** Smallest and largest force on a square (N). */
export const MIN_FORCE = 0;
export const MAX_FORCE = 10;
