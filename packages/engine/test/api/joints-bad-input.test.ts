import { describe, expect, it } from 'vitest';
import {
  PhysicalError,
  World,
  box,
  mouseJoint,
  distanceJoint,
  particle,
  prismaticJoint,
  revoluteJoint,
  weldJoint,
  type Body,
} from '@physical/engine';

// Bad joint input is reported where it comes in, as a PhysicalError naming the field.

function expectField(run: () => unknown, field: string): void {
  let error: unknown = null;
  try {
    run();
  } catch (caught) {
    error = caught;
  }
  expect(error).toBeInstanceOf(PhysicalError);
  expect((error as PhysicalError).field).toBe(field);
}

function pair(): { world: World; a: Body; b: Body } {
  const world = new World();
  const a = world.add(box({ type: 'static', width: 1, height: 1 }));
  const b = world.add(particle({ position: { x: 2, y: 0 }, radius: 0.5 }));
  return { world, a, b };
}

describe('bad joint input', () => {
  it('rejects anchors that are not finite points', () => {
    const { a, b } = pair();
    for (const anchor of [
      { x: NaN, y: 0 },
      { x: 0, y: Infinity },
    ]) {
      expectField(
        () => revoluteJoint({ bodyA: a, bodyB: b, anchor }),
        anchor.y === 0 ? 'anchor.x' : 'anchor.y',
      );
    }
    expectField(() => revoluteJoint({ bodyA: a, bodyB: b } as never), 'anchor');
    expectField(() => mouseJoint({ body: b, target: { x: 0, y: NaN } }), 'target.y');
  });

  it('rejects the same body twice, missing bodies and two bodies that cannot move', () => {
    const { a, b } = pair();
    const anchor = { x: 0, y: 0 };
    expectField(() => revoluteJoint({ bodyA: b, bodyB: b, anchor }), 'bodyB');
    expectField(() => revoluteJoint({ bodyA: null as never, bodyB: b, anchor }), 'bodyA');
    expectField(() => revoluteJoint({ bodyA: a, bodyB: {} as never, anchor }), 'bodyB');
    const wall = box({ type: 'static', width: 1, height: 1 });
    expectField(() => revoluteJoint({ bodyA: a, bodyB: wall, anchor }), 'bodyB');
    expectField(() => mouseJoint({ body: a, target: anchor }), 'body');
  });

  it('rejects limits out of order and negative torques, forces and frequencies', () => {
    const { a, b } = pair();
    const anchor = { x: 0, y: 0 };
    expectField(
      () => revoluteJoint({ bodyA: a, bodyB: b, anchor, lowerAngle: 1, upperAngle: 0 }),
      'lowerAngle',
    );
    expectField(() => revoluteJoint({ bodyA: a, bodyB: b, anchor, upperAngle: NaN }), 'upperAngle');
    expectField(
      () => revoluteJoint({ bodyA: a, bodyB: b, anchor, maxMotorTorque: -1 }),
      'maxMotorTorque',
    );
    expectField(
      () => revoluteJoint({ bodyA: a, bodyB: b, anchor, motorSpeed: Infinity }),
      'motorSpeed',
    );
    expectField(() => revoluteJoint({ bodyA: a, bodyB: b, anchor, hertz: -2 }), 'hertz');
    expectField(
      () => revoluteJoint({ bodyA: a, bodyB: b, anchor, dampingRatio: -1 }),
      'dampingRatio',
    );
    expectField(() => mouseJoint({ body: b, target: anchor, maxForce: -1 }), 'maxForce');
    expectField(() => mouseJoint({ body: b, target: anchor, hertz: 0 }), 'hertz');
    const hinge = revoluteJoint({ bodyA: a, bodyB: b, anchor, enableLimit: true });
    expectField(() => (hinge.lowerAngle = 0.5), 'lowerAngle');
    expectField(() => hinge.setLimits(0, -1), 'lowerAngle');
    expectField(() => (hinge.maxMotorTorque = -3), 'maxMotorTorque');
    const drag = mouseJoint({ body: b, target: anchor });
    expectField(() => (drag.target = { x: Infinity, y: 0 }), 'target.x');
  });

  it('rejects joints whose bodies are not in this world, and joints added twice', () => {
    const { world, a, b } = pair();
    const other = new World();
    const stranger = other.add(particle({ radius: 0.5 }));
    expectField(
      () => world.addJoint(revoluteJoint({ bodyA: a, bodyB: stranger, anchor: { x: 0, y: 0 } })),
      'bodyB',
    );
    const loose = particle({ radius: 0.5 });
    expectField(
      () => world.addJoint(revoluteJoint({ bodyA: loose, bodyB: b, anchor: { x: 0, y: 0 } })),
      'bodyA',
    );
    const joint = world.addJoint(revoluteJoint({ bodyA: a, bodyB: b, anchor: { x: 0, y: 0 } }));
    expectField(() => world.addJoint(joint), 'joint');
    expectField(() => other.addJoint(joint), 'joint');
    expectField(() => other.removeJoint(joint), 'joint');
    expectField(() => world.addJoint({} as never), 'joint');
    world.remove(b);
    expectField(
      () => world.addJoint(revoluteJoint({ bodyA: a, bodyB: b, anchor: { x: 0, y: 0 } })),
      'bodyB',
    );
  });

  it('rejects bad distance, weld and prismatic options', () => {
    const { a, b } = pair();
    const anchorA = { x: 0, y: 0 };
    const anchorB = { x: 2, y: 0 };
    expectField(
      () => distanceJoint({ bodyA: a, bodyB: b, anchorA: { x: NaN, y: 0 }, anchorB }),
      'anchorA.x',
    );
    expectField(
      () => distanceJoint({ bodyA: a, bodyB: b, anchorA, anchorB: undefined as never }),
      'anchorB',
    );
    expectField(
      () => distanceJoint({ bodyA: a, bodyB: b, anchorA, anchorB, length: -1 }),
      'length',
    );
    expectField(
      () => distanceJoint({ bodyA: a, bodyB: b, anchorA, anchorB, minLength: 3, maxLength: 1 }),
      'minLength',
    );
    expectField(
      () => distanceJoint({ bodyA: a, bodyB: b, anchorA, anchorB, maxLength: 1 }),
      'length',
    );
    expectField(() => distanceJoint({ bodyA: a, bodyB: b, anchorA, anchorB, hertz: -1 }), 'hertz');
    const rope = distanceJoint({ bodyA: a, bodyB: b, anchorA, anchorB, enableSpring: true });
    expectField(() => (rope.length = Infinity), 'length');
    expectField(() => rope.setLengthRange(3, 4), 'length');
    expectField(
      () => weldJoint({ bodyA: a, bodyB: b, anchor: { x: 0, y: -Infinity } }),
      'anchor.y',
    );
    expectField(
      () => weldJoint({ bodyA: a, bodyB: b, anchor: anchorA, linearHertz: -1 }),
      'linearHertz',
    );
    expectField(
      () => weldJoint({ bodyA: a, bodyB: b, anchor: anchorA, angularHertz: NaN }),
      'angularHertz',
    );
    expectField(() => weldJoint({ bodyA: a, bodyB: a, anchor: anchorA }), 'bodyB');
    const axis = { x: 1, y: 0 };
    expectField(
      () => prismaticJoint({ bodyA: a, bodyB: b, anchor: anchorA, axis: { x: 0, y: 0 } }),
      'axis',
    );
    expectField(
      () => prismaticJoint({ bodyA: a, bodyB: b, anchor: anchorA, axis: { x: NaN, y: 1 } }),
      'axis.x',
    );
    expectField(
      () => prismaticJoint({ bodyA: a, bodyB: b, anchor: anchorA, axis, lower: 2, upper: 1 }),
      'lower',
    );
    expectField(
      () => prismaticJoint({ bodyA: a, bodyB: b, anchor: anchorA, axis, maxMotorForce: -5 }),
      'maxMotorForce',
    );
  });
});
