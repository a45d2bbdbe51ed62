import { SPRING_MOTOR_LIMIT_END } from './spring-motor-limit.ts';

// A revolute joint's record: the head (joint-record.ts), the spring, motor and limit on its angle
// (spring-motor-limit.ts), then these. The kernel's passes read them from the layout the build
// script generates from this file (J_REVOLUTE_..., wasm/contact-layout.ts).
/** The point's accumulated impulse (x, then y). */
export const LINEAR_IMPULSE_X: number = SPRING_MOTOR_LIMIT_END;
export const LINEAR_IMPULSE_Y: number = SPRING_MOTOR_LIMIT_END + 1;
/** This step: 1 / (1/IA + 1/IB). */
export const AXIAL_MASS: number = SPRING_MOTOR_LIMIT_END + 2;
/** This step's JointStep.maxBiasSpeed. */
export const MAX_BIAS_SPEED: number = SPRING_MOTOR_LIMIT_END + 3;
export const STRIDE: number = SPRING_MOTOR_LIMIT_END + 4;
