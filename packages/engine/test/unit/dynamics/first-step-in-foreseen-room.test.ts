import { describe, expect, it } from 'vitest';
import { World, box, wall } from '@physical/engine';
import { CONTACT_STRIDE } from '../../../src/dynamics/contact-data.ts';
import type { SolverMemory } from '../../../src/dynamics/solver-memory.ts';

// A world makes room for the step it can foresee while its bodies join (WorldMembership.foresee:
// three contacts per shape of a body that can move, contact-manager.ts's foreseenContacts), so
// its first step, which makes every contact of a resting pile at once, neither moves nor grows
// the solver memory (a move lands every byte on fresh pages: large_pyramid's first step took
// ~2,000 page faults moving it). Checked by the block's identity and the regions' sizes.

function memoryOf(world: World): SolverMemory {
  return (world as unknown as { solver: { memory: SolverMemory } }).solver.memory;
}

/** A pyramid of `rows` rows of unit boxes on the ground. */
function pyramid(rows: number): World {
  const world = new World({ enableSleep: false });
  world.add(wall({ from: { x: -rows, y: 0 }, to: { x: rows, y: 0 } }));
  for (let r = 0; r < rows; r++) {
    for (let c = 0; c < rows - r; c++) {
      world.add(
        box({ position: { x: c * 1.01 - (rows - r) / 2, y: -0.5 - r }, width: 1, height: 1 }),
      );
    }
  }
  return world;
}

describe('a world makes its first step in the room it foresaw', () => {
  it('does not move or grow the solver memory in the first step of a 30-row pyramid', () => {
    const world = pyramid(30); // 465 boxes
    const memory = memoryOf(world);
    const block = memory.bodyStore.data.buffer;
    const contactRoom = memory.contactData.length;
    const constraintRoom = memory.constraintOrder.length;
    world.step(1 / 60);
    const contacts = (world.internals() as { contactManager: { count: number } }).contactManager
      .count;
    // More contacts than the memory's first room (256 slots): without the foreseen room the
    // step would have moved the block to make them.
    expect(contacts).toBeGreaterThan(256);
    expect(memory.bodyStore.data.buffer).toBe(block);
    expect(memory.contactData.buffer).toBe(block);
    expect(memory.contactData.length).toBe(contactRoom);
    expect(memory.constraintOrder.length).toBe(constraintRoom);
  });

  it('foresees at most three contacts per moving shape, with the room grown by half at most', () => {
    const world = pyramid(30);
    const memory = memoryOf(world);
    const movingShapes = 465;
    const slots = memory.contactData.length / CONTACT_STRIDE;
    expect(slots).toBeGreaterThanOrEqual(3 * movingShapes);
    expect(slots).toBeLessThanOrEqual(1.5 * 3 * movingShapes);
    expect(memory.constraintOrder.length).toBe(slots);
  });

  it('foresees no contacts for static shapes, which never touch each other', () => {
    const world = new World();
    for (let i = 0; i < 2000; i++) {
      world.add(wall({ from: { x: i, y: 0 }, to: { x: i + 1, y: 0 } }));
    }
    const memory = memoryOf(world);
    // The first room (256 slots), not 6,000 slots.
    expect(memory.contactData.length / CONTACT_STRIDE).toBe(256);
    expect(memory.shapeTable.data.length).toBeGreaterThanOrEqual(2000 * 8);
  });
});
