// An open-addressing hash set of unordered id pairs, stored as (min, max) in two Int32Arrays.
//
// Linear probing with backward-shift deletion (Knuth, TAOCP vol. 3, section 6.4, Algorithm R):
// a removal moves later members of the probe run back instead of leaving tombstones, so lookups
// never slow down with churn and no periodic rehash is needed. The load factor is kept at or
// below one half, where a linear-probing lookup inspects about 1.5 slots on a hit and 2.5 on a
// miss. The hash is fixed (no random seed), so iteration and growth are deterministic.

const EMPTY = -1;
const INITIAL_CAPACITY = 32;

/** Mixes the two ids with multiply-xorshift steps (the finaliser of MurmurHash3, Austin Appleby). */
function hashPair(low: number, high: number): number {
  let h = Math.imul(low, 0x9e3779b1) ^ high;
  h ^= h >>> 16;
  h = Math.imul(h, 0x85ebca6b);
  h ^= h >>> 13;
  h = Math.imul(h, 0xc2b2ae35);
  h ^= h >>> 16;
  return h;
}

/**
 * A set of unordered pairs of non-negative int32 ids: (a, b) and (b, a) are the same member.
 * Grows by doubling; add, remove and has allocate nothing otherwise.
 */
export class PairSet {
  private lows: Int32Array;
  private highs: Int32Array;
  private mask = 0;
  private count = 0;

  constructor(initialCapacity: number = INITIAL_CAPACITY) {
    let capacity = INITIAL_CAPACITY;
    while (capacity < 2 * initialCapacity) {
      capacity *= 2;
    }
    this.lows = new Int32Array(capacity).fill(EMPTY);
    this.highs = new Int32Array(capacity);
    this.mask = capacity - 1;
  }

  /** Number of pairs in the set. */
  get size(): number {
    return this.count;
  }

  /** Adds the pair {a, b}; returns true if it was not already present. */
  add(a: number, b: number): boolean {
    const low = a < b ? a : b;
    const high = a < b ? b : a;
    let slot = hashPair(low, high) & this.mask;
    for (;;) {
      const stored = this.lows[slot]!;
      if (stored === EMPTY) {
        break;
      }
      if (stored === low && this.highs[slot] === high) {
        return false;
      }
      slot = (slot + 1) & this.mask;
    }
    if (2 * (this.count + 1) > this.mask + 1) {
      this.grow();
      slot = hashPair(low, high) & this.mask;
      while (this.lows[slot] !== EMPTY) {
        slot = (slot + 1) & this.mask;
      }
    }
    this.lows[slot] = low;
    this.highs[slot] = high;
    this.count++;
    return true;
  }

  /** Whether the pair {a, b} is in the set. */
  has(a: number, b: number): boolean {
    return this.find(a < b ? a : b, a < b ? b : a) !== EMPTY;
  }

  /** Removes the pair {a, b}; returns true if it was present. */
  remove(a: number, b: number): boolean {
    let hole = this.find(a < b ? a : b, a < b ? b : a);
    if (hole === EMPTY) {
      return false;
    }
    const lows = this.lows;
    const highs = this.highs;
    const mask = this.mask;
    // Backward shift: walk the rest of the probe run and move back every member whose home
    // slot does not lie cyclically in (hole, slot], since the hole would otherwise cut it off
    // from its home.
    let slot = hole;
    for (;;) {
      slot = (slot + 1) & mask;
      const low = lows[slot]!;
      if (low === EMPTY) {
        break;
      }
      const home = hashPair(low, highs[slot]!) & mask;
      const staysPut = hole <= slot ? hole < home && home <= slot : hole < home || home <= slot;
      if (!staysPut) {
        lows[hole] = low;
        highs[hole] = highs[slot]!;
        hole = slot;
      }
    }
    lows[hole] = EMPTY;
    this.count--;
    return true;
  }

  /**
   * Makes room for `count` pairs at once, so adding them rehashes nothing (a pile's first step
   * adds 15,000 pairs, one doubling after another otherwise, in code not yet optimised).
   */
  reserve(count: number): void {
    if (2 * count <= this.mask + 1) return;
    let capacity = this.mask + 1;
    while (capacity < 2 * count) capacity *= 2;
    this.rehash(capacity);
  }

  /** Removes every pair, keeping the capacity. */
  clear(): void {
    this.lows.fill(EMPTY);
    this.count = 0;
  }

  private find(low: number, high: number): number {
    const lows = this.lows;
    let slot = hashPair(low, high) & this.mask;
    for (;;) {
      const stored = lows[slot]!;
      if (stored === EMPTY) {
        return EMPTY;
      }
      if (stored === low && this.highs[slot] === high) {
        return slot;
      }
      slot = (slot + 1) & this.mask;
    }
  }

  private grow(): void {
    this.rehash(2 * this.lows.length);
  }

  private rehash(capacity: number): void {
    const oldLows = this.lows;
    const oldHighs = this.highs;
    const lows = new Int32Array(capacity).fill(EMPTY);
    const highs = new Int32Array(capacity);
    const mask = capacity - 1;
    for (let i = 0; i < oldLows.length; i++) {
      const low = oldLows[i]!;
      if (low === EMPTY) {
        continue;
      }
      const high = oldHighs[i]!;
      let slot = hashPair(low, high) & mask;
      while (lows[slot] !== EMPTY) {
        slot = (slot + 1) & mask;
      }
      lows[slot] = low;
      highs[slot] = high;
    }
    this.lows = lows;
    this.highs = highs;
    this.mask = mask;
  }
}
