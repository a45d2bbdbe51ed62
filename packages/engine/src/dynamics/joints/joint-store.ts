import type { Joint } from './joint.ts';

/**
 * @internal Where joints' records live (joint-record.ts): `stride` doubles per slot in `data`. A
 * world keeps one store for all its joints, every kind at JOINT_RECORD_STRIDE, in its solver
 * memory's JOINT_RECORDS region (solver-memory.ts), where the kernel's joint passes
 * (wasm/joint-passes.ts) read them: the `Joint` handles' getters and setters and the passes read
 * and write the same numbers, so nothing is copied back at a step's end. A joint outside a world
 * has a store of its own (one slot of its kind's stride), like a body outside a world
 * (body-memory.ts); its record is moved into its world's store when the world first solves it,
 * and out when it leaves.
 *
 * A handle keeps the store and its record's offset and reads `data` at each access: growing (the
 * world's memory moving, every view replaced) moves nothing a handle holds.
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
    /** Makes room for this many doubles, replacing `data` (a world's store: its memory grows). */
    private readonly grow: ((doubles: number) => void) | null = null,
  ) {
    // -0, as the fields of the Joint objects the records replace started (see dynamics/README.md).
    this.data = new Float64Array(stride * capacity).fill(-0);
  }

  /** A store of one record, for a joint outside a world. */
  static own(stride: number): JointStore {
    return new JointStore(stride, 1, true);
  }

  /** Moves `joint`'s record from its own store into a new slot here (it joins a world). */
  adopt(joint: Joint): void {
    const stride = this.stride;
    const slot = this.count++;
    if (this.data.length < this.count * stride) {
      if (this.grow !== null) this.grow(this.count * stride);
      else {
        const data = new Float64Array(2 * this.data.length).fill(-0);
        data.set(this.data);
        this.data = data;
      }
    }
    const from = joint.store;
    copyRecord(from.data, joint.base, this.data, slot * stride, Math.min(from.stride, stride));
    this.owners[slot] = joint;
    joint.store = this;
    joint.base = slot * stride;
  }

  /**
   * Moves `joint`'s record (`recordStride` doubles, its kind's) out into a store of its own (it
   * left its world, and keeps its settings and impulses), and the last slot's record into its
   * place.
   */
  release(joint: Joint, recordStride: number): void {
    const stride = this.stride;
    const own = JointStore.own(recordStride);
    copyRecord(this.data, joint.base, own.data, 0, Math.min(recordStride, stride));
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
