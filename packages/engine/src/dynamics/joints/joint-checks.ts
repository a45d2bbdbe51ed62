import { PhysicalError } from '../../core/errors.ts';
import { describeValue } from '../../core/validate.ts';
import type { Vec2 } from '../../math/vec2.ts';
import { checkDistanceJointOptions, type DistanceJointOptions } from './distance-joint.ts';
import type { JointType } from './joint.ts';
import { checkMouseJointOptions, type MouseJointOptions } from './mouse-joint.ts';
import { checkPrismaticJointOptions, type PrismaticJointOptions } from './prismatic-joint.ts';
import { checkRevoluteJointOptions, type RevoluteJointOptions } from './revolute-joint.ts';
import { checkWeldJointOptions, type WeldJointOptions } from './weld-joint.ts';

// The joints' option checks without the joints: a page that drives a world in a worker checks
// what it posts with these and never bundles the joint classes (their solver passes run in the
// worker). Each check is the one its joint's constructor runs.

/** The options of each joint type, as its factory (`revoluteJoint`, ...) takes them. */
export interface JointOptionsByType<UserData = unknown> {
  revolute: RevoluteJointOptions<UserData>;
  prismatic: PrismaticJointOptions<UserData>;
  distance: DistanceJointOptions<UserData>;
  weld: WeldJointOptions<UserData>;
  mouse: MouseJointOptions<UserData>;
}

/** A joint's two points in world coordinates (m) when it is made, as `joint.anchorA` / `anchorB`. */
export interface JointAnchors {
  readonly anchorA: Vec2;
  readonly anchorB: Vec2;
}

/**
 * Checks a joint's options exactly as its factory does (`revoluteJoint(options)` for
 * `'revolute'`, ...), without building the joint: a bad option throws the same
 * {@link PhysicalError} naming it. Returns the joint's anchors in world coordinates as the joint
 * would report them when made (for a mouse joint, the target for both).
 *
 * @example
 * const { anchorA } = checkJointOptions('revolute', { bodyA: ground, bodyB: door, anchor: { x: 0, y: 2 } });
 */
export function checkJointOptions<Type extends JointType>(
  type: Type,
  options: JointOptionsByType[Type],
): JointAnchors {
  switch (type) {
    case 'revolute': {
      const { anchor } = checkRevoluteJointOptions(options as RevoluteJointOptions);
      return both(anchor.x, anchor.y);
    }
    case 'prismatic': {
      const { anchor } = checkPrismaticJointOptions(options as PrismaticJointOptions);
      return both(anchor.x, anchor.y);
    }
    case 'weld': {
      const { anchor } = checkWeldJointOptions(options as WeldJointOptions);
      return both(anchor.x, anchor.y);
    }
    case 'distance': {
      const { anchorA, anchorB } = checkDistanceJointOptions(options as DistanceJointOptions);
      return { anchorA: { x: anchorA.x, y: anchorA.y }, anchorB: { x: anchorB.x, y: anchorB.y } };
    }
    case 'mouse': {
      const { target } = checkMouseJointOptions(options as MouseJointOptions);
      return both(target.x, target.y);
    }
    default:
      throw new PhysicalError(
        'type',
        `must be revolute, prismatic, distance, weld or mouse, got ${describeValue(type)}.`,
      );
  }
}

function both(x: number, y: number): JointAnchors {
  return { anchorA: { x, y }, anchorB: { x, y } };
}
