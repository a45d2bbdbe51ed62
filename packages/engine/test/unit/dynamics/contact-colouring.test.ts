import { describe, expect, it } from 'vitest';
import { STATE_STRIDE } from '../../../src/dynamics/body-state.ts';
import { ContactColouring } from '../../../src/dynamics/contact-colouring.ts';

// The colouring (contact-colouring.ts) decides which neighbours of the visiting order the
// WebAssembly kernel solves in lanes: two neighbours of one colour must never share a moving body.

/** Constraint bodies as the solver stores them: state offsets, slot 0 immovable. */
function bodiesOf(pairs: [number, number][]): Int32Array {
  return Int32Array.from(pairs.flatMap(([a, b]) => [a * STATE_STRIDE, b * STATE_STRIDE]));
}

function coloured(pairs: [number, number][], run: number, order?: number[]): number[] {
  const o = Int32Array.from(order ?? pairs.map((_, i) => i));
  const bodyCount = Math.max(...pairs.flat());
  new ContactColouring().colour(o, o.length, bodiesOf(pairs), bodyCount, run);
  return Array.from(o);
}

describe('ContactColouring', () => {
  it('gives a chain of bodies alternate colours and lists them colour by colour', () => {
    // Bodies 1-2-3-4-5 in a chain: colours 0, 1, 0, 1.
    expect(
      coloured(
        [
          [1, 2],
          [2, 3],
          [3, 4],
          [4, 5],
        ],
        32,
      ),
    ).toEqual([0, 2, 1, 3]);
  });

  it('does not count immovable bodies: contacts with the ground alone keep one colour and their order', () => {
    expect(
      coloured(
        [
          [0, 1],
          [2, 0],
          [0, 3],
        ],
        32,
        [2, 0, 1],
      ),
    ).toEqual([2, 0, 1]);
  });

  it('colours each run of the order on its own, so constraints never leave their run', () => {
    // Runs of two: [c0, c1] share body 2, [c2, c3] share body 4.
    const pairs: [number, number][] = [
      [1, 2],
      [2, 3],
      [3, 4],
      [4, 5],
    ];
    expect(coloured(pairs, 2, [1, 0, 3, 2])).toEqual([1, 0, 3, 2]);
    // Whole: c1 colour 0, c0 colour 1 (shares body 2), c3 colour 0, c2 colour 1 (shares 3 and 4).
    expect(coloured(pairs, 4, [1, 0, 3, 2])).toEqual([1, 3, 0, 2]);
  });

  it('makes most neighbours of a pile independent, each run keeping its constraints', () => {
    // A pile: bodies 1..60 in rows of 6, each resting on the two below it and beside its
    // neighbours; the first row on the ground (slot 0). Listed row by row, as contacts are made.
    const pairs: [number, number][] = [];
    for (let row = 0; row < 10; row++) {
      for (let k = 0; k < 6; k++) {
        const body = row * 6 + k + 1;
        if (row === 0) pairs.push([0, body]);
        else {
          pairs.push([body - 6, body]);
          if (k > 0) pairs.push([body - 7, body]);
        }
        if (k > 0) pairs.push([body - 1, body]);
      }
    }
    const shares = (i: number, j: number): boolean => {
      const [a, b] = pairs[i]!;
      const [c, d] = pairs[j]!;
      return (a !== 0 && (a === c || a === d)) || b === c || b === d;
    };
    const independentNeighbours = (order: number[]): number =>
      order.filter((i, n) => n % run !== 0 && !shares(order[n - 1]!, i)).length;
    const run = 32;
    const before = pairs.map((_, i) => i);
    const order = coloured(pairs, run);
    for (let start = 0; start < order.length; start += run) {
      const end = Math.min(order.length, start + run);
      expect(order.slice(start, end).sort((x, y) => x - y)).toEqual(before.slice(start, end));
    }
    // 155 constraints in 5 runs: in creation order 59 neighbours share no moving body, coloured
    // 147 of the 150 a run can have.
    expect(independentNeighbours(before)).toBe(59);
    expect(independentNeighbours(order)).toBeGreaterThanOrEqual(0.9 * pairs.length);
  });
});
