import { describe, expect, it } from 'vitest';
import {
  PhysicalError,
  World,
  box,
  capsule,
  particle,
  polygon,
  restoreSnapshot,
  takeSnapshot,
  wall,
} from '@physical/engine';
import type { WorldSnapshot } from '@physical/engine';

/**
 * A pyramid, falling particles, capsules and a concave L, a sleeping stack, timed forces, a sensor,
 * a bullet, a removal.
 */
function busyWorld(): World {
  const world = new World();
  world.add(wall({ from: { x: -20, y: 0 }, to: { x: 20, y: 0 } }));
  const rows = 8;
  for (let row = 0; row < rows; row++) {
    for (let i = 0; i < rows - row; i++) {
      world.add(
        box({
          position: { x: -4 + i * 1.02 + row * 0.51, y: -0.5 - row * 1.0 },
          width: 1,
          height: 1,
        }),
      );
    }
  }
  for (let i = 0; i < 3; i++) {
    world.add(
      box({ position: { x: 12, y: -0.25 - 0.5 * i }, width: 0.5, height: 0.5, asleep: true }),
    );
  }
  for (let i = 0; i < 12; i++) {
    const ball = world.add(
      particle({
        position: { x: -8 + 1.3 * i, y: -12 - (i % 3) },
        radius: 0.2 + 0.02 * i,
        restitution: 0.3,
        angularVelocity: i - 6,
        filter: i % 4 === 0 ? { group: -1 } : {},
      }),
    );
    if (i % 3 === 0)
      ball.applyForce({ x: 3, y: -1 }, { duration: 1.5, point: { x: -8 + 1.3 * i + 0.1, y: -12 } });
  }
  for (let i = 0; i < 3; i++) {
    world.add(
      capsule({
        position: { x: 4 + i, y: -6 - i },
        length: 0.6,
        radius: 0.15 + 0.05 * i,
        angle: i,
      }),
    );
  }
  world.add(
    polygon({
      position: { x: 16, y: -4 },
      vertices: [
        { x: 0, y: 0 },
        { x: 1.5, y: 0 },
        { x: 1.5, y: -0.4 },
        { x: 0.4, y: -0.4 },
        { x: 0.4, y: -1.5 },
        { x: 0, y: -1.5 },
      ],
    }),
  );
  world.add(box({ type: 'static', position: { x: 8, y: -1 }, width: 2, height: 2, sensor: true }));
  world.add(
    particle({
      position: { x: -15, y: -3 },
      radius: 0.05,
      bullet: true,
      linearVelocity: { x: 80, y: 0 },
    }),
  );
  const doomed = world.add(particle({ position: { x: 15, y: -3 }, radius: 0.3 }));
  world.step();
  world.remove(doomed);
  return world;
}

function state(world: World): number[] {
  const out: number[] = [];
  for (const body of world.bodies) {
    out.push(
      body.position.x,
      body.position.y,
      body.angle,
      body.linearVelocity.x,
      body.linearVelocity.y,
    );
    out.push(body.angularVelocity, body.isAwake ? 1 : 0);
  }
  return out;
}

function sameBits(a: number[], b: number[]): boolean {
  return a.length === b.length && a.every((x, i) => Object.is(x, b[i]));
}

