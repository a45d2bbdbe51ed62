import { MouseJoint, type MouseJointOptions } from './mouse-joint.ts';
import { RevoluteJoint, type RevoluteJointOptions } from './revolute-joint.ts';

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
