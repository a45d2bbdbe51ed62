import { describe, expect, it } from 'vitest';
import { BODY_STRIDE } from '../../../src/dynamics/body-memory.ts';
import { SolverMemory, kernelSettings } from '../../../src/dynamics/solver-memory.ts';

// reserveStep makes room for a whole step in one move of the block (a big world's first step used
// to move it once per region), keeps the live bodies and contact slots, and does nothing for a
// step that fits.

const CONSTRAINT_STRIDE = 58;
const CONTACT_STRIDE = 43;
const TABLE_STRIDE = 5;

describe('SolverMemory.reserveStep', () => {
  it('grows every region a step needs at once and keeps the live bodies and contact slots', () => {
    const memory = new SolverMemory(CONSTRAINT_STRIDE, CONTACT_STRIDE, TABLE_STRIDE);
    memory.start(false);
    memory.reserveBodies(3);
    memory.bodyStore.data[2 * BODY_STRIDE + 1] = 0.75;
    memory.reserveContacts(2);
    memory.contactData[CONTACT_STRIDE + 5] = 3.125;
    memory.contactBodies[3] = 42;
    const bodies = 5000;
    const contacts = 15000;
    memory.reserveStep((bodies + 1) * 8, bodies, contacts, 2);
    expect(memory.states.length).toBeGreaterThanOrEqual((bodies + 1) * 8);
    expect(memory.bodyTable.length).toBeGreaterThanOrEqual(bodies * TABLE_STRIDE);
    expect(memory.contactData.length).toBeGreaterThanOrEqual(contacts * CONTACT_STRIDE);
    expect(memory.contactBodies.length).toBeGreaterThanOrEqual(2 * contacts);
    expect(memory.constraintData.length).toBeGreaterThanOrEqual(contacts * CONSTRAINT_STRIDE);
    expect(memory.constraintOrder.length).toBeGreaterThanOrEqual(contacts);
    expect([
      memory.bodyStore.data[2 * BODY_STRIDE + 1],
      memory.contactData[CONTACT_STRIDE + 5],
    ]).toEqual([0.75, 3.125]);
    expect(memory.contactBodies[3]).toBe(42);
    // A step this size moves to the WebAssembly kernel, as reserveConstraints would.
    expect(contacts).toBeGreaterThanOrEqual(kernelSettings.minConstraints);
    expect(memory.kernel).not.toBeNull();
    expect(memory.usesWebAssembly).toBe(true);

    // The same step again: nothing moves, so every view stays the one the passes hold.
    const views = [memory.states, memory.contactData, memory.constraintData, memory.bodyTable];
    memory.reserveStep((bodies + 1) * 8, bodies, contacts, contacts);
    memory.reserveContacts(contacts);
    memory.reserveConstraints(contacts);
    const after = [memory.states, memory.contactData, memory.constraintData, memory.bodyTable];
    after.forEach((view, i) => expect(view === views[i]).toBe(true));
  });

  it('carries neither the per-step regions nor the room past the live bodies and slots', () => {
    // Each byte carried lands on a fresh page of the new block: the step rebuilds the states,
    // the body table and the constraints before reading them, and the rest is unused room.
    const memory = new SolverMemory(CONSTRAINT_STRIDE, CONTACT_STRIDE, TABLE_STRIDE);
    memory.start(false);
    memory.reserveStates(16)[3] = 1.5;
    memory.reserveBodyTable(2)[7] = -2.25;
    memory.reserveConstraints(4);
    memory.constraintData[9] = 6.5;
    memory.constraintOrder[1] = 3;
    memory.reserveBodies(4);
    memory.bodyStore.data[BODY_STRIDE] = 1.25; // body 1, live
    memory.bodyStore.data[3 * BODY_STRIDE] = 2.5; // body 3, past the live two
    memory.reserveContacts(3);
    memory.contactData[CONTACT_STRIDE] = 4.5; // slot 1, live
    memory.contactData[2 * CONTACT_STRIDE] = 8.5; // slot 2, past the live two
    memory.contactBodies[5] = 7;
    memory.reserveStep(5001 * 8, 2, 15000, 2);
    expect([memory.states[3], memory.bodyTable[7], memory.constraintData[9]]).toEqual([0, 0, 0]);
    expect(memory.constraintOrder[1]).toBe(0);
    expect([memory.bodyStore.data[BODY_STRIDE], memory.bodyStore.data[3 * BODY_STRIDE]]).toEqual([
      1.25, 0,
    ]);
    expect([memory.contactData[CONTACT_STRIDE], memory.contactData[2 * CONTACT_STRIDE]]).toEqual([
      4.5, 0,
    ]);
    expect(memory.contactBodies[5]).toBe(0);
  });
});
