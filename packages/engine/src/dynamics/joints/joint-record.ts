// A joint's numbers: one record of doubles in its kind's store (joint-store.ts), read and written
// in place by the `Joint` handle's getters and setters and by the kind's solver passes (Box2D v3
// keeps its joint solver data in arrays the same way). Every kind's record starts with this head,
// the numbers all kinds keep at the same offsets, so the code that reads them is written once
// (the frame's preparation, the reaction, the soft point constraint); the kind's own numbers
// follow from JOINT_HEAD on (its file lists them).
//
//   0-3   rAx, rAy, rBx, rBy    levers from the centres to the anchors at the step's start (m)
//   4-5   delta centre          centre of B minus centre of A at the step's start (m)
//   6     joint angle 0         angle of B minus angle of A minus the reference, at the step's start
//   7-10  1/mA, 1/IA, 1/mB, 1/IB as the solver sees them this step (0: static, sleeping, kinematic)
//   11-12 state A, state B      the bodies' state offsets (solver slot x STATE_STRIDE) this step
//   13-15 step impulse          on B, summed over the step's relax passes (N s, N m s)
//   16-18 reaction              the last step's average force and torque on B (N, N m)
//   19    sub-step duration     of the last step (s): turns a sub-step impulse into a force
//   20-23 local anchors         A's and B's anchor in its body's frame (m, from the body origin)
//   24    reference angle       angle of B minus angle of A at creation (rad)

export const R_AX = 0;
export const R_AY = 1;
export const R_BX = 2;
export const R_BY = 3;
export const DELTA_CENTER_X = 4;
export const DELTA_CENTER_Y = 5;
export const JOINT_ANGLE_0 = 6;
export const INV_MASS_A = 7;
export const INV_I_A = 8;
export const INV_MASS_B = 9;
export const INV_I_B = 10;
export const STATE_A = 11;
export const STATE_B = 12;
export const STEP_IMPULSE_X = 13;
export const STEP_IMPULSE_Y = 14;
export const STEP_ANGULAR_IMPULSE = 15;
export const REACTION_X = 16;
export const REACTION_Y = 17;
export const REACTION_ANGULAR = 18;
export const SUB_STEP_DURATION = 19;
export const LOCAL_ANCHOR_AX = 20;
export const LOCAL_ANCHOR_AY = 21;
export const LOCAL_ANCHOR_BX = 22;
export const LOCAL_ANCHOR_BY = 23;
export const REFERENCE_ANGLE = 24;
/** Where a kind's own numbers start. */
export const JOINT_HEAD = 25;
/**
 * Doubles per record in a world's store: the largest kind's (prismatic); every kind's record is
 * at most this long (joint-layouts.test.ts), so all kinds share one store in the solver memory.
 */
export const JOINT_RECORD_STRIDE = 48;
