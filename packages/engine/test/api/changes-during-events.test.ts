import { describe, expect, it } from 'vitest';
import {
  World,
  box,
  particle,
  type Body,
  type BodyEvents,
  type CollisionEvent,
  type ContactEvent,
  type SensorEvent,
} from '@physical/engine';
import { physicalErrorOf } from './expect-physical-error.ts';

// One model of changes made during a step or an event (the engine README, "Changes made during a
// step or an event"), checked for every event a step delivers: while a change is queued, `has`
// and `body.world` already report it; remove then add (or add then remove) cancel; a body queued
// for removal gets no more events on its own listeners; a listener that throws still lets the
// queued changes apply before the error reaches the caller.

type Kind = keyof BodyEvents | 'wake';

interface Scene {
  readonly world: World;
  /** The body the event names. */
  readonly body: Body;
}

/** Bodies an event names. */
function named(kind: Kind, event: unknown): Body[] {
  switch (kind) {
    case 'move':
    case 'wake':
      return [event as Body];
    case 'sensorBegin':
    case 'sensorEnd':
      return [(event as SensorEvent).sensorBody, (event as SensorEvent).visitorBody];
    default:
      return [(event as CollisionEvent | ContactEvent).bodyA, (event as ContactEvent).bodyB];
  }
}

/** A scene in which, within 120 steps of 1/60 s, a step delivers `kind` naming `body`. */
function scene(kind: Kind): Scene {
  const world = new World({ gravity: { x: 0, y: 10 } });
  world.add(box({ type: 'static', position: { x: 0, y: 5 }, width: 20, height: 1 }));
  switch (kind) {
    case 'contactEnd': {
      // Rests on the ground, then is thrown up: the contact ends during a step.
      const body = world.add(particle({ position: { x: 0, y: 4 }, radius: 0.5 }));
      for (let i = 0; i < 10; i++) world.step();
      body.linearVelocity = { x: 0, y: -6 };
      return { world, body };
    }
    case 'sensorBegin':
    case 'sensorEnd': {
      world.gravity = { x: 0, y: 0 };
      const zone = world.add(
        particle({ type: 'kinematic', position: { x: 0, y: 0 }, radius: 0.5, sensor: true }),
      );
      const body = world.add(
        particle({ position: { x: -1, y: 0 }, radius: 0.1, linearVelocity: { x: 3, y: 0 } }),
      );
      void zone;
      return { world, body };
    }
    case 'wake': {
      // A sleeping ball on the ground, woken by another falling onto it.
      const body = world.add(particle({ position: { x: 0, y: 4 }, radius: 0.5, asleep: true }));
      world.add(particle({ position: { x: 0, y: 2 }, radius: 0.5 }));
      return { world, body };
    }
    default: {
      const body = world.add(particle({ position: { x: 0, y: 3 }, radius: 0.5 }));
      return { world, body };
    }
  }
}

const KINDS: Kind[] = [
  'collision',
  'contactBegin',
  'contactEnd',
  'sensorBegin',
  'sensorEnd',
  'move',
  'wake',
];
const BODY_KINDS: (keyof BodyEvents)[] = [
  'collision',
  'contactBegin',
  'contactEnd',
  'sensorBegin',
  'sensorEnd',
  'move',
];

/** Listens to `kind` on the world (one listener type for every kind). */
function listen(world: World, kind: Kind, listener: (event: unknown) => void): void {
  world.on(kind, listener as never);
}

/** Steps until `done()` or 120 steps; returns whether done. */
function stepUntil(world: World, done: () => boolean): boolean {
  for (let i = 0; i < 120 && !done(); i++) world.step(1 / 60);
  return done();
}

