import type { Joint } from './joint.ts';

/**
 * @internal Where joints' records live (joint-record.ts): `stride` doubles per slot in `data`. A
 * world keeps one store per joint kind (the kind's batch, joint-batch.ts) and its joints' records
 * are there and only there: the `Joint` handles' getters and setters and the kind's passes read
 * and write the same numbers, so nothing is copied back at a step's end. A joint outside a world
 * has a store of its own (one slot), like a body outside a world (body-memory.ts); its record is
 * moved into its world's store when the world first solves it, and out when it leaves.
 *
 * A handle keeps the store and its record's offset and reads `data` at each access: growing
 * (a new array of twice the size) moves nothing a handle holds.
 */
export class JointStore {
  data: Float64Array;
  /** Slots in use (a world's store). */
  count = 0;
  /** The joint of each slot in use (a world's store), to rename the one moved into a hole. */
  private readonly owners: (Joint | null)[] = [];

  constructor(
    readonly stride: number,
    capacity: number,
    /** A joint's own store (outside a world), not a world's. */
    readonly local: boolean,
  ) {
    // -0, as the fields of the Joint objects the records replace started (see dynamics/README.md).
    this.data = new Float64Array(stride * capacity).fill(-0);
  }

  /** A store of one record, for a joint outside a world. */
  static own(stride: number): JointStore {
    return new JointStore(stride, 1, true);
  }

  /** Moves `joint`'s record from its own store into a new slot here (it joins a world's kind). */
  adopt(joint: Joint): void {
    const stride = this.stride;
    const slot = this.count++;
    if (this.data.length < this.count * stride) {
      const data = new Float64Array(2 * this.data.length).fill(-0);
      data.set(this.data);
      this.data = data;
    }
    copyRecord(joint.store.data, joint.base, this.data, slot * stride, stride);
    this.owners[slot] = joint;
    joint.store = this;
    joint.base = slot * stride;
  }

  /**
   * Moves `joint`'s record out into a store of its own (it left its world, and keeps its settings
   * and impulses), and the last slot's record into its place.
   */
  release(joint: Joint): void {
    const stride = this.stride;
    const own = JointStore.own(stride);
    copyRecord(this.data, joint.base, own.data, 0, stride);
    const slot = joint.base / stride;
    const last = --this.count;
    if (slot !== last) {
      copyRecord(this.data, last * stride, this.data, slot * stride, stride);
      const moved = this.owners[last]!;
      this.owners[slot] = moved;
      moved.base = slot * stride;
    }
    this.owners[last] = null;
    joint.store = own;
    joint.base = 0;
  }
}

function copyRecord(
  from: Float64Array,
  fromOffset: number,
  to: Float64Array,
  toOffset: number,
  stride: number,
): void {
  for (let i = 0; i < stride; i++) to[toOffset + i] = from[fromOffset + i]!;
}
