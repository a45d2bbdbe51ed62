import { describe, expect, it } from 'vitest';
import { FILTER_ROW, filterRowsAllow } from '../../../src/collision/pair-filter.ts';
import { filtersCollide } from '../../../src/dynamics/filter.ts';
import { makeRandom } from './random-boxes.ts';

describe('filterRowsAllow', () => {
  it('allows a pair exactly when neither is a sensor and filtersCollide allows it', () => {
    const random = makeRandom(7);
    const count = 400;
    const filters = new Int32Array(count * FILTER_ROW);
    const bits = (): number => [0, 1, 2, 3, 0xffff, 0xfffffffd, 0xffffffff][(random() * 7) | 0]!;
    const described: { categoryBits: number; maskBits: number; groupIndex: number }[] = [];
    const sensor: boolean[] = [];
    for (let id = 0; id < count; id++) {
      const filter = {
        categoryBits: bits(),
        maskBits: bits(),
        groupIndex: [0, 0, 1, -1, 2, -2][(random() * 6) | 0]!,
      };
      described.push(filter);
      sensor.push(random() < 0.1);
      // As the shape table stores them: int32 rows.
      filters[id * FILTER_ROW] = filter.categoryBits | 0;
      filters[id * FILTER_ROW + 1] = filter.maskBits | 0;
      filters[id * FILTER_ROW + 2] = filter.groupIndex;
      filters[id * FILTER_ROW + 3] = sensor[id] ? 1 : 0;
    }
    let allowed = 0;
    for (let a = 0; a < count; a++) {
      for (let b = a + 1; b < count; b++) {
        const expected = !sensor[a] && !sensor[b] && filtersCollide(described[a]!, described[b]!);
        expect(filterRowsAllow(filters, a, b)).toBe(expected);
        if (expected) allowed++;
      }
    }
    // Both outcomes occur often.
    expect(allowed).toBeGreaterThan(10_000);
    expect(allowed).toBeLessThan((count * (count - 1)) / 2 - 10_000);
  });
});
