// Seeded random numbers and boxes shared by the collision tests.
import { AABB } from '../../../src/geometry/aabb.ts';

/** Mulberry32: a small seeded PRNG so every run sees the same sequence. */
export function makeRandom(seed: number): () => number {
  let state = seed >>> 0;
  return () => {
    state = (state + 0x6d2b79f5) >>> 0;
    let t = state;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** A box with its corner within `extent` (m) of the origin and sides up to `maxSize` (m). */
export function randomBox(random: () => number, extent: number, maxSize: number): AABB {
  const x = (random() * 2 - 1) * extent;
  const y = (random() * 2 - 1) * extent;
  return new AABB().set(x, y, x + 0.01 + random() * maxSize, y + 0.01 + random() * maxSize);
}
