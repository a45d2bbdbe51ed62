import { describe, expect, it } from 'vitest';
import { SolverMemory, kernelSettings } from '../../../src/dynamics/solver-memory.ts';

// reserveStep makes room for a whole step in one move of the block (a big world's first step used
// to move it once per region), keeps what the regions hold, and does nothing for a step that fits.

const CONSTRAINT_STRIDE = 58;
const CONTACT_STRIDE = 43;
const TABLE_STRIDE = 5;

describe('SolverMemory.reserveStep', () => {
  it('grows every region a step needs at once and keeps their contents', () => {
    const memory = new SolverMemory(CONSTRAINT_STRIDE, CONTACT_STRIDE, TABLE_STRIDE);
    memory.start(false);
    memory.reserveStates(16)[3] = 1.5;
    memory.reserveBodyTable(2)[7] = -2.25;
    memory.reserveContacts(1);
    memory.contactData[5] = 3.125;
    memory.contactBodies[1] = 42;
    const bodies = 5000;
    const contacts = 15000;
    memory.reserveStep((bodies + 1) * 8, bodies, contacts);
    expect(memory.states.length).toBeGreaterThanOrEqual((bodies + 1) * 8);
    expect(memory.bodyTable.length).toBeGreaterThanOrEqual(bodies * TABLE_STRIDE);
    expect(memory.contactData.length).toBeGreaterThanOrEqual(contacts * CONTACT_STRIDE);
    expect(memory.contactBodies.length).toBeGreaterThanOrEqual(2 * contacts);
    expect(memory.constraintData.length).toBeGreaterThanOrEqual(contacts * CONSTRAINT_STRIDE);
    expect(memory.constraintOrder.length).toBeGreaterThanOrEqual(contacts);
    expect([memory.states[3], memory.bodyTable[7], memory.contactData[5]]).toEqual([
      1.5, -2.25, 3.125,
    ]);
    expect(memory.contactBodies[1]).toBe(42);
    // A step this size moves to the WebAssembly kernel, as reserveConstraints would.
    expect(contacts).toBeGreaterThanOrEqual(kernelSettings.minConstraints);
    expect(memory.kernel).not.toBeNull();
    expect(memory.usesWebAssembly).toBe(true);

    // The same step again: nothing moves, so every view stays the one the passes hold.
    const views = [memory.states, memory.contactData, memory.constraintData, memory.bodyTable];
    memory.reserveStep((bodies + 1) * 8, bodies, contacts);
    memory.reserveContacts(contacts);
    memory.reserveConstraints(contacts);
    const after = [memory.states, memory.contactData, memory.constraintData, memory.bodyTable];
    after.forEach((view, i) => expect(view === views[i]).toBe(true));
  });
});
