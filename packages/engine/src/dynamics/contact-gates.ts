import { AABB_MARGIN, LINEAR_SLOP } from '../core/constants.ts';

// The distances the narrow phase's gates decide a contact by (the kernel's collideContacts,
// wasm/contact-gates.ts, which ContactManager.collide runs). One definition: the kernel build
// writes the mirror into wasm/contact-layout.ts.

// Manifolds are reused while B moved less than this relative to A (m). Motion along the normal is
// measured exactly on reuse; only sliding along the surface can leave a contact point behind its
// true place, by at most this much: half the slop, below anything the solver resolves.
const REUSE_TOLERANCE = 0.5 * LINEAR_SLOP;
/** The reuse tolerance squared (m^2). */
export const REUSE_TOLERANCE_SQUARED: number = REUSE_TOLERANCE * REUSE_TOLERANCE;

/**
 * A contact whose fat boxes parted lives on while its shapes' tight boxes are no farther apart
 * than this (m) along either axis. Fat boxes reach AABB_MARGIN past their shapes, so shapes
 * within two margins can meet again by re-fattening alone; a turning box's own box also swells and
 * shrinks from step to step. Counted in tumbler's first 150 steps: keeping to two margins, 62,000
 * of the 124,000 contacts made were pairs ended the step before, at tight gaps of 0.21-0.29 m;
 * keeping to four, 358 of 36,000. Per step over 300 steps (npm run bench:churn): 1,106 made
 * before, 152 after.
 */
export const KEEP_GAP: number = 4 * AABB_MARGIN;

/** What collideContacts stops at a slot for (GATE_ACTION of the narrow-phase scratch). */
export const GATE_DESTROY = 1;
/** The contact stopped touching: its end is recorded. */
export const GATE_END = 2;
/** The contact started touching: its begin is recorded and its bodies woken. */
export const GATE_BEGIN = 3;
