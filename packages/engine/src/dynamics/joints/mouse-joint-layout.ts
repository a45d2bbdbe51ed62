import { JOINT_HEAD } from './joint-record.ts';

// A mouse joint's record: the head (joint-record.ts; the grabbed point is B's local anchor, the
// "A" side is the fixed target, so of A's numbers only zeros), then these. The kernel's passes
// (wasm/joint-passes.ts) read them from the layout the build script generates from this file
// (J_MOUSE_..., wasm/contact-layout.ts).

/** Settings. */
export const TARGET_X: number = JOINT_HEAD;
export const TARGET_Y: number = JOINT_HEAD + 1;
export const MAX_FORCE: number = JOINT_HEAD + 2;
export const HERTZ: number = JOINT_HEAD + 3;
export const DAMPING_RATIO: number = JOINT_HEAD + 4;
/** The pull's softness this step (bias rate, mass scale, impulse scale). */
export const LINEAR_BIAS_RATE: number = JOINT_HEAD + 5;
export const LINEAR_MASS_SCALE: number = JOINT_HEAD + 6;
export const LINEAR_IMPULSE_SCALE: number = JOINT_HEAD + 7;
/** The spin brake's softness this step (it has no target angle: its bias rate is unused). */
export const ANGULAR_BIAS_RATE: number = JOINT_HEAD + 8;
export const ANGULAR_MASS_SCALE: number = JOINT_HEAD + 9;
export const ANGULAR_IMPULSE_SCALE: number = JOINT_HEAD + 10;
/** Accumulated impulses (warm-started). */
export const LINEAR_IMPULSE_X: number = JOINT_HEAD + 11;
export const LINEAR_IMPULSE_Y: number = JOINT_HEAD + 12;
export const ANGULAR_IMPULSE: number = JOINT_HEAD + 13;
export const STRIDE: number = JOINT_HEAD + 14;
