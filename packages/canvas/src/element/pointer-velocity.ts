/** How far back (ms) a release looks to measure the finger's velocity. */
export const VELOCITY_WINDOW_MS = 80;

const CAPACITY = 16;

/**
 * The velocity of a pointer from its last moves: the displacement over the last
 * {@link VELOCITY_WINDOW_MS}, divided by its time. A pointer that stopped before release
 * (no move in the window) has velocity 0, so letting go of a held element does not throw it.
 */
export class PointerVelocity {
  private readonly times = new Float64Array(CAPACITY);
  private readonly xs = new Float64Array(CAPACITY);
  private readonly ys = new Float64Array(CAPACITY);
  private count = 0;
  private next = 0;

  /** Forgets every sample. */
  reset(): void {
    this.count = 0;
    this.next = 0;
  }

  /** Records the pointer at (x, y) at `timeMs`. */
  add(timeMs: number, x: number, y: number): void {
    const i = this.next;
    this.times[i] = timeMs;
    this.xs[i] = x;
    this.ys[i] = y;
    this.next = (i + 1) % CAPACITY;
    if (this.count < CAPACITY) this.count++;
  }

  /** Velocity (units per second) at `nowMs`; writes and returns `out`. */
  velocity(nowMs: number, out: { x: number; y: number }): { x: number; y: number } {
    out.x = 0;
    out.y = 0;
    if (this.count < 2) return out;
    const last = (this.next - 1 + CAPACITY) % CAPACITY;
    if (nowMs - this.times[last]! > VELOCITY_WINDOW_MS) return out;
    let first = last;
    for (let k = 1; k < this.count; k++) {
      const i = (last - k + CAPACITY) % CAPACITY;
      if (this.times[last]! - this.times[i]! > VELOCITY_WINDOW_MS) break;
      first = i;
    }
    const dt = (this.times[last]! - this.times[first]!) / 1000;
    if (first === last || dt <= 0) return out;
    out.x = (this.xs[last]! - this.xs[first]!) / dt;
    out.y = (this.ys[last]! - this.ys[first]!) / dt;
    return out;
  }
}