describe('snapshots', () => {
  it('restoring through JSON and stepping 1,000 times gives bit-for-bit the same states', () => {
    const original = busyWorld();
    for (let i = 0; i < 120; i++) original.step(1 / 60);
    const saved = JSON.stringify(takeSnapshot(original));
    const restored = restoreSnapshot(JSON.parse(saved) as WorldSnapshot);
    expect(restored.bodies.length).toBe(original.bodies.length);
    expect(restored.steps).toBe(original.steps);
    let sleepingSeen = false;
    for (let i = 0; i < 1000; i++) {
      original.step(1 / 60);
      restored.step(1 / 60);
      if (i % 50 === 0) expect(sameBits(state(restored), state(original))).toBe(true);
      if (original.bodies.some((b) => b.type === 'dynamic' && !b.isAwake)) sleepingSeen = true;
    }
    expect(sleepingSeen).toBe(true);
    expect(sameBits(state(restored), state(original))).toBe(true);
    // Every internal the snapshot holds agrees too (contacts, trees, timers).
    expect(JSON.stringify(takeSnapshot(restored))).toBe(JSON.stringify(takeSnapshot(original)));
  }, 30_000);

  it('reads a version 1 snapshot (contacts without their bouncing count) as not bouncing', () => {
    const original = busyWorld();
    for (let i = 0; i < 120; i++) original.step(1 / 60);
    const saved = JSON.parse(JSON.stringify(takeSnapshot(original))) as {
      version: number;
      contacts: { data: unknown[] }[];
    };
    expect(saved.version).toBe(2);
    expect(saved.contacts.length).toBeGreaterThan(10);
    // Version 1's contact data: the same slot without index 22 (BOUNCING_STEPS), read as 0.
    for (const contact of saved.contacts) contact.data[22] = 0;
    const v1 = structuredClone(saved);
    v1.version = 1;
    for (const contact of v1.contacts) contact.data.splice(22, 1);
    const fromV1 = restoreSnapshot(v1 as unknown as WorldSnapshot);
    const fromV2 = restoreSnapshot(saved as unknown as WorldSnapshot);
    for (let i = 0; i < 200; i++) {
      fromV1.step(1 / 60);
      fromV2.step(1 / 60);
    }
    expect(sameBits(state(fromV1), state(fromV2))).toBe(true);
    expect(JSON.stringify(takeSnapshot(fromV1))).toBe(JSON.stringify(takeSnapshot(fromV2)));
    // A version 1 slot of version 2's length is refused, naming the field.
    const wrong = structuredClone(saved);
    wrong.version = 1;
    expect(() => restoreSnapshot(wrong as unknown as WorldSnapshot)).toThrow(
      /snapshot\.contacts\[0\]\.data: .*42/,
    );
  });

  it('restores a world saved before its first step, and sensor overlaps without repeating begins', () => {
    const early = new World();
    early.add(particle({ radius: 0.5, position: { x: 0, y: -3 } }));
    early.add(box({ type: 'static', position: { x: 0, y: 0 }, width: 4, height: 4, sensor: true }));
    const copyEarly = restoreSnapshot(
      JSON.parse(JSON.stringify(takeSnapshot(early))) as WorldSnapshot,
    );
    const begins = [0, 0];
    early.on('sensorBegin', () => begins[0]!++);
    copyEarly.on('sensorBegin', () => begins[1]!++);
    for (let i = 0; i < 60; i++) {
      early.step(1 / 60);
      copyEarly.step(1 / 60);
      if (i === 30) {
        // Saved while the ball is inside the sensor: the copy must not report it entering again.
        const mid = restoreSnapshot(
          JSON.parse(JSON.stringify(takeSnapshot(early))) as WorldSnapshot,
        );
        let again = 0;
        mid.on('sensorBegin', () => again++);
        mid.step(1 / 60);
        expect(again).toBe(0);
      }
    }
    expect(begins).toEqual([1, 1]);
    expect(sameBits(state(copyEarly), state(early))).toBe(true);
  });

  it('keeps -0, infinite force durations and a JSON round trip exact', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const ball = world.add(particle({ radius: 0.5, linearVelocity: { x: -0, y: 0 } }));
    ball.applyForce({ x: 1, y: 0 }, { duration: 'constant' });
    world.step();
    ball.linearVelocity = { x: -0, y: 0 };
    const snap = JSON.parse(JSON.stringify(takeSnapshot(world))) as WorldSnapshot;
    const copy = restoreSnapshot(snap);
    expect(Object.is(copy.bodies[0]!.linearVelocity.x, -0)).toBe(true);
    expect(copy.bodies[0]!.forces[0]!.remaining).toBe(Infinity);
    copy.step();
    world.step();
    expect(copy.bodies[0]!.linearVelocity.x).toBe(ball.linearVelocity.x);
  });

  it('takes no snapshot while stepping', () => {
    const world = new World();
    world.add(particle({ radius: 0.5 }));
    let error: unknown = null;
    world.on('move', () => {
      try {
        takeSnapshot(world);
      } catch (e) {
        error = e;
      }
    });
    world.step();
    expect(error).toBeInstanceOf(PhysicalError);
    expect(String(error)).toMatch(/snapshot.*while the world is stepping/);
    // After the step it is allowed again.
    expect(takeSnapshot(world).bodies).toHaveLength(1);
  });
});

