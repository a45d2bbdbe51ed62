import { describe, expect, it } from 'vitest';
import { World, box, distanceJoint, prismaticJoint, revoluteJoint, wall } from '@physical/engine';
import { physicalErrorOf } from './expect-physical-error.ts';

// Finding 6: a flag is true or false; a string, a number or null is refused, in options and setters.

const notBooleans: unknown[] = ['no', 0, 1, null, {}];

function bodies(): { world: World; a: ReturnType<typeof box>; b: ReturnType<typeof box> } {
  const world = new World();
  const a = world.add(wall({ from: { x: -5, y: 0 }, to: { x: 5, y: 0 } }));
  const b = world.add(box({ position: { x: 0, y: -2 }, width: 1, height: 1 }));
  return { world, a: a as ReturnType<typeof box>, b };
}

describe('flags must be booleans', () => {
  it.each(notBooleans)('body options refuse %s', (value) => {
    for (const flag of ['fixedRotation', 'allowSleep', 'bullet', 'asleep']) {
      const error = physicalErrorOf(() => box({ width: 1, height: 1, [flag]: value }));
      expect(error.field).toBe(flag);
    }
  });

  it.each(notBooleans)('body setters refuse %s and keep the flag', (value) => {
    const { b } = bodies();
    for (const flag of ['fixedRotation', 'allowSleep', 'bullet'] as const) {
      const before = b[flag];
      const error = physicalErrorOf(() => {
        (b as unknown as Record<string, unknown>)[flag] = value;
      });
      expect(error.field).toBe(flag);
      expect(b[flag]).toBe(before);
    }
  });

  it.each(notBooleans)('world options and setters refuse %s', (value) => {
    expect(physicalErrorOf(() => new World({ enableSleep: value as boolean })).field).toBe(
      'enableSleep',
    );
    expect(physicalErrorOf(() => new World({ enableContinuous: value as boolean })).field).toBe(
      'enableContinuous',
    );
    const world = new World();
    physicalErrorOf(() => {
      (world as unknown as Record<string, unknown>).enableSleep = value;
    });
    expect(world.enableSleep).toBe(true);
  });

  it.each(notBooleans)('joint options and setters refuse %s', (value) => {
    const { a, b } = bodies();
    const anchor = { x: 0, y: -2 };
    expect(
      physicalErrorOf(() =>
        revoluteJoint({ bodyA: a, bodyB: b, anchor, collideConnected: value as boolean }),
      ).field,
    ).toBe('collideConnected');
    for (const flag of ['enableLimit', 'enableMotor', 'enableSpring']) {
      expect(
        physicalErrorOf(() => revoluteJoint({ bodyA: a, bodyB: b, anchor, [flag]: value })).field,
      ).toBe(flag);
      expect(
        physicalErrorOf(() =>
          prismaticJoint({ bodyA: a, bodyB: b, anchor, axis: { x: 1, y: 0 }, [flag]: value }),
        ).field,
      ).toBe(flag);
    }
    const joint = revoluteJoint({ bodyA: a, bodyB: b, anchor });
    for (const flag of ['enableLimit', 'enableMotor', 'enableSpring'] as const) {
      physicalErrorOf(() => {
        (joint as unknown as Record<string, unknown>)[flag] = value;
      });
      expect(joint[flag]).toBe(false);
    }
    const spring = distanceJoint({ bodyA: a, bodyB: b, anchorA: { x: 0, y: 0 }, anchorB: anchor });
    physicalErrorOf(() => {
      (spring as unknown as Record<string, unknown>).enableSpring = value;
    });
    expect(spring.enableSpring).toBe(false);
  });

  it('shape options refuse a non-boolean sensor or oneSided', () => {
    physicalErrorOf(() => box({ width: 1, height: 1, sensor: 'yes' as unknown as boolean }));
    physicalErrorOf(() =>
      wall({ from: { x: 0, y: 0 }, to: { x: 1, y: 0 }, oneSided: 1 as unknown as boolean }),
    );
  });
});
