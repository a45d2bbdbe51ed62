import { describe, expect, it } from 'vitest';
import {
  Body,
  World,
  box,
  capsule,
  distanceJoint,
  particle,
  revoluteJoint,
  takeSnapshot,
  wall,
  weldJoint,
} from '@physical/engine';

// Many internal number fields start as -0 so that V8 stores them as doubles from the first object
// on (see the comment in dynamics/body.ts). That must never show: every zero an app reads is +0
// (Object.is(-0, 0) is false, and -0 prints as "-0" in some places), and snapshots hold no "-0".

function negativeZeros(value: unknown, path: string, found: string[]): void {
  if (typeof value === 'number') {
    if (Object.is(value, -0)) found.push(path);
  } else if (value === '-0') {
    found.push(path);
  } else if (Array.isArray(value)) {
    value.forEach((item, i) => negativeZeros(item, `${path}[${i}]`, found));
  } else if (typeof value === 'object' && value !== null) {
    for (const [key, item] of Object.entries(value)) negativeZeros(item, `${path}.${key}`, found);
  }
}

function readBody(body: Body): Record<string, unknown> {
  return {
    position: { ...body.position },
    angle: body.angle,
    linearVelocity: { ...body.linearVelocity },
    angularVelocity: body.angularVelocity,
    centerOfMass: { ...body.centerOfMass },
    localCenterOfMass: { ...body.localCenterOfMass },
    mass: body.mass,
    inertia: body.inertia,
    gravityScale: body.gravityScale,
    linearDamping: body.linearDamping,
    angularDamping: body.angularDamping,
    drag: body.drag,
    kineticEnergy: body.kineticEnergy,
    shapes: body.shapes.map((shape) => ({
      friction: shape.friction,
      restitution: shape.restitution,
      bounds: shape.getBounds(),
    })),
  };
}

function bodies(): Body[] {
  return [
    wall({ from: { x: -5, y: 0 }, to: { x: 5, y: 0 } }),
    box({ width: 1, height: 1 }),
    particle({ radius: 0.5 }),
    capsule({ length: 1, radius: 0.2 }),
    new Body({ type: 'kinematic', shapes: [{ type: 'circle', radius: 1 }] }),
    new Body({ type: 'static' }),
  ];
}

describe('zeros an app reads are +0', () => {
  it('on fresh bodies of every type, before and after they join a world', () => {
    const found: string[] = [];
    const list = bodies();
    list.forEach((body, i) => negativeZeros(readBody(body), `fresh[${i}]`, found));
    const world = new World({ gravity: { x: 0, y: 0 } });
    for (const body of list) world.add(body);
    world.step();
    list.forEach((body, i) => negativeZeros(readBody(body), `stepped[${i}]`, found));
    expect(found).toEqual([]);
  });

  it('on fresh joints and in a snapshot of a world that has stepped', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const [ground, a, b, c] = [
      world.add(wall({ from: { x: -5, y: 0 }, to: { x: 5, y: 0 } })),
      world.add(box({ width: 1, height: 1, position: { x: 0, y: -3 } })),
      world.add(box({ width: 1, height: 1, position: { x: 2, y: -3 } })),
      world.add(particle({ radius: 0.3, position: { x: 4, y: -3 } })),
    ];
    const joints = [
      world.addJoint(revoluteJoint({ bodyA: a, bodyB: b, anchor: { x: 1, y: -3 } })),
      world.addJoint(
        distanceJoint({ bodyA: b, bodyB: c, anchorA: { x: 2, y: -3 }, anchorB: { x: 4, y: -3 } }),
      ),
      world.addJoint(weldJoint({ bodyA: ground, bodyB: a, anchor: { x: 0, y: -2 } })),
    ];
    const found: string[] = [];
    const readJoints = (tag: string): void =>
      joints.forEach((joint, i) =>
        negativeZeros(
          { force: { ...joint.reactionForce }, torque: joint.reactionTorque },
          `${tag}[${i}]`,
          found,
        ),
      );
    readJoints('fresh');
    world.step();
    readJoints('stepped');
    negativeZeros(takeSnapshot(world), 'snapshot', found);
    expect(found).toEqual([]);
  });
});
