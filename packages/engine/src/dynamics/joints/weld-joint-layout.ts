import { JOINT_HEAD } from './joint-record.ts';

// A weld joint's record: the head (joint-record.ts), then these. The kernel's passes
// (wasm/joint-passes.ts) read them from the layout the build script generates from this file
// (J_WELD_..., wasm/contact-layout.ts).

/** Settings: the holds' stiffness (Hz) and damping ratio. */
export const LINEAR_HERTZ: number = JOINT_HEAD;
export const ANGULAR_HERTZ: number = JOINT_HEAD + 1;
export const DAMPING_RATIO: number = JOINT_HEAD + 2;
/** This step: 1 / (1/IA + 1/IB). */
export const AXIAL_MASS: number = JOINT_HEAD + 3;
/**
 * 1: the position hold has its own softness (bias rate, mass scale and impulse scale next), in
 * both passes; 0: rigid. The order is what the soft point reads.
 */
export const LINEAR_SPRINGY: number = JOINT_HEAD + 4;
/** Then its mass scale and impulse scale. */
export const LINEAR_BIAS_RATE: number = JOINT_HEAD + 5;
/** The same for the angle hold. */
export const ANGULAR_SPRINGY: number = JOINT_HEAD + 8;
export const ANGULAR_BIAS_RATE: number = JOINT_HEAD + 9;
export const ANGULAR_MASS_SCALE: number = JOINT_HEAD + 10;
export const ANGULAR_IMPULSE_SCALE: number = JOINT_HEAD + 11;
/** Accumulated impulses (warm-started). */
export const LINEAR_IMPULSE_X: number = JOINT_HEAD + 12;
export const LINEAR_IMPULSE_Y: number = JOINT_HEAD + 13;
export const ANGULAR_IMPULSE: number = JOINT_HEAD + 14;
export const STRIDE: number = JOINT_HEAD + 15;
