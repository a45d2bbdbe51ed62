import { STATE_STRIDE } from './body-state.ts';

/** Colours a run can hold; a constraint whose bodies already use all of them comes last. */
const COLOURS = 32;

/**
 * Graph colouring of the contact constraints' visiting order, run by run (Box2D v3's graph
 * colours, `b2AssignJointColor`/`b2AddContactToGraph`: a constraint takes the lowest colour that
 * neither of its moving bodies has yet; immovable bodies, state slot 0, do not count). Within each
 * run of `run` consecutive positions of the order, the constraints are rewritten colour by colour,
 * each colour in its former order; runs stay where they are, so the bodies and constraints of a run
 * stay together in cache (a colouring of the whole order was 5 % slower from lost locality, see
 * README.md). Two neighbours of one colour share no moving body, so the WebAssembly kernel solves
 * them side by side in the two lanes of an `f64x2` (wasm/contact-kernel.ts), and that gives the
 * bits of solving them one after the other, which the JavaScript build does: both builds visit
 * this one order.
 */
export class ContactColouring {
  /** Per state slot, the colours its constraints took in the current run (bit c: colour c). */
  private masks = new Int32Array(64);
  /** Per position of the current run, its colour; then the run's order, sorted. */
  private colours = new Int32Array(64);
  private sorted = new Int32Array(64);
  /** Scratch of storeInOrder: slots, bodies, and each constraint's new index. */
  private slots = new Int32Array(64);
  private bodies = new Int32Array(128);
  private moved = new Int32Array(64);
  /** Constraints per colour (and the overflow colour COLOURS), then where each colour starts. */
  private readonly counts = new Int32Array(COLOURS + 2);

  /**
   * Rewrites the first `count` entries of `order` run by run, colour by colour. `bodies` holds
   * each constraint's two state offsets (slot * STATE_STRIDE); `bodyCount` the step's moving
   * bodies (slots 1..bodyCount).
   */
  colour(order: Int32Array, count: number, bodies: Int32Array, bodyCount: number, run: number): void {
    if (this.masks.length < bodyCount + 1) this.masks = new Int32Array(2 * (bodyCount + 1));
    if (this.colours.length < run) {
      this.colours = new Int32Array(run);
      this.sorted = new Int32Array(run);
    }
    for (let start = 0; start < count; start += run) {
      if (process.env.LANES_PAIR) this.pairRun(order, start, Math.min(count, start + run), bodies);
      else this.colourRun(order, start, Math.min(count, start + run), bodies);
    }
  }

  /** Pairs order[from .. to) greedily: each constraint is followed by the next one independent of it. */
  private pairRun(order: Int32Array, from: number, to: number, bodies: Int32Array): void {
    for (let n = from; n + 1 < to; ) {
      const i = order[n]!;
      const a = bodies[2 * i]!;
      const b = bodies[2 * i + 1]!;
      let m = n + 1;
      for (; m < to; m++) {
        const j = order[m]!;
        const c = bodies[2 * j]!;
        const d = bodies[2 * j + 1]!;
        if ((a === 0 || (a !== c && a !== d)) && (b === 0 || (b !== c && b !== d))) break;
      }
      if (m === to) {
        n++;
        continue;
      }
      const j = order[m]!;
      for (let k = m; k > n + 1; k--) order[k] = order[k - 1]!;
      order[n + 1] = j;
      n += 2;
    }
  }

  /** Colours and sorts order[from .. to), leaving the masks zero again. */
  private colourRun(order: Int32Array, from: number, to: number, bodies: Int32Array): void {
    const masks = this.masks;
    const colours = this.colours;
    const counts = this.counts;
    counts.fill(0);
    for (let n = from; n < to; n++) {
      const i = order[n]!;
      const a = bodies[2 * i]! / STATE_STRIDE;
      const b = bodies[2 * i + 1]! / STATE_STRIDE;
      const used = (a !== 0 ? masks[a]! : 0) | (b !== 0 ? masks[b]! : 0);
      // The lowest clear bit of `used`; COLOURS when none is clear.
      const free = ~used & (used + 1);
      const colour = free === 0 ? COLOURS : 31 - Math.clz32(free);
      if (colour < COLOURS) {
        if (a !== 0) masks[a] = masks[a]! | free;
        if (b !== 0) masks[b] = masks[b]! | free;
      }
      colours[n - from] = colour;
      counts[colour + 1]!++;
    }
    // Counting sort by colour, stable.
    for (let c = 1; c <= COLOURS + 1; c++) counts[c] = counts[c]! + counts[c - 1]!;
    const sorted = this.sorted;
    for (let n = from; n < to; n++) {
      const i = order[n]!;
      sorted[counts[colours[n - from]!]!++] = i;
      masks[bodies[2 * i]! / STATE_STRIDE] = 0;
      masks[bodies[2 * i + 1]! / STATE_STRIDE] = 0;
    }
    for (let n = from; n < to; n++) order[n] = sorted[n - from]!;
  }

  /**
   * Renumbers the first `count` classified constraints so that constraint n is the n-th visited
   * and `order` becomes 0, 1, 2, ...: their numbers are then filled and streamed in the visiting
   * order. The passes read a constraint's numbers one after the other in memory only when the
   * constraints follow each other in memory too: visiting the 32 constraints of a run in colour
   * order while they stayed in creation order made large_pyramid's steps ~30 % slower (the memory
   * prefetcher follows a stride, not a permutation). Moves each constraint's contact slot and
   * state offsets, and renames the circle pairs' list; the constraints must not be filled yet.
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
