/** Samples of one quantity over simulated time, oldest first, limited to a window. */
export class TimeSeries {
  readonly times: number[] = [];
  readonly values: number[] = [];
  /** Changes whenever a sample is added or the series is cleared (graphs redraw on change). */
  version = 0;
  private readonly listeners = new Set<() => void>();

  /** Calls `listener` after every change; returns the function that stops it. */
  subscribe(listener: () => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  private changed(): void {
    this.version++;
    for (const listener of this.listeners) listener();
  }

  constructor(
    /** Seconds of history kept. */
    readonly window = 10,
  ) {}

  /** Adds a sample; a time at or before the last one replaces the history after it. */
  push(time: number, value: number): void {
    while (this.times.length > 0 && this.times[this.times.length - 1]! >= time) {
      this.times.pop();
      this.values.pop();
    }
    this.times.push(time);
    this.values.push(value);
    const oldest = time - this.window * 1.5;
    let drop = 0;
    while (drop < this.times.length && this.times[drop]! < oldest) drop++;
    if (drop > 0) {
      this.times.splice(0, drop);
      this.values.splice(0, drop);
    }
    this.changed();
  }

  /** Forgets the samples after `time` (s): the simulation was stepped back to it. */
  truncateAfter(time: number): void {
    let end = this.times.length;
    while (end > 0 && this.times[end - 1]! > time + 1e-9) end--;
    if (end === this.times.length) return;
    this.times.splice(end);
    this.values.splice(end);
    this.changed();
  }

  clear(): void {
    this.times.length = 0;
    this.values.length = 0;
    this.changed();
  }

  get last(): number | null {
    return this.values.length === 0 ? null : this.values[this.values.length - 1]!;
  }

  get lastTime(): number {
    return this.times.length === 0 ? 0 : this.times[this.times.length - 1]!;
  }
}

/** "Nice" tick spacing (1, 2 or 5 times a power of ten) for about `count` ticks over `span`. */
export function niceStep(span: number, count: number): number {
  if (!(span > 0)) return 1;
  const raw = span / Math.max(1, count);
  const power = 10 ** Math.floor(Math.log10(raw));
  const fraction = raw / power;
  const nice = fraction <= 1 ? 1 : fraction <= 2 ? 2 : fraction <= 5 ? 5 : 10;
  return nice * power;
}
