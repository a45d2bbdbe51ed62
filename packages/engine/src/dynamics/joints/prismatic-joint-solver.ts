import { SPRING_MOTOR_LIMIT_END } from './spring-motor-limit.ts';

// A prismatic joint's record: the head (joint-record.ts), the spring, motor and limit on its
// translation (spring-motor-limit.ts), then these. The kernel's passes read them from the layout
// the build script generates from this file (J_PRISMATIC_..., wasm/contact-layout.ts).
/** The slide's direction in A's frame (unit). */
export const LOCAL_AXIS_X: number = SPRING_MOTOR_LIMIT_END;
export const LOCAL_AXIS_Y: number = SPRING_MOTOR_LIMIT_END + 1;
/** The axis in world orientation at the step's start. */
export const AXIS_X: number = SPRING_MOTOR_LIMIT_END + 2;
export const AXIS_Y: number = SPRING_MOTOR_LIMIT_END + 3;
/** Accumulated impulses (warm-started). */
export const PERPENDICULAR_IMPULSE: number = SPRING_MOTOR_LIMIT_END + 4;
export const ANGULAR_IMPULSE: number = SPRING_MOTOR_LIMIT_END + 5;
export const STRIDE: number = SPRING_MOTOR_LIMIT_END + 6;