describe.each(KINDS)('changes made from a %s listener', (kind) => {
  it('remove(b) then add(b) cancel: b stays in the world, and has/world say so at once', () => {
    const { world, body } = scene(kind);
    let seen = false;
    const log: string[] = [];
    listen(world, kind, (event) => {
      if (seen || !named(kind, event).includes(body)) return;
      seen = true;
      world.remove(body);
      log.push(`removed: has ${world.has(body)}, world ${body.world === null ? 'null' : 'set'}`);
      world.add(body);
      log.push(`added: has ${world.has(body)}, world ${body.world === world ? 'this' : 'other'}`);
    });
    expect(stepUntil(world, () => seen)).toBe(true);
    expect(log).toEqual(['removed: has false, world null', 'added: has true, world this']);
    expect(world.has(body)).toBe(true);
    expect(body.world).toBe(world);
    expect(world.bodies.filter((b) => b === body).length).toBe(1);
    for (let i = 0; i < 30; i++) world.step(1 / 60);
    expect(world.has(body)).toBe(true);
    world.remove(body); // removable once, as any body in the world
    expect(world.has(body)).toBe(false);
  });

  it('add(b) then remove(b) cancel: b never joins', () => {
    const { world, body } = scene(kind);
    const extra = particle({ position: { x: 8, y: 0 }, radius: 0.2 });
    let seen = false;
    listen(world, kind, (event) => {
      if (seen || !named(kind, event).includes(body)) return;
      seen = true;
      world.add(extra);
      expect(world.has(extra)).toBe(true);
      expect(extra.world).toBe(world);
      world.remove(extra);
      expect(world.has(extra)).toBe(false);
      expect(extra.world).toBeNull();
    });
    expect(stepUntil(world, () => seen)).toBe(true);
    expect(world.bodies).not.toContain(extra);
    expect(extra.world).toBeNull();
  });

  it('a body removed by a world listener gets no more events on its own listeners', () => {
    const { world, body } = scene(kind);
    let removed = false;
    listen(world, kind, (event) => {
      if (!removed && named(kind, event).includes(body)) {
        world.remove(body);
        removed = true;
        expect(body.world).toBeNull();
      }
    });
    const after: string[] = [];
    for (const type of BODY_KINDS) {
      body.on(type, () => {
        if (removed) after.push(type);
      });
    }
    // A second world listener of the same kind: an event naming a body queued for removal stops
    // there (ends excepted: every begin gets its end).
    const later: string[] = [];
    listen(world, kind, (event) => {
      if (removed && named(kind, event).includes(body)) later.push(kind);
    });
    expect(stepUntil(world, () => removed)).toBe(true);
    for (let i = 0; i < 10; i++) world.step(1 / 60);
    expect(after).toEqual([]);
    if (kind !== 'contactEnd' && kind !== 'sensorEnd') expect(later).toEqual([]);
    expect(world.bodies).not.toContain(body);
  });

  it('a listener that queues remove(b) and throws leaves the world consistent', () => {
    const { world, body } = scene(kind);
    let thrown = false;
    listen(world, kind, (event) => {
      if (thrown || !named(kind, event).includes(body)) return;
      thrown = true;
      world.remove(body);
      throw new Error('listener failed');
    });
    let caught: unknown = null;
    for (let i = 0; i < 120 && !thrown; i++) {
      try {
        world.step(1 / 60);
      } catch (error) {
        caught = error;
      }
    }
    expect((caught as Error | null)?.message).toBe('listener failed');
    // The removal applied at the deferred point, before the error reached the caller.
    expect(world.has(body)).toBe(false);
    expect(body.world).toBeNull();
    expect(world.bodies).not.toContain(body);
    expect(world.isStepping).toBe(false);
    // Removing it again is removing twice, refused as always; adding it back works.
    expect(physicalErrorOf(() => world.remove(body)).message).toContain('not in this world');
    world.add(body);
    expect(world.has(body)).toBe(true);
    for (let i = 0; i < 60; i++) world.step(1 / 60);
    expect(Number.isFinite(body.position.y)).toBe(true);
  });
});

describe('changes made from listeners outside a step', () => {
  it('a contactEnd listener that throws while a body is removed still lets the removal finish', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    const ground = world.add(
      box({ type: 'static', position: { x: 0, y: 5 }, width: 20, height: 1 }),
    );
    const ball = world.add(particle({ position: { x: 0, y: 4 }, radius: 0.5 }));
    const other = world.add(particle({ position: { x: 3, y: 4 }, radius: 0.5 }));
    for (let i = 0; i < 20; i++) world.step(1 / 60);
    world.on('contactEnd', () => {
      world.remove(other);
      throw new Error('end listener failed');
    });
    expect(() => world.remove(ground)).toThrow('end listener failed');
    expect(world.has(ground)).toBe(false);
    expect(world.has(other)).toBe(false);
    expect(world.bodies).toEqual([ball]);
    expect(other.world).toBeNull();
  });
});
