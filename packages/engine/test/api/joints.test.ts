import { describe, expect, it } from 'vitest';
import {
  World,
  box,
  mouseJoint,
  particle,
  revoluteJoint,
  type Body,
  type Joint,
} from '@physical/engine';

// Joints as an app uses them: added and removed at any time (also from listeners), gone with
// their bodies, waking what they join, and keeping joined bodies from colliding unless asked.

const DT = 1 / 60;

function chainOfTwo(): { world: World; ground: Body; a: Body; b: Body } {
  const world = new World();
  const ground = world.add(
    box({ type: 'static', position: { x: 0, y: 0 }, width: 0.2, height: 0.2 }),
  );
  const a = world.add(box({ position: { x: 0.5, y: 0 }, width: 1, height: 0.2 }));
  const b = world.add(box({ position: { x: 1.5, y: 0 }, width: 1, height: 0.2 }));
  return { world, ground, a, b };
}

describe('joints in a world', () => {
  it('lists joints in the order added, on the world and on their bodies', () => {
    const { world, ground, a, b } = chainOfTwo();
    const first = world.addJoint(
      revoluteJoint({ bodyA: ground, bodyB: a, anchor: { x: 0, y: 0 } }),
    );
    const second = world.addJoint(revoluteJoint({ bodyA: a, bodyB: b, anchor: { x: 1, y: 0 } }));
    expect(world.joints).toEqual([first, second]);
    expect(a.joints).toEqual([first, second]);
    expect(first.world).toBe(world);
    expect(first.type).toBe('revolute');
    world.removeJoint(first);
    expect(world.joints).toEqual([second]);
    expect(a.joints).toEqual([second]);
    expect(first.world).toBeNull();
    expect(() => world.removeJoint(first)).toThrow(/not in this world/);
  });

  it('removing a body removes its joints, with a jointRemoved event', () => {
    const { world, ground, a, b } = chainOfTwo();
    const first = world.addJoint(
      revoluteJoint({ bodyA: ground, bodyB: a, anchor: { x: 0, y: 0 } }),
    );
    const second = world.addJoint(revoluteJoint({ bodyA: a, bodyB: b, anchor: { x: 1, y: 0 } }));
    const removed: Joint[] = [];
    world.on('jointRemoved', (joint) => removed.push(joint));
    world.remove(a);
    expect(removed).toEqual([second, first]);
    expect(world.joints).toEqual([]);
    expect(b.joints).toEqual([]);
    // b now falls freely.
    world.step(DT);
    expect(b.linearVelocity.y).toBeCloseTo(9.81 * DT, 9);
  });

  it('defers addJoint and removeJoint made inside a listener to the end of the step', () => {
    const world = new World();
    const ground = world.add(
      box({ type: 'static', position: { x: 0, y: 0 }, width: 0.2, height: 0.2 }),
    );
    const ball = world.add(particle({ position: { x: 1, y: 0 }, radius: 0.1 }));
    let joint: Joint | null = null;
    const off = world.on('move', () => {
      if (joint === null) {
        joint = world.addJoint(
          revoluteJoint({ bodyA: ground, bodyB: ball, anchor: { x: 0, y: 0 } }),
        );
        expect(world.joints).toEqual([]);
      }
    });
    world.step(DT);
    off();
    expect(world.joints).toEqual([joint]);
    world.on('move', () => {
      if (joint !== null && joint.world !== null) {
        world.removeJoint(joint);
        expect(world.joints).toEqual([joint]);
      }
    });
    world.step(DT);
    expect(world.joints).toEqual([]);
  });

  it('a joint added in a listener to a body added in the same listener joins with it', () => {
    const world = new World();
    const ground = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
    let added = false;
    // Something that moves, so that a 'move' listener runs.
    world.add(particle({ position: { x: 5, y: 0 }, radius: 0.1 }));
    world.on('move', () => {
      if (added) return;
      added = true;
      const ball = world.add(particle({ position: { x: 1, y: 0 }, radius: 0.1 }));
      world.addJoint(revoluteJoint({ bodyA: ground, bodyB: ball, anchor: { x: 0, y: 0 } }));
    });
    world.step(DT);
    expect(world.joints.length).toBe(1);
    for (let i = 0; i < 60; i++) world.step(DT);
    const ball = world.joints[0]!.bodyB;
    expect(Math.hypot(ball.position.x, ball.position.y)).toBeCloseTo(1, 2);
  });

  it('joined bodies do not collide unless collideConnected', () => {
    for (const collideConnected of [false, true]) {
      const world = new World({ gravity: { x: 0, y: 0 } });
      const a = world.add(box({ position: { x: 0, y: 0 }, width: 1, height: 1 }));
      const b = world.add(box({ position: { x: 0.5, y: 0 }, width: 1, height: 1 }));
      world.step(DT); // the overlapping pair touches before the joint exists
      world.addJoint(
        revoluteJoint({ bodyA: a, bodyB: b, anchor: { x: 0.25, y: 0 }, collideConnected }),
      );
      let contacts = 0;
      for (let i = 0; i < 10; i++) world.step(DT);
      world.forEachContact(() => contacts++);
      expect(contacts).toBe(collideConnected ? 1 : 0);
    }
  });

  it('bodies collide again once the joint that kept them apart is removed', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const a = world.add(box({ position: { x: 0, y: 0 }, width: 1, height: 1 }));
    const b = world.add(box({ position: { x: 0.5, y: 0 }, width: 1, height: 1 }));
    const joint = world.addJoint(revoluteJoint({ bodyA: a, bodyB: b, anchor: { x: 0.25, y: 0 } }));
    world.step(DT);
    let contacts = 0;
    world.forEachContact(() => contacts++);
    expect(contacts).toBe(0);
    world.removeJoint(joint);
    world.step(DT);
    world.forEachContact(() => contacts++);
    expect(contacts).toBe(1);
  });

  it('joined bodies sleep together and wake together', () => {
    const world = new World();
    const ground = world.add(
      box({ type: 'static', position: { x: 0, y: 0 }, width: 0.2, height: 0.2 }),
    );
    const a = world.add(box({ position: { x: 0, y: 0.5 }, width: 0.2, height: 1 }));
    const b = world.add(box({ position: { x: 0, y: 1.5 }, width: 0.2, height: 1 }));
    world.addJoint(revoluteJoint({ bodyA: ground, bodyB: a, anchor: { x: 0, y: 0 } }));
    world.addJoint(revoluteJoint({ bodyA: a, bodyB: b, anchor: { x: 0, y: 1 } }));
    for (let i = 0; i < 120; i++) world.step(DT);
    expect(a.isAwake).toBe(false);
    expect(b.isAwake).toBe(false);
    // A push on the lowest link wakes the whole chain, and the chain swings as one.
    b.applyImpulse({ x: 0.5, y: 0 });
    expect(a.isAwake).toBe(true);
    world.step(DT);
    expect(a.angularVelocity).not.toBe(0);
  });

  it('adding or removing a joint wakes its bodies', () => {
    const world = new World();
    const ground = world.add(
      box({ type: 'static', position: { x: 0, y: 2 }, width: 10, height: 1 }),
    );
    const body = world.add(box({ position: { x: 0, y: 1 }, width: 1, height: 1 }));
    for (let i = 0; i < 120; i++) world.step(DT);
    expect(body.isAwake).toBe(false);
    const joint = world.addJoint(
      revoluteJoint({ bodyA: ground, bodyB: body, anchor: { x: 0, y: 1 } }),
    );
    expect(body.isAwake).toBe(true);
    for (let i = 0; i < 120; i++) world.step(DT);
    expect(body.isAwake).toBe(false);
    world.removeJoint(joint);
    expect(body.isAwake).toBe(true);
  });

  it('changing a motor wakes the bodies', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const ground = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
    const wheel = world.add(particle({ radius: 0.5 }));
    const hinge = world.addJoint(
      revoluteJoint({
        bodyA: ground,
        bodyB: wheel,
        anchor: { x: 0, y: 0 },
        enableMotor: true,
        maxMotorTorque: 10,
      }),
    );
    for (let i = 0; i < 60; i++) world.step(DT);
    expect(wheel.isAwake).toBe(false);
    hinge.motorSpeed = 1;
    expect(wheel.isAwake).toBe(true);
    world.step(DT);
    expect(wheel.angularVelocity).toBeCloseTo(1, 6);
  });

  it('a mouse joint can be removed at any time, and the body falls', () => {
    const world = new World();
    const body = world.add(box({ width: 1, height: 1 }));
    const drag = world.addJoint(mouseJoint({ body, target: { x: 0, y: 0 } }));
    for (let i = 0; i < 30; i++) world.step(DT);
    expect(Math.abs(body.position.y)).toBeLessThan(0.02);
    world.removeJoint(drag);
    world.step(DT);
    world.step(DT);
    expect(body.linearVelocity.y).toBeGreaterThan(0.2);
  });
});
