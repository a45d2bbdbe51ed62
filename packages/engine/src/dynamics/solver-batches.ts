import { STATE_STRIDE } from './body-state.ts';

/**
 * When a step is split into batches: at least `minConstraints` contact constraints (~950 KB of
 * constraint numbers; fewer fit in a core's cache as they are), and about `constraintsPerBatch`
 * constraints a batch (~240 KB, within a phone's L2 cache too; 128 to 512 measured the same on
 * many_pyramids, 4,096 was 5 % slower). Settings rather than constants so tests can batch small
 * worlds.
 */
export const batchSettings: { minConstraints: number; constraintsPerBatch: number } = {
  minConstraints: 2048,
  constraintsPerBatch: 512,
};

/** Steps before looking for islands again after one island held most of a step's constraints. */
const RETRY_STEPS = 30;

/**
 * Cache-sized batches of a step's islands. The sub-step loop visits every constraint twelve times
 * a step (four sub-steps of warm start, solve and relax); when a scene's constraints outgrow the
 * cache (400 pyramids of 55 boxes: 58,000 contacts, 27 MB), every visit fetches them from memory
 * again, and the warm start and solve passes ran at a third and half the speed they have on a
 * small scene. Islands (bodies joined through contacts, never through static bodies) share no
 * moving body, so one island's whole step does not depend on another's: the solver runs every
 * sub-step of a batch of islands before the next batch, and the batch stays in cache across its
 * twelve passes (Box2D v2 solved island by island; Box2D v3 colours one graph instead).
 *
 * The result is the same to the last bit: each constraint still comes after the same constraints
 * of its own island, in the same order, and every body still gets the same operations in the
 * same order. Kinematic bodies join islands like dynamic ones, because the sub-steps move them.
 */
export class SolverBatches {
  /** Batches of the current step; 0 when the step is solved whole. */
  count: number = 0;
  /** Batch k's constraints are order[orderStart[k] .. orderStart[k + 1]) after {@link build}. */
  orderStart: Int32Array = new Int32Array(17);
  /** Batch k's bodies (awake indices) are bodies[bodyStart[k] .. bodyStart[k + 1]). */
  bodyStart: Int32Array = new Int32Array(17);
  bodies: Int32Array = new Int32Array(64);
  /** Union-find parents by awake index, then each island root's constraint count and batch. */
  private parent = new Int32Array(64);
  private size = new Int32Array(64);
  private batchOf = new Int32Array(64);
  /** Each constraint's island root, and a copy of the order to sort from. */
  private rootOf = new Int32Array(64);
  private scratch = new Int32Array(64);
  /** Builds still to skip after one that found a dominant island. */
  private skip = 0;

  /**
   * Whether a step of up to `contacts` constraints may be batched, asked once per step before
   * {@link build}. Islands change slowly: after a build found one island holding most
   * constraints (one big pile), this says no for RETRY_STEPS steps, since finding the islands
   * costs ~2 % of such a step. Whether a step is batched never changes its result.
   */
  wants(contacts: number): boolean {
    if (contacts < batchSettings.minConstraints) return false;
    if (this.skip > 0) {
      this.skip--;
      return false;
    }
    return true;
  }

