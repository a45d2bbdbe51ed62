import { DistanceJoint, type DistanceJointOptions } from './distance-joint.ts';
import { MouseJoint, type MouseJointOptions } from './mouse-joint.ts';
import { PrismaticJoint, type PrismaticJointOptions } from './prismatic-joint.ts';
import { RevoluteJoint, type RevoluteJointOptions } from './revolute-joint.ts';
import { WeldJoint, type WeldJointOptions } from './weld-joint.ts';

// One function per joint, like the body helpers (particle, box, wall): build it, then
// world.addJoint(...). Every option is checked here; a bad one throws a PhysicalError naming it.

/**
 * A hinge through a world point: body B turns about it relative to body A. Optional angle limits,
 * motor and torsion spring.
 *
 * @example
 * const hinge = world.addJoint(revoluteJoint({ bodyA: ground, bodyB: door, anchor: { x: 0, y: 2 } }));
 */
export function revoluteJoint<UserData = unknown>(
  options: RevoluteJointOptions<UserData>,
): RevoluteJoint<UserData> {
  return new RevoluteJoint(options);
}

/**
 * A slider: body B moves along an axis fixed in body A, without turning relative to it. Optional
 * translation limits, motor and spring.
 *
 * @example
 * const piston = world.addJoint(prismaticJoint({ bodyA: ground, bodyB: block, anchor: { x: 0, y: 0 }, axis: { x: 1, y: 0 } }));
 */
export function prismaticJoint<UserData = unknown>(
  options: PrismaticJointOptions<UserData>,
): PrismaticJoint<UserData> {
  return new PrismaticJoint(options);
}

/**
 * Keeps two points at a distance: a rigid rod, or a spring (enableSpring, hertz, dampingRatio),
 * with an optional length range (a rope: enableSpring with hertz 0 and a maxLength).
 *
 * @example
 * const rope = world.addJoint(distanceJoint({ bodyA: ceiling, bodyB: lamp, anchorA: hook, anchorB: lampTop }));
 */
export function distanceJoint<UserData = unknown>(
  options: DistanceJointOptions<UserData>,
): DistanceJoint<UserData> {
  return new DistanceJoint(options);
}

/**
 * Glues two bodies together at a point: rigid (0 Hz), or springy in position and angle.
 *
 * @example
 * world.addJoint(weldJoint({ bodyA: board, bodyB: tip, anchor: { x: 2, y: 0 }, angularHertz: 3 }));
 */
export function weldJoint<UserData = unknown>(
  options: WeldJointOptions<UserData>,
): WeldJoint<UserData> {
  return new WeldJoint(options);
}

/**
 * Drags a body toward a target point with a soft spring of bounded force: what a finger or the
 * mouse needs. Move the target with `joint.target = { x, y }`; remove the joint on release.
 *
 * @example
 * const drag = world.addJoint(mouseJoint({ body, target: pointer }));
 * drag.target = nextPointer;
 */
export function mouseJoint<UserData = unknown>(
  options: MouseJointOptions<UserData>,
): MouseJoint<UserData> {
  return new MouseJoint(options);
}
