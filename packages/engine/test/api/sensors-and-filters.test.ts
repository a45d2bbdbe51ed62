import { describe, expect, it } from 'vitest';
import { PhysicalError, World, box, particle, wall } from '@physical/engine';
import type { SensorEvent, Body } from '@physical/engine';

interface Record {
  type: string;
  sensor: Body;
  visitor: Body;
}

function record(world: World): Record[] {
  const log: Record[] = [];
  const keep = (type: string) => (e: SensorEvent) =>
    log.push({ type, sensor: e.sensorBody, visitor: e.visitorBody });
  world.on('sensorBegin', keep('begin'));
  world.on('sensorEnd', keep('end'));
  return log;
}

describe('sensors', () => {
  it('report begin and end of overlap, and never push the visitor', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const zone = world.add(
      box({ type: 'static', position: { x: 0, y: 0 }, width: 1, height: 1, sensor: true }),
    );
    const ball = world.add(
      particle({ position: { x: -2, y: 0 }, radius: 0.1, linearVelocity: { x: 2, y: 0 } }),
    );
    const log = record(world);
    let beganAt = -1;
    let endedAt = -1;
    for (let i = 0; i < 150; i++) {
      world.step(1 / 60);
      if (beganAt < 0 && log.length > 0) beganAt = i;
      if (endedAt < 0 && log.length > 1) endedAt = i;
    }
    expect(log.map((r) => r.type)).toEqual(['begin', 'end']);
    expect(log[0]!.sensor).toBe(zone);
    expect(log[0]!.visitor).toBe(ball);
    // It flies straight through at 2 m/s: enters when its edge reaches x = -0.5, i.e. after
    // (2 - 0.5 - 0.1) / 2 = 0.7 s (step 42), leaves at (2 + 0.5 + 0.1) / 2 = 1.3 s (step 78).
    expect(Math.abs(beganAt + 1 - 42)).toBeLessThanOrEqual(1);
    expect(Math.abs(endedAt + 1 - 78)).toBeLessThanOrEqual(1);
    expect(ball.linearVelocity.x).toBe(2);
    expect(ball.linearVelocity.y).toBe(0);
  });

  it('sends events to the sensor body and the visitor body', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const zone = world.add(particle({ type: 'kinematic', radius: 1, sensor: true }));
    const ball = world.add(particle({ position: { x: 0.5, y: 0 }, radius: 0.1 }));
    const onZone: string[] = [];
    const onBall: string[] = [];
    zone.on('sensorBegin', () => onZone.push('begin'));
    ball.on('sensorBegin', () => onBall.push('begin'));
    ball.on('sensorEnd', () => onBall.push('end'));
    world.step();
    expect(onZone).toEqual(['begin']);
    expect(onBall).toEqual(['begin']);
    world.remove(zone); // removing a sensor ends its overlaps
    expect(onBall).toEqual(['begin', 'end']);
  });

  it('do not wake sleeping bodies, make no contacts, and ignore other sensors', () => {
    const world = new World();
    world.add(wall({ from: { x: -5, y: 0 }, to: { x: 5, y: 0 } }));
    const sleeper = world.add(particle({ position: { x: 0, y: -0.5 }, radius: 0.5, asleep: true }));
    const other = world.add(
      particle({ type: 'static', position: { x: 3, y: -1 }, radius: 0.5, sensor: true }),
    );
    const probe = world.add(
      particle({ type: 'kinematic', position: { x: 3, y: -1 }, radius: 0.3, sensor: true }),
    );
    const log = record(world);
    world.step();
    probe.linearVelocity = { x: -60, y: 0 }; // sweeps over the sleeper in 3 steps
    for (let i = 0; i < 10; i++) world.step(1 / 60);
    expect(sleeper.isAwake).toBe(false);
    let contacts = 0;
    world.forEachContact(() => contacts++);
    expect(contacts).toBe(0);
    expect(
      log.some((r) => r.visitor === other || (r.sensor === other && r.visitor === probe)),
    ).toBe(false);
    expect(
      log.filter((r) => r.sensor === probe && r.visitor === sleeper).map((r) => r.type),
    ).toEqual(['begin', 'end']);
  });

  it('rejects a sensor flag that is not a boolean', () => {
    expect(() => particle({ radius: 1, sensor: 'yes' as unknown as boolean })).toThrow(/^sensor: /);
  });
});

