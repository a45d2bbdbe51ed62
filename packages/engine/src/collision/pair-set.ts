// An open-addressing hash set of unordered id pairs, stored as (min, max) side by side in one
// Int32Array: a lookup's probe reads both ids from one cache line (issue #30: in tumbler the
// broad phase asks about 11,000 pairs a step, in a set of 21,000 pairs, mostly cache misses).
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
  /** Slot s holds its low id at 2 s (EMPTY when free) and its high id at 2 s + 1. */
  private keys: Int32Array;
  private mask = 0;
  private count = 0;

  constructor(initialCapacity: number = INITIAL_CAPACITY) {
    let capacity = INITIAL_CAPACITY;
    while (capacity < 2 * initialCapacity) {
      capacity *= 2;
    }
    this.keys = new Int32Array(2 * capacity).fill(EMPTY);
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
    if (this.find(low, high) !== EMPTY) {
      return false;
    }
    if (2 * (this.count + 1) > this.mask + 1) {
      this.rehash(2 * (this.mask + 1));
    }
    const keys = this.keys;
    const mask = this.mask;
    let slot = hashPair(low, high) & mask;
    while (keys[2 * slot] !== EMPTY) {
      slot = (slot + 1) & mask;
    }
    keys[2 * slot] = low;
    keys[2 * slot + 1] = high;
    this.count++;
    return true;
  }

  /** Whether the pair {a, b} is in the set. */
  has(a: number, b: number): boolean {
    return this.find(a < b ? a : b, a < b ? b : a) !== EMPTY;
  }

  /** Whether the pair {low, high} is in the set, given `low` < `high` (the broad phase's order). */
  hasOrdered(low: number, high: number): boolean {
    return this.find(low, high) !== EMPTY;
  }

  /** Removes the pair {a, b}; returns true if it was present. */
  remove(a: number, b: number): boolean {
    let hole = this.find(a < b ? a : b, a < b ? b : a);
    if (hole === EMPTY) {
      return false;
    }
    const keys = this.keys;
    const mask = this.mask;
    // Backward shift: walk the rest of the probe run and move back every member whose home
    // slot does not lie cyclically in (hole, slot], since the hole would otherwise cut it off
    // from its home.
    let slot = hole;
    for (;;) {
      slot = (slot + 1) & mask;
      const low = keys[2 * slot]!;
      if (low === EMPTY) {
        break;
      }
      const high = keys[2 * slot + 1]!;
      const home = hashPair(low, high) & mask;
      const staysPut = hole <= slot ? hole < home && home <= slot : hole < home || home <= slot;
      if (!staysPut) {
        keys[2 * hole] = low;
        keys[2 * hole + 1] = high;
        hole = slot;
      }
    }
    keys[2 * hole] = EMPTY;
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
    this.keys.fill(EMPTY);
    this.count = 0;
  }

  /** The slot holding {low, high}, or EMPTY. */
  private find(low: number, high: number): number {
    const keys = this.keys;
    const mask = this.mask;
    let slot = hashPair(low, high) & mask;
    for (;;) {
      const stored = keys[2 * slot]!;
      if (stored === EMPTY) {
        return EMPTY;
      }
      if (stored === low && keys[2 * slot + 1] === high) {
        return slot;
      }
      slot = (slot + 1) & mask;
    }
  }

  private rehash(capacity: number): void {
    const old = this.keys;
    const keys = new Int32Array(2 * capacity).fill(EMPTY);
    const mask = capacity - 1;
    for (let i = 0; i < old.length; i += 2) {
      const low = old[i]!;
      if (low === EMPTY) {
        continue;
      }
      const high = old[i + 1]!;
      let slot = hashPair(low, high) & mask;
      while (keys[2 * slot] !== EMPTY) {
        slot = (slot + 1) & mask;
      }
      keys[2 * slot] = low;
      keys[2 * slot + 1] = high;
    }
    this.keys = keys;
    this.mask = mask;
  }
}
