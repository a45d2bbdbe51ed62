import { describe, expect, it } from 'vitest';
import {
  PhysicalError,
  box,
  checkJointOptions,
  distanceJoint,
  mouseJoint,
  prismaticJoint,
  revoluteJoint,
  weldJoint,
  type Joint,
  type JointOptionsByType,
  type JointType,
} from '@physical/engine';

// checkJointOptions: each joint's option check without the joint (what a worker world's page
// runs), the same check its factory runs: the same PhysicalError field for every bad option, and
// the anchors the joint reports when made.

const factories: { [T in JointType]: (options: JointOptionsByType[T]) => Joint } = {
  revolute: revoluteJoint,
  prismatic: prismaticJoint,
  distance: distanceJoint,
  weld: weldJoint,
  mouse: mouseJoint,
};

function bodies() {
  const bodyA = box({ position: { x: -1, y: 0.5 }, angle: 0.3, width: 1, height: 1 });
  const bodyB = box({ position: { x: 2, y: -1 }, angle: -0.7, width: 1, height: 0.5 });
  return { bodyA, bodyB };
}

/** Valid options of each type, and options with one bad field each. */
function cases(): { type: JointType; options: Record<string, unknown> }[] {
  const { bodyA, bodyB } = bodies();
  const hinge = { bodyA, bodyB, anchor: { x: 0.5, y: 0.25 } };
  const valid: { type: JointType; options: Record<string, unknown> }[] = [
    { type: 'revolute', options: { ...hinge, enableLimit: true, lowerAngle: -1, upperAngle: 1 } },
    { type: 'prismatic', options: { ...hinge, axis: { x: 0, y: 2 }, lower: -1, upper: 1 } },
    {
      type: 'distance',
      options: { bodyA, bodyB, anchorA: { x: -1, y: 0 }, anchorB: { x: 2, y: -1.1 }, minLength: 1 },
    },
    { type: 'weld', options: { ...hinge, angularHertz: 3 } },
    { type: 'mouse', options: { body: bodyB, target: { x: 2.1, y: -0.9 }, hertz: 4 } },
  ];
  const bad: [string, unknown][] = [
    ['bodyB', bodyA],
    ['anchor', { x: Number.NaN, y: 0 }],
    ['anchorA', undefined],
    ['axis', { x: 0, y: 0 }],
    ['collideConnected', 'yes'],
    ['lowerAngle', 2],
    ['lower', 2],
    ['maxMotorTorque', -1],
    ['maxLength', 0.5],
    ['length', -3],
    ['linearHertz', Number.POSITIVE_INFINITY],
    ['target', null],
    ['hertz', 0],
    ['dampingRatio', -1],
  ];
  const out = [...valid];
  for (const { type, options } of valid) {
    for (const [field, value] of bad) out.push({ type, options: { ...options, [field]: value } });
  }
  return out;
}

function fieldOf(call: () => unknown): string {
  try {
    call();
  } catch (error) {
    expect(error).toBeInstanceOf(PhysicalError);
    return (error as PhysicalError).field;
  }
  return 'none';
}

describe('checkJointOptions', () => {
  it("refuses what each joint's factory refuses, naming the same option, and accepts what it accepts", () => {
    let refused = 0;
    for (const { type, options } of cases()) {
      const check = fieldOf(() => checkJointOptions(type, options as never));
      expect(check, `${type} ${JSON.stringify(Object.keys(options))}`).toBe(
        fieldOf(() => factories[type](options as never)),
      );
      if (check !== 'none') refused++;
    }
    // The bad options reach the checks (the rest are options the type does not read): 26 refused.
    expect(refused).toBe(26);
  });

  it('returns the anchors the joint reports when made (world points, m)', () => {
    for (const { type, options } of cases().slice(0, 5)) {
      const anchors = checkJointOptions(type, options as never);
      const joint = factories[type](options as never);
      expect(anchors.anchorA.x).toBeCloseTo(joint.anchorA.x, 12);
      expect(anchors.anchorA.y).toBeCloseTo(joint.anchorA.y, 12);
      expect(anchors.anchorB.x).toBeCloseTo(joint.anchorB.x, 12);
      expect(anchors.anchorB.y).toBeCloseTo(joint.anchorB.y, 12);
    }
  });

  it('names `type` for an unknown joint type', () => {
    expect(fieldOf(() => checkJointOptions('rope' as JointType, {} as never))).toBe('type');
  });
});
