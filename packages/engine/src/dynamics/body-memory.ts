// Every number of a body in one place: a stride of BODY_STRIDE doubles per body, by world index,
// in the world's solver memory (solver-memory.ts, region BODIES). `Body` is a handle: its getters
// and setters read and write its stride there, and the step's passes read the same numbers in
// order. A body not in a world keeps its stride in a small array of its own (a BodyStore of one
// body), copied into the world's region on `add` and out of it on `remove`, and only there.
//
// The first line (64 bytes) is what the narrow phase's gates read of each body
// (contact-manager.ts: the offsets are literals in its loop, which is hot); the rest is read by
// gathering, finalizing, sleep, continuous collision and the handles.
//
//   0 x, 1 y, 2 c, 3 s       the transform of the body origin (cosine and sine of the angle)
//   4 vx, 5 vy, 6 w          velocity of the centre of mass (m/s), angular velocity (rad/s)
//   7 origin reach           farthest point of the shapes from the body origin (m)
//   8 max extent             farthest point of the shapes from the centre of mass (m)
//   9 awake                  1 awake, 0 asleep (static bodies: 0)
//  10 angle                  unwrapped rotation (rad)
//  11 cx, 12 cy              centre of mass, world (m)
//  13 lcx, 14 lcy            centre of mass, body-local (m)
//  15 sleep time             seconds the body has rested
//  16 1/m, 17 1/I, 18 m, 19 I
//  20 cx0, 21 cy0, 22 angle0 centre of mass and angle at the start of the step (continuous)
//  23 min extent             smallest distance from the centre of mass to the surface (m)
//  24 gravity scale, 25 linear damping, 26 angular damping, 27 drag
//  28 fx, 29 fy, 30 torque   force and torque of this step, gathered from the body's forces
//  31 flags                  FLAG_* bits
//  32 mass override, 33 inertia override (0: computed from the shapes)
//  34 contact head           first key of the body's contact edges plus one, 0: none (contact-edges.ts)
//  35 forces left            1 while the body has forces with a duration still to act, else 0
//                            (written by Solver.gatherBodies, read by the kernel's finalizeBodies)
//  36 shape head             first shape id of the body plus one, 0: none; the next shape's id plus
//                            one per shape in SHAPE_NEXT (solver-memory.ts), in shapeList's order
//                            (written by WorldMembership, read by the kernel's shapeBounds)
//  37-39 free (the stride stays a whole number of cache lines)

export const BODY_STRIDE = 40;
export const B_X = 0;
export const B_Y = 1;
export const B_C = 2;
export const B_S = 3;
export const B_VX = 4;
export const B_VY = 5;
export const B_W = 6;
export const B_ORIGIN_REACH = 7;
export const B_MAX_EXTENT = 8;
export const B_AWAKE = 9;
export const B_ANGLE = 10;
export const B_CENTER_X = 11;
export const B_CENTER_Y = 12;
export const B_LOCAL_CENTER_X = 13;
export const B_LOCAL_CENTER_Y = 14;
export const B_SLEEP_TIME = 15;
export const B_INV_MASS = 16;
export const B_INV_INERTIA = 17;
export const B_MASS = 18;
export const B_INERTIA = 19;
export const B_CENTER0_X = 20;
export const B_CENTER0_Y = 21;
export const B_ANGLE0 = 22;
export const B_MIN_EXTENT = 23;
export const B_GRAVITY_SCALE = 24;
export const B_LINEAR_DAMPING = 25;
export const B_ANGULAR_DAMPING = 26;
export const B_DRAG = 27;
export const B_FORCE_X = 28;
export const B_FORCE_Y = 29;
export const B_TORQUE = 30;
export const B_FLAGS = 31;
export const B_MASS_OVERRIDE = 32;
export const B_INERTIA_OVERRIDE = 33;
export const B_CONTACT_HEAD = 34;
export const B_FORCES_LEFT = 35;
export const B_SHAPE_HEAD = 36;

/** Bits of B_FLAGS. */
export const FLAG_FIXED_ROTATION = 1;
export const FLAG_ALLOW_SLEEP = 2;
export const FLAG_BULLET = 4;

/**
 * Where bodies' numbers live: `data` holds a stride per body. The world's store is the view of
 * its solver memory's BODIES region, replaced (never grown in place) when the memory moves, so
 * handles keep the store and read `data` at each access. A body outside a world has a store of
 * its own.
 */
export class BodyStore {
  constructor(public data: Float64Array) {}
}

/**
 * A store for one body outside a world. Every field starts as -0, as the fields of the Body
 * object it replaces did (a snapshot saves such a field as 0; an app reads +0, written over it).
 */
export function createLocalBodyStore(): BodyStore {
  return new BodyStore(new Float64Array(BODY_STRIDE).fill(-0));
}
