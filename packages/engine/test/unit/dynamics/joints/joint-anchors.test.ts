import { describe, expect, it } from 'vitest';
import {
  type Joint,
  World,
  box,
  distanceJoint,
  mouseJoint,
  particle,
  prismaticJoint,
  revoluteJoint,
  weldJoint,
} from '@physical/engine';

// joint.anchorA / anchorB: the joint's points on its bodies in world coordinates, from the
// bodies' current poses (what a renderer draws), as reused read-only views.

const DT = 1 / 60;

function pair() {
  const world = new World({ enableSleep: false });
  const ceiling = world.add(
    box({ type: 'static', position: { x: 0, y: 0 }, width: 4, height: 0.2 }),
  );
  const bob = world.add(box({ position: { x: 2, y: 1 }, width: 0.4, height: 0.4 }));
  return { world, ceiling, bob };
}

function expectPoint(point: { x: number; y: number }, x: number, y: number): void {
  expect(point.x).toBeCloseTo(x, 12);
  expect(point.y).toBeCloseTo(y, 12);
}

describe('joint anchors in world coordinates', () => {
  it('start where each factory was told, for every two-body joint', () => {
    const { ceiling, bob } = pair();
    const at = { x: 1.5, y: 0.5 };
    const joints: Joint[] = [
      revoluteJoint({ bodyA: ceiling, bodyB: bob, anchor: at }),
      prismaticJoint({ bodyA: ceiling, bodyB: bob, anchor: at, axis: { x: 1, y: 0 } }),
      weldJoint({ bodyA: ceiling, bodyB: bob, anchor: at }),
    ];
    for (const joint of joints) {
      expectPoint(joint.anchorA, 1.5, 0.5);
      expectPoint(joint.anchorB, 1.5, 0.5);
    }
    const rod = distanceJoint({
      bodyA: ceiling,
      bodyB: bob,
      anchorA: { x: -1, y: 0.1 },
      anchorB: { x: 2.2, y: 1.2 },
    });
    expectPoint(rod.anchorA, -1, 0.1);
    expectPoint(rod.anchorB, 2.2, 1.2);
  });

  it('move rigidly with their body: a quarter turn about the centre turns the anchor with it', () => {
    const { ceiling, bob } = pair();
    const rod = distanceJoint({
      bodyA: ceiling,
      bodyB: bob,
      anchorA: { x: 0, y: 0 },
      anchorB: { x: 2.2, y: 1 }, // 0.2 m along the box's +x
    });
    bob.angle = Math.PI / 2;
    // +x turned a quarter turn is +y: the anchor is now 0.2 m along +y from the centre.
    expectPoint(rod.anchorB, 2, 1.2);
    bob.position = { x: -3, y: 4 };
    expectPoint(rod.anchorB, -3, 4.2);
    expectPoint(rod.anchorA, 0, 0);
  });

  it('of a stepped pendulum hinge stay together (under 1 mm) and on the bob (0.5 m away)', () => {
    const world = new World({ enableSleep: false });
    const pivot = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
    const bob = world.add(particle({ position: { x: 0.5, y: 0 }, radius: 0.1 }));
    const hinge = world.addJoint(
      revoluteJoint({ bodyA: pivot, bodyB: bob, anchor: { x: 0, y: 0 } }),
    );
    for (let i = 0; i < 20; i++) world.step(DT);
    expect(bob.position.y, 'the bob swung down').toBeGreaterThan(0.3);
    const a = hinge.anchorA;
    const b = hinge.anchorB;
    expect(Math.hypot(a.x - b.x, a.y - b.y)).toBeLessThan(1e-3);
    expect(Math.hypot(b.x - bob.position.x, b.y - bob.position.y)).toBeCloseTo(0.5, 12);
  });

  it('of a mouse joint are the target (A) and the pulled point of the body (B)', () => {
    const { bob } = pair();
    const drag = mouseJoint({ body: bob, target: { x: 2.1, y: 1.1 } });
    expectPoint(drag.anchorA, 2.1, 1.1);
    expectPoint(drag.anchorB, 2.1, 1.1);
    drag.target = { x: 5, y: 6 };
    expectPoint(drag.anchorA, 5, 6);
    expectPoint(drag.anchorB, 2.1, 1.1);
  });

  it('are reused views: the same object on every read, updated in place', () => {
    const { ceiling, bob } = pair();
    const weld = weldJoint({ bodyA: ceiling, bodyB: bob, anchor: { x: 2, y: 1 } });
    const first = weld.anchorB;
    bob.position = { x: 3, y: 1 };
    expect(weld.anchorB).toBe(first);
    expectPoint(first, 3, 1);
    expect(weld.anchorA).not.toBe(first);
  });
});
