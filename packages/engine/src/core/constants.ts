// Tuning constants shared by collision and dynamics. Lengths are metres, the engine's unit:
// these values suit bodies from about 0.05 m to 50 m, the range Box2D documents for the same values.

/** Allowed overlap that the solver does not push apart: it keeps contacts persistent and stacks calm (m). */
export const LINEAR_SLOP = 0.005;

/**
 * Contact points are kept while the shapes are closer than this, before they touch, so the solver
 * can stop a body exactly at the surface instead of after it has passed it (speculative contacts, m).
 */
export const SPECULATIVE_DISTANCE: number = 4 * LINEAR_SLOP;

/** Broad-phase boxes are fattened by this much so that small motions do not update the tree (m). */
export const AABB_MARGIN = 0.1;

/** Bodies slower than this (m/s, at their farthest point) count as resting. */
export const SLEEP_SPEED = 0.05;

/** Polygons may have at most this many vertices. */
export const MAX_POLYGON_VERTICES = 8;

/**
 * The sizes of moving bodies (largest extent, m) the solver is tuned for: Box2D's guidance is
 * "moving objects between 0.1 and 10 meters" (static ones may be larger). Outside it, the slop
 * and margins above are too large or too small for the body; a development build warns (see
 * world/size-warning.ts).
 */
export const MIN_MOVING_SIZE = 0.1;
/** See {@link MIN_MOVING_SIZE}. */
export const MAX_MOVING_SIZE = 10;
