import { describe, expect, it } from 'vitest';
import {
  World,
  box,
  capsule,
  distanceJoint,
  mouseJoint,
  particle,
  polygon,
  prismaticJoint,
  regularPolygon,
  revoluteJoint,
  wall,
  weldJoint,
} from '@physical/engine';
import { physicalErrorOf } from './expect-physical-error.ts';

// A refused value is named as the user wrote it: the factory's option (capsule's `length`, box's
// `width`), not the shape the factory built from it (`shapes[0].center1.x`); a setter names the
// field it sets (`slide.upper = -5` names `upper`). And a field that is read-only in the typings
// is read-only at run time: a write from plain JavaScript throws a PhysicalError naming it, and
// changes nothing.

describe('factory errors name the option', () => {
  const cases: [string, () => unknown, string][] = [
    ['capsule length 1e300', () => capsule({ length: 1e300, radius: 0.1 }), 'length'],
    ['capsule radius', () => capsule({ length: 1, radius: -1 }), 'radius'],
    ['box width', () => box({ width: -1, height: 1 }), 'width'],
    ['box height', () => box({ width: 1, height: Number.NaN }), 'height'],
    ['box rounding', () => box({ width: 1, height: 1, radius: -1 }), 'radius'],
    ['box density', () => box({ width: 1, height: 1, density: -1 }), 'density'],
    ['box friction', () => box({ width: 1, height: 1, friction: Number.NaN }), 'friction'],
    ['particle radius', () => particle({ radius: 1e9 }), 'radius'],
    ['particle sensor', () => particle({ radius: 1, sensor: 1 as never }), 'sensor'],
    [
      'polygon vertex',
      () =>
        polygon({
          vertices: [
            { x: 0, y: 0 },
            { x: Number.NaN, y: 0 },
            { x: 0, y: 1 },
          ],
        }),
      'vertices[1].x',
    ],
    ['regularPolygon radius', () => regularPolygon({ sides: 5, radius: -2 }), 'radius'],
    ['regularPolygon tiny', () => regularPolygon({ sides: 5, radius: 1e-9 }), 'radius'],
    ['wall from', () => wall({ from: { x: 1e300, y: 0 }, to: { x: 0, y: 0 } }), 'from.x'],
  ];
  it.each(cases)('%s', (_name, build, field) => {
    const error = physicalErrorOf(build);
    expect(error.field).toBe(field);
    expect(error.message.startsWith(`${field}: `)).toBe(true);
    expect(error.message).not.toContain('shapes[');
  });
});

describe('setters of ordered limits name the limit set', () => {
  function joined(): { world: World; a: ReturnType<typeof box>; b: ReturnType<typeof box> } {
    const world = new World();
    const a = world.add(box({ width: 1, height: 1 }));
    const b = world.add(box({ width: 1, height: 1, position: { x: 2, y: 0 } }));
    return { world, a, b };
  }

  it('prismatic lower and upper', () => {
    const { a, b } = joined();
    const slide = prismaticJoint({
      bodyA: a,
      bodyB: b,
      anchor: { x: 1, y: 0 },
      axis: { x: 1, y: 0 },
      enableLimit: true,
      lower: 0,
      upper: 1,
    });
    expect(physicalErrorOf(() => (slide.upper = -5)).field).toBe('upper');
    expect(physicalErrorOf(() => (slide.lower = 5)).field).toBe('lower');
    expect([slide.lower, slide.upper]).toEqual([0, 1]);
  });

  it('revolute lowerAngle and upperAngle', () => {
    const { a, b } = joined();
    const hinge = revoluteJoint({ bodyA: a, bodyB: b, anchor: { x: 1, y: 0 } });
    hinge.setLimits(-1, 1);
    expect(physicalErrorOf(() => (hinge.upperAngle = -2)).field).toBe('upperAngle');
    expect(physicalErrorOf(() => (hinge.lowerAngle = 2)).field).toBe('lowerAngle');
    expect([hinge.lowerAngle, hinge.upperAngle]).toEqual([-1, 1]);
  });
});

describe('fields read-only in the typings are read-only at run time', () => {
  it('Body, Shape, Joint kinds and Force', () => {
    const world = new World();
    const a = world.add(box({ width: 1, height: 1 }));
    const b = world.add(box({ width: 1, height: 1, position: { x: 2, y: 0 } }));
    const shape = a.shapes[0]!;
    const force = a.applyForce({ x: 1, y: 0 }, { duration: 2 });
    const joints = [
      world.addJoint(revoluteJoint({ bodyA: a, bodyB: b, anchor: { x: 1, y: 0 } })),
      world.addJoint(weldJoint({ bodyA: a, bodyB: b, anchor: { x: 1, y: 0 } })),
      world.addJoint(
        distanceJoint({ bodyA: a, bodyB: b, anchorA: { x: 0, y: 0 }, anchorB: { x: 2, y: 0 } }),
      ),
      world.addJoint(
        prismaticJoint({ bodyA: a, bodyB: b, anchor: { x: 1, y: 0 }, axis: { x: 1, y: 0 } }),
      ),
      world.addJoint(mouseJoint({ body: b, target: { x: 2, y: 0 } })),
    ];
    const writes: [object, string][] = [
      [a, 'type'],
      [shape, 'sensor'],
      [shape, 'density'],
      [shape, 'body'],
      [shape, 'geometry'],
      [force, 'duration'],
    ];
    for (const joint of joints) {
      for (const key of ['bodyA', 'bodyB', 'type', 'collideConnected']) writes.push([joint, key]);
    }
    for (const [object, key] of writes) {
      const before = (object as Record<string, unknown>)[key];
      const error = physicalErrorOf(() => {
        (object as Record<string, unknown>)[key] = key === 'type' ? 'static' : b;
      });
      expect(error.field).toBe(key);
      expect((object as Record<string, unknown>)[key]).toBe(before);
    }
    // The world still agrees with itself: every joint is on both its bodies' lists.
    expect(a.joints.length).toBe(4);
    expect(b.joints.length).toBe(5);
    for (let i = 0; i < 10; i++) world.step();
    expect(Number.isFinite(b.position.x)).toBe(true);
  });
});
