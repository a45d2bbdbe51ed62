// The kernel's fractional arguments, in a small fixed region of the solver memory
// (KERNEL_ARGUMENTS, solver-memory.ts): the caller stores them there and passes the region's byte
// offset, and the kernel's passes (wasm/body-passes.ts, contact-kernel.ts, shape-bounds.ts,
// shock-propagation.ts, joint-passes.ts) load them from it. This file is the one definition of
// the layout; the kernel build writes its mirror into wasm/contact-layout.ts.
//
// Why not arguments: V8 (Node 20) calls a WebAssembly export through a wrapper that takes tagged
// values, so a double passed to it is boxed into a new heap number (16 bytes) unless the optimising
// compiler inlined that call into optimised code, which a caller not yet optimised (code run once
// a step stays in V8's baseline tiers for thousands of steps) and some optimised callers do not
// get. The bodies' boxes after a sweep (bodyBounds, once per fast body) made ~16 KB of garbage a
// step in tumbler that way, and the sub-steps' passes, the joints' passes and prepareListed ~2 KB
// more. A store into a Float64Array boxes nothing.

/** The step (s): finalizeBodies, prepareListed. */
export const A_DT = 0;
/** The step the broad-phase boxes look ahead (s): shapeBounds, bodyBounds. */
export const A_BOUNDS_DT = 1;
/** The sub-step (s) and its inverse: the body passes, prepareListed, solve, shockSweep. */
export const A_H = 2;
export const A_INVERSE_H = 3;
/** Gravity (m/s^2): integrateVelocities, prepareShockSweep. */
export const A_GRAVITY_X = 4;
export const A_GRAVITY_Y = 5;
/** The speed limits (m/s, rad/s): the body passes. */
export const A_MAX_SPEED = 6;
export const A_MAX_ANGULAR_SPEED = 7;
/** The contacts' push-out limit (m/s): solve, shockSweep, impacts. */
export const A_MAX_PUSH_SPEED = 8;
/** Restitution's threshold (m/s): solve, shockSweep. */
export const A_RESTITUTION_THRESHOLD = 9;
/** The impact rounds' speeds (m/s, Solver.subSteps): solve, impacts. */
export const A_IMPACT_SPEED = 10;
export const A_LOAD_SPEED = 11;
/** The contacts' softness (softness.ts) between moving bodies and against static ones: prepareListed. */
export const A_CONTACT_BIAS_RATE = 12;
export const A_CONTACT_MASS_SCALE = 13;
export const A_CONTACT_IMPULSE_SCALE = 14;
export const A_STATIC_BIAS_RATE = 15;
export const A_STATIC_MASS_SCALE = 16;
export const A_STATIC_IMPULSE_SCALE = 17;
export const A_CONTACT_HERTZ = 18;
export const A_CONTACT_ZETA = 19;
/** The heavy-on-light sweep's bias rate, rest speed and approach limit: shock-propagation.ts. */
export const A_SHOCK_BIAS_RATE = 20;
export const A_SHOCK_REST_SPEED = 21;
export const A_SHOCK_MAX_APPROACH = 22;
/** A joint pass's step numbers (JointStep, joints/joint.ts): jointPass. */
export const A_JOINT_H = 23;
export const A_JOINT_INVERSE_H = 24;
export const A_JOINT_BIAS_RATE = 25;
export const A_JOINT_MASS_SCALE = 26;
export const A_JOINT_IMPULSE_SCALE = 27;
export const A_JOINT_MAX_BIAS_SPEED = 28;
/** Doubles of the region. */
export const KERNEL_ARGUMENT_DOUBLES = 29;
