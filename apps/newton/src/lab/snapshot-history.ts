import { type World, type WorldSnapshot, restoreSnapshot, takeSnapshot } from '@physical/engine';

/** One saved moment: the world's snapshot, its time and what the app keeps beside it. */
export interface HistoryEntry<Data> {
  /** Simulated time (s). */
  readonly time: number;
  readonly snapshot: WorldSnapshot;
  readonly data: Data;
}

/**
 * The last seconds of a simulation, for stepping back and scrubbing: engine snapshots
 * (`takeSnapshot`) of the world after each recorded step, oldest first, at most `capacity` of
 * them. Restoring one (`restoreSnapshot`) gives a new world that steps on bit for bit as the
 * original did from that moment. `Data` is what the app must restore beside the world (names of
 * bodies by index, readouts), since a snapshot keeps no app objects.
 */
export class SnapshotHistory<Data> {
  private entries: HistoryEntry<Data>[] = [];

  /** `capacity`: the most entries kept (the oldest go first), at least 2. */
  constructor(readonly capacity: number) {
    if (!Number.isInteger(capacity) || capacity < 2) {
      throw new RangeError(`capacity must be a whole number of 2 or more, got ${capacity}`);
    }
  }

  /** Number of entries saved. */
  get length(): number {
    return this.entries.length;
  }

  /** The entry at `index` (0 the oldest). */
  entry(index: number): HistoryEntry<Data> | undefined {
    return this.entries[index];
  }

  /** The newest entry. */
  get last(): HistoryEntry<Data> | undefined {
    return this.entries[this.entries.length - 1];
  }

  /** Saves `world` (between steps) as the newest entry, dropping the oldest when full. */
  record(world: World, time: number, data: Data): void {
    this.entries.push({ time, snapshot: takeSnapshot(world), data });
    if (this.entries.length > this.capacity)
      this.entries.splice(0, this.entries.length - this.capacity);
  }

  /**
   * A new world in the state of the entry at `index`, with the entry. The entries after it stay
   * until {@link truncateAfter} (so a learner can scrub back and forth before going on).
   */
  restore(index: number): { world: World; entry: HistoryEntry<Data> } {
    const entry = this.entries[index];
    if (entry === undefined) {
      throw new RangeError(`no entry ${index}: the history holds ${this.entries.length}`);
    }
    return { world: restoreSnapshot(entry.snapshot), entry };
  }

  /** Forgets the entries after `index`: the simulation goes on from there, a new future. */
  truncateAfter(index: number): void {
    this.entries.length = Math.min(this.entries.length, Math.max(0, index + 1));
  }

  clear(): void {
    this.entries = [];
  }
}
