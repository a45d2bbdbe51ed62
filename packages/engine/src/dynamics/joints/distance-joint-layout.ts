import { JOINT_HEAD } from './joint-record.ts';

// A distance joint's record: the head (joint-record.ts), then these. The kernel's passes
// (wasm/joint-passes.ts) read them from the layout the build script generates from this file
// (J_DISTANCE_..., wasm/contact-layout.ts).

/** Settings: rest length, shortest and longest length (m). */
export const REST: number = JOINT_HEAD;
export const MIN_LENGTH: number = JOINT_HEAD + 1;
export const MAX_LENGTH: number = JOINT_HEAD + 2;
/** 1 or 0: a spring, else a rigid rod. */
export const SPRING_ENABLED: number = JOINT_HEAD + 3;
export const HERTZ: number = JOINT_HEAD + 4;
export const DAMPING_RATIO: number = JOINT_HEAD + 5;
/** This step, 1 or 0: the spring acts as a force (see DistanceJoint.prepare). */
export const EXPLICIT_SPRING: number = JOINT_HEAD + 6;
export const SPRING_OMEGA: number = JOINT_HEAD + 7;
/** 1 or 0: the rod, or the spring as a soft constraint. */
export const LENGTH_ROW_ON: number = JOINT_HEAD + 8;
export const SPRING_BIAS_RATE: number = JOINT_HEAD + 9;
export const SPRING_MASS_SCALE: number = JOINT_HEAD + 10;
export const SPRING_IMPULSE_SCALE: number = JOINT_HEAD + 11;
/** 1 or 0: the minLength row. */
export const LOWER_ON: number = JOINT_HEAD + 12;
/** 1 or 0: the maxLength row. */
export const UPPER_ON: number = JOINT_HEAD + 13;
/** Accumulated impulses (warm-started). */
export const IMPULSE: number = JOINT_HEAD + 14;
export const LOWER_IMPULSE: number = JOINT_HEAD + 15;
export const UPPER_IMPULSE: number = JOINT_HEAD + 16;
/** The explicit spring's impulse in the sub-step. */
export const SPRING_SUB_STEP_IMPULSE: number = JOINT_HEAD + 17;
export const STRIDE: number = JOINT_HEAD + 18;

/** Below this anchor distance (m) the joint has no direction and does nothing. */
export const LENGTH_EPSILON = 1e-9;