describe('collision filters', () => {
  function drop(filterA: object, filterB: object): number {
    const world = new World();
    world.add(box({ type: 'static', position: { x: 0, y: 1 }, width: 4, height: 0.2 }));
    const lower = world.add(
      box({ position: { x: 0, y: 0.5 }, width: 1, height: 0.5, filter: filterA }),
    );
    const upper = world.add(
      box({ position: { x: 0, y: -0.5 }, width: 1, height: 0.5, filter: filterB }),
    );
    for (let i = 0; i < 120; i++) world.step(1 / 60);
    return upper.position.y - lower.position.y;
  }

  // Every filter below keeps category 1 (the floor) in its mask, so the lower box always rests.
  it('category and mask bits decide, both ways', () => {
    // Resting on top: upper centre 0.5 m above the lower one.
    expect(drop({}, {})).toBeCloseTo(-0.5, 1);
    expect(drop({ category: 2 }, { mask: ~2 >>> 0 })).toBeCloseTo(0, 1); // falls into it
    expect(drop({ mask: 1 }, { category: 4 })).toBeCloseTo(0, 1);
    expect(drop({ category: 2, mask: 5 }, { category: 4, mask: 3 })).toBeCloseTo(-0.5, 1);
  });

  it('a shared negative group never collides, a shared positive group always does', () => {
    expect(drop({ group: -1 }, { group: -1 })).toBeCloseTo(0, 1);
    expect(
      drop({ group: 3, category: 2, mask: 1 }, { group: 3, category: 4, mask: 1 }),
    ).toBeCloseTo(-0.5, 1);
    expect(drop({ group: -1 }, { group: -2 })).toBeCloseTo(-0.5, 1);
  });

  it('changing the filter at run time ends forbidden contacts and finds allowed pairs', () => {
    const world = new World();
    world.add(box({ type: 'static', position: { x: 0, y: 1 }, width: 4, height: 0.2 }));
    const crate = world.add(box({ position: { x: 0, y: 0.5 }, width: 1, height: 0.5 }));
    const ends: Body[] = [];
    world.on('contactEnd', (e) => ends.push(e.bodyB));
    for (let i = 0; i < 30; i++) world.step(1 / 60);
    expect(crate.position.y).toBeCloseTo(0.65, 2);
    crate.shapes[0]!.filter = { mask: 0 };
    expect(ends).toContain(crate);
    expect(crate.shapes[0]!.filter).toEqual({ category: 1, mask: 0, group: 0 });
    for (let i = 0; i < 30; i++) world.step(1 / 60);
    expect(crate.position.y).toBeGreaterThan(1.5); // falls through the floor
    crate.position = { x: 0, y: 0.5 };
    crate.shapes[0]!.filter = {};
    for (let i = 0; i < 60; i++) world.step(1 / 60);
    expect(crate.position.y).toBeCloseTo(0.65, 2);
  });

  it('rejects bad bits and groups, naming the field', () => {
    expect(() => box({ width: 1, height: 1, filter: { category: -1 } })).toThrow(
      /^filter\.category: /,
    );
    expect(() => box({ width: 1, height: 1, filter: { mask: 2 ** 32 } })).toThrow(
      /^filter\.mask: /,
    );
    expect(() => box({ width: 1, height: 1, filter: { group: 1.5 } })).toThrow(/^filter\.group: /);
    const body = box({ width: 1, height: 1 });
    expect(() => (body.shapes[0]!.filter = { mask: Number.NaN })).toThrow(PhysicalError);
    expect(() => (body.shapes[0]!.filter = null as unknown as object)).toThrow(/filter/);
  });
});

describe('bullet flag', () => {
  it('is an option and a property, and rejects non-booleans', () => {
    const shot = particle({ radius: 0.1, bullet: true });
    expect(shot.bullet).toBe(true);
    shot.bullet = false;
    expect(shot.bullet).toBe(false);
    expect(particle({ radius: 0.1 }).bullet).toBe(false);
    expect(() => particle({ radius: 0.1, bullet: 1 as unknown as boolean })).toThrow(/^bullet: /);
    expect(() => (shot.bullet = 'yes' as unknown as boolean)).toThrow(PhysicalError);
  });
});
