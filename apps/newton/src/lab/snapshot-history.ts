import { type World, type WorldSnapshot, restoreSnapshot, takeSnapshot } from '@physical/engine';

/** One saved step: its time, what the app keeps beside the world, and maybe a snapshot. */
export interface HistoryEntry<Data> {
  /** Simulated time (s). */
  readonly time: number;
  readonly data: Data;
  /** The world after this step, on every `interval`th entry only (null between). */
  readonly snapshot: WorldSnapshot | null;
}

/** Options of a {@link SnapshotHistory}. */
export interface SnapshotHistoryOptions {
  /** The most steps kept (the oldest go first), at least 2. */
  readonly capacity: number;
  /**
   * A world snapshot every this many steps (default 1). Between two, a restore replays the steps
   * from the one before: a snapshot of 50 particles costs several steps' time, replaying is
   * exact (restored worlds step bit for bit as the original did).
   */
  readonly interval?: number;
  /** The fixed step (s) to replay with. Default 1/60. */
  readonly step?: number;
}

/**
 * The last seconds of a simulation, step by step, for stepping back and scrubbing: engine
 * snapshots (`takeSnapshot`) every `interval` steps, and each step's time and app data, oldest
 * first. Restoring step k (`restoreSnapshot` of the snapshot at or before it, then the steps
 * up to k replayed) gives a new world that goes on bit for bit as the original did. `Data` is
 * what the app must restore beside the world (names of bodies by index, readouts), since a
 * snapshot keeps no app objects.
 */
export class SnapshotHistory<Data> {
  readonly capacity: number;
  readonly interval: number;
  readonly step: number;
  private entries: HistoryEntry<Data>[] = [];
  /** Steps since the last snapshot. */
  private sinceSnapshot = 0;
  /** The world was changed between two steps: the next entry needs a snapshot of its own. */
  private changed = false;

  constructor(options: SnapshotHistoryOptions) {
    const { capacity, interval = 1, step = 1 / 60 } = options;
    if (!Number.isInteger(capacity) || capacity < 2) {
      throw new RangeError(`capacity must be a whole number of 2 or more, got ${capacity}`);
    }
    if (!Number.isInteger(interval) || interval < 1 || interval > capacity) {
      throw new RangeError(`interval must be a whole number from 1 to capacity, got ${interval}`);
    }
    if (!(step > 0)) throw new RangeError(`step must be a positive time, got ${step}`);
    this.capacity = capacity;
    this.interval = interval;
    this.step = step;
  }

  /** Number of steps saved. */
  get length(): number {
    return this.entries.length;
  }

  /** The entry at `index` (0 the oldest). */
  entry(index: number): HistoryEntry<Data> | undefined {
    return this.entries[index];
  }

  /**
   * The newest entry at or before `time` (s), or -1 when every entry is later: where a world
   * stepped beside another (Forces' two tracks) stood when the other was at `time`.
   */
  indexAt(time: number): number {
    let index = this.entries.length - 1;
    while (index >= 0 && this.entries[index]!.time > time + 1e-9) index--;
    return index;
  }

  /** The newest entry. */
  get last(): HistoryEntry<Data> | undefined {
    return this.entries[this.entries.length - 1];
  }

  /**
   * Saves `world` (between steps) as the newest entry, with a snapshot when `interval` steps
   * have passed since the last (the first entry always has one). Drops the oldest entries when
   * full, so that the oldest kept has a snapshot.
   */
  record(world: World, time: number, data: Data): void {
    const snap =
      this.entries.length === 0 || this.changed || this.sinceSnapshot + 1 >= this.interval;
    this.changed = false;
    this.entries.push({ time, data, snapshot: snap ? takeSnapshot(world) : null });
    this.sinceSnapshot = snap ? 0 : this.sinceSnapshot + 1;
    if (this.entries.length > this.capacity) {
      let start = this.entries.length - this.capacity;
      while (start > 0 && this.entries[start]!.snapshot === null) start--;
      // Nothing to drop but entries that the next snapshot needs: wait for it.
      if (start > 0) this.entries.splice(0, start);
    }
  }

  /**
   * Says that the app changed the world between two steps (a force switched on, a body moved):
   * replaying the steps from an earlier snapshot would miss the change, so the next entry gets a
   * snapshot of its own.
   */
  markChanged(): void {
    this.changed = true;
  }

  /**
   * A new world in the state of the entry at `index`, with the entry: the snapshot at or before
   * it, restored, and the steps between replayed. The entries after it stay until
   * {@link truncateAfter} (so a learner can scrub back and forth before going on).
   * `replay`, before each replayed step, puts back what the app set on the world before that
   * step and keeps in the step's data (Reactions: the tray's lean, which a phone in the hand
   * changes in almost every step, too often for a snapshot each time).
   */
  restore(
    index: number,
    replay?: (world: World, data: Data) => void,
  ): { world: World; entry: HistoryEntry<Data> } {
    const entry = this.entries[index];
    if (entry === undefined) {
      throw new RangeError(`no entry ${index}: the history holds ${this.entries.length}`);
    }
    let base = index;
    while (this.entries[base]!.snapshot === null) base--;
    const world = restoreSnapshot(this.entries[base]!.snapshot!);
    for (let i = base; i < index; i++) {
      replay?.(world, this.entries[i + 1]!.data);
      world.step(this.step);
    }
    return { world, entry };
  }

  /** Forgets the entries after `index`: the simulation goes on from there, a new future. */
  truncateAfter(index: number): void {
    this.entries.length = Math.min(this.entries.length, Math.max(0, index + 1));
    let since = 0;
    for (let i = this.entries.length - 1; i >= 0 && this.entries[i]!.snapshot === null; i--)
      since++;
    this.sinceSnapshot = since;
  }

  clear(): void {
    this.entries = [];
    this.sinceSnapshot = 0;
    this.changed = false;
  }
}
