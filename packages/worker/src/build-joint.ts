import {
  distanceJoint,
  mouseJoint,
  prismaticJoint,
  revoluteJoint,
  weldJoint,
  type Body,
  type DistanceJointOptions,
  type Joint,
  type PrismaticJointOptions,
  type RevoluteJointOptions,
  type WeldJointOptions,
} from '@physical/engine';
import {
  JOINT_KINDS,
  requireDefinition,
  resolve,
  withoutKind,
  type JointDefinition,
} from './definitions.ts';
import type { BodyId } from './ids.ts';

// The worker builds each joint with the engine's factory (the page only checks it: its copies
// are PageJoints), in a file of its own so that a page never bundles the joint classes.

/**
 * Builds the engine joint a definition describes between the bodies `bodyOf` resolves (throws the
 * engine's PhysicalError on bad input, or for an unknown body id).
 */
export function buildJoint(definition: JointDefinition, bodyOf: (id: BodyId) => Body): Joint {
  requireDefinition(definition, JOINT_KINDS);
  if (definition.kind === 'mouse') {
    const { body, ...rest } = definition;
    return mouseJoint({ ...withoutKind(rest), body: resolve('body', body, bodyOf) });
  }
  const { kind, bodyA, bodyB, ...rest } = definition;
  const bodies = {
    bodyA: resolve('bodyA', bodyA, bodyOf),
    bodyB: resolve('bodyB', bodyB, bodyOf),
  };
  switch (kind) {
    case 'revolute':
      return revoluteJoint({
        ...(rest as Omit<RevoluteJointOptions, 'bodyA' | 'bodyB'>),
        ...bodies,
      });
    case 'prismatic':
      return prismaticJoint({
        ...(rest as Omit<PrismaticJointOptions, 'bodyA' | 'bodyB'>),
        ...bodies,
      });
    case 'distance':
      return distanceJoint({
        ...(rest as Omit<DistanceJointOptions, 'bodyA' | 'bodyB'>),
        ...bodies,
      });
    case 'weld':
      return weldJoint({ ...(rest as Omit<WeldJointOptions, 'bodyA' | 'bodyB'>), ...bodies });
  }
}
