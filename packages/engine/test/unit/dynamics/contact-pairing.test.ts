import { describe, expect, it } from 'vitest';
import { ContactPairing } from '../../../src/dynamics/contact-pairing.ts';

// State offsets as the solver stores them: 0 is immovable (static or sleeping bodies), a moving
// body's offset is its solver slot times the state stride; any distinct numbers do here.

/** Whether constraints i and j share a moving body. */
function share(bodies: Int32Array, i: number, j: number): boolean {
  const a = bodies[2 * i]!;
  const b = bodies[2 * i + 1]!;
  const c = bodies[2 * j]!;
  const d = bodies[2 * j + 1]!;
  return (a !== 0 && (a === c || a === d)) || (b !== 0 && (b === c || b === d));
}

describe('ContactPairing', () => {
  it('puts a constraint that shares no moving body after each one at an even position of its run', () => {
    // A chain of boxes 1-2-3-4-5-6 on the ground (0): each box touches the ground and its
    // neighbours, so creation order puts constraints that share a box side by side.
    const pairs: [number, number][] = [];
    for (let box = 1; box <= 6; box++) {
      pairs.push([0, box]);
      if (box < 6) pairs.push([box, box + 1]);
    }
    const bodies = new Int32Array(pairs.flat());
    const count = pairs.length;
    const order = Int32Array.from({ length: count }, (_, i) => i);
    let before = 0;
    for (let n = 0; n + 1 < count; n += 2) if (!share(bodies, order[n]!, order[n + 1]!)) before++;

    new ContactPairing().pair(order, count, bodies, 8);

    // Still every constraint once, and no constraint left its run of 8 positions.
    expect([...order].sort((x, y) => x - y)).toEqual([...Array(count).keys()]);
    for (let n = 0; n < count; n++) expect(Math.floor(order[n]! / 8)).toBe(Math.floor(n / 8));
    let after = 0;
    for (let n = 0; n + 1 < count; n += 2) if (!share(bodies, order[n]!, order[n + 1]!)) after++;
    expect(before).toBe(0);
    // Runs of 8 and 3 positions: the first pairs three of its four (box 4-5's contact finds no
    // partner left in its run), the second its one.
    expect(after).toBe(4);
  });

  it('keeps the order where a constraint has no partner in its run', () => {
    // Three constraints on the same moving body: none can share lanes.
    const bodies = new Int32Array([8, 0, 8, 16, 24, 8]);
    const order = new Int32Array([2, 0, 1]);
    new ContactPairing().pair(order, 3, bodies, 32);
    expect([...order]).toEqual([2, 0, 1]);
  });

  it('renumbers constraints in their visiting order, with their slots, bodies and circle pairs', () => {
    const order = new Int32Array([2, 0, 3, 1]);
    const bodies = new Int32Array([10, 11, 20, 21, 30, 31, 40, 41]);
    const slots = new Int32Array([100, 200, 300, 400]);
    const circlePairs = new Int32Array([3, 2]);
    new ContactPairing().storeInOrder(order, 4, bodies, slots, circlePairs, 2);
    expect([...order]).toEqual([0, 1, 2, 3]);
    expect([...slots]).toEqual([300, 100, 400, 200]);
    expect([...bodies]).toEqual([30, 31, 10, 11, 40, 41, 20, 21]);
    // Old constraint 3 is now the third visited (2), old 2 the first (0).
    expect([...circlePairs]).toEqual([2, 0]);
  });
});