describe('bad snapshots', () => {
  function good(): Record<string, unknown> {
    return JSON.parse(JSON.stringify(takeSnapshot(busyWorld()))) as Record<string, unknown>;
  }
  function load(snap: unknown): () => World {
    return () => restoreSnapshot(snap as WorldSnapshot);
  }
  type Mutable = Record<string, unknown> & {
    bodies: Record<string, unknown>[];
    contacts: Record<string, unknown>[];
  };

  it('names a wrong format or version', () => {
    expect(load({ ...good(), format: 'box2d' })).toThrow(/snapshot\.format.*'box2d'/);
    expect(load({ ...good(), version: 3 })).toThrow(/snapshot\.version.*1 or 2.*got 3/);
    expect(load(null)).toThrow(/snapshot/);
    expect(load('physical-world')).toThrow(PhysicalError);
  });

  it('names a missing field, a NaN, a wrong type', () => {
    const missing = good() as Mutable;
    delete missing.bodies[3]!['velocity'];
    expect(load(missing)).toThrow(/snapshot\.bodies\[3\]\.velocity: is missing/);
    const nan = good() as Mutable;
    (nan.bodies[2]!['transform'] as unknown[])[1] = Number.NaN;
    expect(load(nan)).toThrow(/snapshot\.bodies\[2\]\.transform\[1\]: must be a number, got NaN/);
    const viaJson = good() as Mutable;
    viaJson.bodies[2]!['angle'] = null; // what JSON makes of NaN
    expect(load(viaJson)).toThrow(/snapshot\.bodies\[2\]\.angle: must be a number, got null/);
    const settings = good();
    (settings['settings'] as Record<string, unknown>)['subSteps'] = 0;
    expect(load(settings)).toThrow(/snapshot\.settings\.subSteps/);
    const shape = good() as Mutable;
    (
      (shape.bodies[5]!['shapes'] as Record<string, unknown>[])[0]!['geometry'] as Record<
        string,
        unknown
      >
    )['kind'] = 'star';
    expect(load(shape)).toThrow(/snapshot\.bodies\[5\]\.shapes\[0\]\.geometry\.kind/);
    // A contact marked touching must hold manifold points, and the other way round.
    const touching = good() as Mutable;
    const at = touching.contacts.findIndex((c) => c['touching'] === true);
    touching.contacts[at]!['touching'] = false;
    expect(load(touching)).toThrow(
      new RegExp(`snapshot\\.contacts\\[${at}\\]\\.touching: must be true`),
    );
  });

  it('names bad references', () => {
    const contact = good() as Mutable;
    contact.contacts[0]!['shapes'] = [0, 9999];
    expect(load(contact)).toThrow(/snapshot\.contacts\[0\]\.shapes/);
    const list = good() as Mutable;
    const withContacts = list.bodies.findIndex((b) => (b['contacts'] as unknown[]).length > 0);
    list.bodies[withContacts]!['contacts'] = [];
    expect(load(list)).toThrow(/snapshot\.contacts\[\d+\]: is missing from the contact list/);
    const tree = good();
    const trees = (tree['broadPhase'] as Record<string, unknown>)['trees'] as Record<
      string,
      unknown
    >[];
    trees[2]!['root'] = 0;
    expect(load(tree)).toThrow(/snapshot\.broadPhase\.trees\[2\]/);
    const ids = good() as Mutable;
    ids.bodies[4]!['id'] = ids.bodies[3]!['id'];
    expect(load(ids)).toThrow(/snapshot\.bodies\[4\]\.id/);
  });

  it('names a bad capsule', () => {
    const snap = good() as Mutable;
    const k = snap.bodies.findIndex(
      (b) =>
        ((b['shapes'] as Record<string, unknown>[])[0]!['geometry'] as Record<string, unknown>)[
          'kind'
        ] === 'capsule',
    );
    expect(k).toBeGreaterThan(0);
    const geometry = (): Record<string, unknown> =>
      (snap.bodies[k]!['shapes'] as Record<string, unknown>[])[0]!['geometry'] as Record<
        string,
        unknown
      >;
    const center = geometry()['center2'];
    geometry()['center2'] = [1];
    expect(load(snap)).toThrow(
      new RegExp(`snapshot\\.bodies\\[${k}\\]\\.shapes\\[0\\]\\.geometry\\.center2: must hold 2`),
    );
    geometry()['center2'] = center;
    geometry()['radius'] = 0;
    expect(load(snap)).toThrow(new RegExp(`snapshot\\.bodies\\[${k}\\]\\.shapes\\[0\\]\\.radius`));
  });

  it("names a contact's data slot of the wrong length or with 3 points", () => {
    const short = good() as Mutable;
    const data = short.contacts[0]!['data'] as unknown[];
    short.contacts[0]!['data'] = data.slice(0, data.length - 1);
    expect(load(short)).toThrow(
      new RegExp(`snapshot\\.contacts\\[0\\]\\.data: must hold ${data.length} entries`),
    );
    const three = good() as Mutable;
    (three.contacts[0]!['data'] as unknown[])[2] = 3; // the point count (contact-data.ts)
    expect(load(three)).toThrow(
      /snapshot\.contacts\[0\]\.data\[2\]: must be a whole number from 0 to 2, got 3/,
    );
  });

  it('names a missing joints section (joint entries: snapshot-joints.test.ts)', () => {
    const snap = good();
    delete snap['joints'];
    expect(load(snap)).toThrow('snapshot.joints: is missing.');
  });
});