  /**
   * Groups the first `count` constraints of `order` into batches of whole islands and rewrites
   * `order` so that each batch's constraints are together, in their original relative order.
   * `constraintBodies` holds each constraint's two state offsets (slot * STATE_STRIDE, 0 for a
   * static body); `awakeCount` the step's bodies. Returns false, leaving `order` as it was, when
   * batching would not pay: few constraints, or one island holding half of them.
   */
  build(
    order: Int32Array,
    count: number,
    constraintBodies: Int32Array,
    awakeCount: number,
  ): boolean {
    this.count = 0;
    if (count < batchSettings.minConstraints || count < 2) return false;
    this.reserve(awakeCount, count);
    const parent = this.parent;
    const size = this.size;
    for (let i = 0; i < awakeCount; i++) {
      parent[i] = i;
      size[i] = 0;
    }
    for (let c = 0; c < count; c++) {
      const a = constraintBodies[2 * c]! / STATE_STRIDE - 1;
      const b = constraintBodies[2 * c + 1]! / STATE_STRIDE - 1;
      if (a >= 0 && b >= 0) this.union(a, b);
    }
    const rootOf = this.rootOf;
    let largest = 0;
    for (let c = 0; c < count; c++) {
      const a = constraintBodies[2 * c]! / STATE_STRIDE - 1;
      const b = constraintBodies[2 * c + 1]! / STATE_STRIDE - 1;
      // Every constraint has a moving body (Math.max only guards the union-find's index).
      const root = this.find(Math.max(0, a >= 0 ? a : b));
      rootOf[c] = root;
      const n = ++size[root];
      if (n > largest) largest = n;
    }
    if (2 * largest > count) {
      this.skip = RETRY_STEPS;
      return false;
    }

    // Islands join batches in the order their first constraint is visited.
    const batchOf = this.batchOf;
    batchOf.fill(-1, 0, awakeCount);
    const perBatch = batchSettings.constraintsPerBatch;
    let batches = 1;
    let filled = 0;
    for (let n = 0; n < count; n++) {
      const root = rootOf[order[n]!]!;
      if (batchOf[root] !== -1) continue;
      if (filled > 0 && filled + size[root]! > perBatch) {
        batches++;
        filled = 0;
      }
      batchOf[root] = batches - 1;
      filled += size[root]!;
    }
    if (batches === 1) return false;
    if (this.orderStart.length < batches + 1) {
      this.orderStart = new Int32Array(2 * batches + 1);
      this.bodyStart = new Int32Array(2 * batches + 1);
    }

    // Stable counting sorts by batch: constraints in visiting order, bodies in awake order
    // (bodies without constraints go with the first batch).
    const start = this.orderStart;
    start.fill(0, 0, batches + 1);
    for (let c = 0; c < count; c++) {
      const k = batchOf[rootOf[c]!]! + 1;
      start[k] = start[k]! + 1;
    }
    for (let k = 0; k < batches; k++) start[k + 1] = start[k + 1]! + start[k]!;
    const scratch = this.scratch;
    scratch.set(order.subarray(0, count));
    const next = this.size; // reused as each batch's write position
    for (let k = 0; k < batches; k++) next[k] = start[k]!;
    for (let n = 0; n < count; n++) {
      const c = scratch[n]!;
      const k = batchOf[rootOf[c]!]!;
      order[next[k]!] = c;
      next[k] = next[k]! + 1;
    }
    const bodyStart = this.bodyStart;
    bodyStart.fill(0, 0, batches + 1);
    for (let i = 0; i < awakeCount; i++) {
      const batch = batchOf[this.find(i)]!;
      // Reuse rootOf for the bodies' batches: the constraints' roots are no longer needed.
      const k = batch < 0 ? 0 : batch;
      rootOf[i] = k;
      bodyStart[k + 1] = bodyStart[k + 1]! + 1;
    }
    for (let k = 0; k < batches; k++) bodyStart[k + 1] = bodyStart[k + 1]! + bodyStart[k]!;
    for (let k = 0; k < batches; k++) next[k] = bodyStart[k]!;
    const bodies = this.bodies;
    for (let i = 0; i < awakeCount; i++) {
      const k = rootOf[i]!;
      bodies[next[k]!] = i;
      next[k] = next[k]! + 1;
    }
    this.count = batches;
    return true;
  }

  private find(i: number): number {
    const parent = this.parent;
    while (parent[i] !== i) {
      // Path halving (Tarjan and van Leeuwen, 1984).
      const grandparent = parent[parent[i]!]!;
      parent[i] = grandparent;
      i = grandparent;
    }
    return i;
  }

  private union(a: number, b: number): void {
    const ra = this.find(a);
    const rb = this.find(b);
    // The smaller index becomes the root: the same scene always builds the same islands.
    if (ra < rb) this.parent[rb] = ra;
    else if (rb < ra) this.parent[ra] = rb;
  }

  private reserve(bodies: number, constraints: number): void {
    const n = Math.max(bodies, constraints);
    if (this.parent.length >= n) return;
    let length = this.parent.length;
    while (length < n) length *= 2;
    this.parent = new Int32Array(length);
    this.size = new Int32Array(length);
    this.batchOf = new Int32Array(length);
    this.rootOf = new Int32Array(length);
    this.scratch = new Int32Array(length);
    this.bodies = new Int32Array(length);
  }
}
