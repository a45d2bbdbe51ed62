// Pairs of contact constraints for the WebAssembly kernel's lanes (wasm/contact-kernel.ts): the
// kernel solves constraints 2m and 2m + 1 side by side in the two lanes of an f64x2 when they are
// visited one after the other and share no moving body. Their numbers are stored interleaved
// (contact-constraint-layout.ts, constraintBase), so one v128.load fetches a number of both.
//
// Two steps, both in JavaScript so both builds of the kernel visit the same order (the JavaScript
// build has no lanes, and gives the same bits: two constraints that share no moving body touch
// disjoint states):
// 1. `pair`: within each run of the scrambled order (solver.ts, scrambleOrder), the constraint at
//    an even position is followed by the first later one of its run that shares no moving body
//    with it (the others shift on by one, keeping their order). Box2D v3 colours its constraint
//    graph so that a colour's constraints share no dynamic body (static bodies do not count) and
//    solves a colour in SIMD lanes; this is that idea for lanes of two, kept inside a run so the
//    scrambled order's locality stays.
// 2. `storeInOrder`: renumbers the classified constraints so that the n-th visited is constraint
//    n; the pairs of step 1 are then constraints 2m and 2m + 1, and the passes stream the
//    constraint memory in order.

export class ContactPairing {
  /** Scratch of storeInOrder: slots, bodies, and each constraint's new index. */
  private slots = new Int32Array(64);
  private bodies = new Int32Array(128);
  private moved = new Int32Array(64);

  /**
   * Reorders each run of `run` positions of `order` (runs start at multiples of `run`, an even
   * number) so that positions 2m and 2m + 1 hold constraints sharing no moving body where the run
   * has one. `bodies` holds each constraint's two state offsets; offset 0 is immovable.
   */
  pair(order: Int32Array, count: number, bodies: Int32Array, run: number): void {
    for (let start = 0; start < count; start += run) {
      const end = Math.min(count, start + run);
      for (let n = start; n + 1 < end; n += 2) {
        const i = order[n]!;
        const a = bodies[2 * i]!;
        const b = bodies[2 * i + 1]!;
        let m = n + 1;
        for (; m < end; m++) {
          const j = order[m]!;
          const c = bodies[2 * j]!;
          const d = bodies[2 * j + 1]!;
          if ((a === 0 || (a !== c && a !== d)) && (b === 0 || (b !== c && b !== d))) break;
        }
        if (m === end || m === n + 1) continue;
        const j = order[m]!;
        for (let k = m; k > n + 1; k--) order[k] = order[k - 1]!;
        order[n + 1] = j;
      }
    }
  }

  /**
   * Renumbers the first `count` classified constraints so that constraint n is the n-th visited
   * and `order` becomes 0, 1, 2, ...: moves each one's contact slot and state offsets and renames
   * the circle pairs' list. The constraints must not be filled yet (their numbers do not move).
   */
  storeInOrder(
    order: Int32Array,
    count: number,
    bodies: Int32Array,
    slots: Int32Array,
    circlePairs: Int32Array,
    circlePairCount: number,
  ): void {
    if (this.slots.length < count) {
      this.slots = new Int32Array(2 * count);
      this.bodies = new Int32Array(4 * count);
      this.moved = new Int32Array(2 * count);
    }
    const s = this.slots;
    const b = this.bodies;
    const moved = this.moved;
    for (let n = 0; n < count; n++) {
      const i = order[n]!;
      s[n] = slots[i]!;
      b[2 * n] = bodies[2 * i]!;
      b[2 * n + 1] = bodies[2 * i + 1]!;
      moved[i] = n;
    }
    for (let n = 0; n < count; n++) {
      slots[n] = s[n]!;
      bodies[2 * n] = b[2 * n]!;
      bodies[2 * n + 1] = b[2 * n + 1]!;
      order[n] = n;
    }
    for (let k = 0; k < circlePairCount; k++) circlePairs[k] = moved[circlePairs[k]!]!;
  }
}
