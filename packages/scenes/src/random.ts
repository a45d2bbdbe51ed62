/**
 * A seeded pseudo-random generator (mulberry32, Tommy Ettinger's public-domain 32-bit mixer), so
 * a scene with "random" sizes is the same world every time: the regression hash depends on it.
 */
export function seededRandom(seed: number): () => number {
  let state = seed >>> 0;
  return () => {
    state = (state + 0x6d2b79f5) >>> 0;
    let t = state;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
