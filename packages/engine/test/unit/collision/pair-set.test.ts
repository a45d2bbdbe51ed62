import { describe, expect, it } from 'vitest';
import { PairSet } from '../../../src/collision/pair-set.ts';

/** Mulberry32: a small seeded PRNG so every run sees the same sequence. */
function makeRandom(seed: number): () => number {
  let state = seed >>> 0;
  return () => {
    state = (state + 0x6d2b79f5) >>> 0;
    let t = state;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function keyOf(a: number, b: number): string {
  return a < b ? `${a},${b}` : `${b},${a}`;
}

describe('PairSet', () => {
  it('treats (a, b) and (b, a) as the same pair', () => {
    const set = new PairSet();
    expect(set.add(3, 9)).toBe(true);
    expect(set.add(9, 3)).toBe(false);
    expect(set.has(9, 3)).toBe(true);
    expect(set.has(3, 9)).toBe(true);
    expect(set.size).toBe(1);
    expect(set.remove(9, 3)).toBe(true);
    expect(set.has(3, 9)).toBe(false);
    expect(set.remove(3, 9)).toBe(false);
    expect(set.size).toBe(0);
  });

  it('agrees with a JS Set over many random adds, removes and lookups, through growth', () => {
    const random = makeRandom(2024);
    const set = new PairSet(4);
    const reference = new Set<string>();
    // A small id range makes repeats, hash collisions and long probe runs common.
    let mismatches = 0;
    for (let op = 0; op < 60000; op++) {
      const a = Math.floor(random() * 300);
      const b = Math.floor(random() * 300);
      const roll = random();
      const key = keyOf(a, b);
      if (roll < 0.5) {
        mismatches += set.add(a, b) === !reference.has(key) ? 0 : 1;
        reference.add(key);
      } else if (roll < 0.8) {
        mismatches += set.remove(a, b) === reference.has(key) ? 0 : 1;
        reference.delete(key);
      } else {
        mismatches += set.has(a, b) === reference.has(key) ? 0 : 1;
      }
      mismatches += set.size === reference.size ? 0 : 1;
    }
    expect(mismatches).toBe(0);
    expect(reference.size).toBeGreaterThan(1000);
    for (const key of reference) {
      const [a, b] = key.split(',').map(Number) as [number, number];
      expect(set.has(b, a)).toBe(true);
    }
  });

  it('handles large ids and id 0', () => {
    const set = new PairSet();
    const big = 0x7fffffff;
    expect(set.add(0, big)).toBe(true);
    expect(set.add(big, big - 1)).toBe(true);
    expect(set.add(0, 0)).toBe(true);
    expect(set.has(big, 0)).toBe(true);
    expect(set.has(big - 1, big)).toBe(true);
    expect(set.has(0, 0)).toBe(true);
    expect(set.has(1, 0)).toBe(false);
    expect(set.size).toBe(3);
  });

  it('is empty after clear and usable again', () => {
    const set = new PairSet();
    for (let i = 0; i < 500; i++) {
      set.add(i, i + 1);
    }
    expect(set.size).toBe(500);
    set.clear();
    expect(set.size).toBe(0);
    for (let i = 0; i < 500; i++) {
      expect(set.has(i, i + 1)).toBe(false);
    }
    expect(set.add(10, 11)).toBe(true);
    expect(set.has(11, 10)).toBe(true);
  });

  it('keeps its members through reserve, and then holds the reserved pairs without growing', () => {
    const set = new PairSet();
    for (let i = 0; i < 100; i++) set.add(i, 3 * i + 7);
    set.reserve(5000);
    expect(set.size).toBe(100);
    for (let i = 0; i < 100; i++) expect(set.has(3 * i + 7, i)).toBe(true);
    expect(set.has(1, 2)).toBe(false);
    // The arrays are replaced only when the set grows.
    const arrays = set as unknown as { lows: Int32Array };
    const lows = arrays.lows;
    for (let i = 100; i < 5000; i++) set.add(i, 3 * i + 7);
    expect(arrays.lows).toBe(lows);
    expect(set.size).toBe(5000);
  });
});
