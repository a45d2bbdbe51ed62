import { describe, expect, it } from 'vitest';
import { World, box, particle, restoreSnapshot, takeSnapshot, wall } from '@physical/engine';

// Each body's contacts are a linked list of edges in flat memory (contact-edges.ts): a contact's
// end unlinks its two edges and moves the last slot into its place, renaming that contact's edges.
// A list that lost or kept a wrong key would hide a contact from the island search (a pile that
// sleeps while something still rests on it) or wake the wrong body.

type Internals = ReturnType<World['internals']>;

/** Checks every body's list against the slots; returns the number of edges walked. */
function expectListsMatchSlots(world: World): number {
  const { bodies, contactManager: manager } = world.internals() as Internals;
  const { edges } = manager;
  const slotBodies = manager.slots.bodies;
  const seen = new Uint8Array(manager.count);
  let walked = 0;
  for (const body of bodies) {
    let prev = -1;
    for (let key = edges.first(body.worldIndex); key >= 0; key = edges.next[key]!) {
      const slot = key >> 1;
      expect(slot).toBeLessThan(manager.count);
      // The edge's own side of its slot names this body, and the list is linked both ways.
      expect(slotBodies[key]).toBe(body.worldIndex);
      expect(edges.prev[key]).toBe(prev);
      expect(seen[slot]! & (1 << (key & 1))).toBe(0);
      seen[slot]! |= 1 << (key & 1);
      prev = key;
      walked++;
    }
  }
  // Every contact is in both of its bodies' lists.
  for (let slot = 0; slot < manager.count; slot++) expect(seen[slot]).toBe(3);
  return walked;
}

/** A drum of walls turned by hand, full of boxes and balls: contacts begin and end every step. */
function tumbler(): World {
  const world = new World({ gravity: { x: 0, y: -10 } });
  for (let i = 0; i < 4; i++) {
    const a = (i * Math.PI) / 2;
    world.add(
      wall({
        from: { x: 3 * Math.cos(a) - 3 * Math.sin(a), y: 3 * Math.sin(a) + 3 * Math.cos(a) },
        to: { x: 3 * Math.cos(a) + 3 * Math.sin(a), y: 3 * Math.sin(a) - 3 * Math.cos(a) },
      }),
    );
  }
  for (let i = 0; i < 40; i++) {
    const position = { x: -2 + (i % 8) * 0.5, y: -2 + Math.floor(i / 8) * 0.5 };
    world.add(
      i % 3 === 0
        ? particle({ position, radius: 0.2 })
        : box({ position, width: 0.35, height: 0.3, linearVelocity: { x: (i % 5) - 2, y: 0 } }),
    );
  }
  return world;
}

describe('each body lists exactly its contacts, in flat memory', () => {
  it('holds while contacts begin and end, bodies leave and filters change', () => {
    const world = tumbler();
    const { contactManager: manager } = world.internals() as Internals;
    let walked = 0;
    for (let step = 0; step < 240; step++) {
      world.step(1 / 60);
      if (step === 100) world.remove(world.bodies[10]!);
      // A filter that now forbids the body's pairs ends its contacts (from the body's list).
      if (step === 140) {
        const body = world.bodies[20]!;
        const before = (world.internals() as Internals).contactManager.destroyed;
        body.shapes[0]!.filter = { category: 1, mask: 0 };
        expect((world.internals() as Internals).contactManager.destroyed).toBeGreaterThan(before);
      }
      if (step % 20 === 0) walked += expectListsMatchSlots(world);
    }
    walked += expectListsMatchSlots(world);
    // Contacts were made and ended many times over, so slots moved.
    expect(manager.destroyed).toBeGreaterThan(50);
    expect(walked).toBeGreaterThan(100);
  }, 60_000);

  it('keeps each list and its order through a snapshot', () => {
    const world = tumbler();
    for (let step = 0; step < 90; step++) world.step(1 / 60);
    const saved = takeSnapshot(world);
    const restored = restoreSnapshot(saved);
    expectListsMatchSlots(restored);
    expect(takeSnapshot(restored)).toEqual(saved);
    for (let step = 0; step < 60; step++) {
      world.step(1 / 60);
      restored.step(1 / 60);
    }
    expect(takeSnapshot(restored)).toEqual(takeSnapshot(world));
  }, 60_000);
});
