/**
 * Schedules animation frames: `requestAnimationFrame` in a page, or a manual clock in tests (60
 * and 120 Hz pacing, frame counting) and in tools that render offline.
 */
export interface FrameScheduler {
  /** Calls `callback` once, at the next frame, with the frame's time (ms, monotonic). */
  requestFrame(callback: (timeMs: number) => void): number;
  /** Cancels a request made by {@link FrameScheduler.requestFrame}. */
  cancelFrame(handle: number): void;
}

/** The page's display-synchronised scheduler: `requestAnimationFrame`, read at call time. */
export const animationFrameScheduler: FrameScheduler = {
  requestFrame: (callback) => requestAnimationFrame(callback),
  cancelFrame: (handle) => cancelAnimationFrame(handle),
};

/**
 * A scheduler driven by hand: {@link ManualFrameScheduler.advance} runs the pending frame at a
 * chosen time. Deterministic pacing for tests: `advance(1000 / 120)` is one frame of a 120 Hz
 * display. {@link ManualFrameScheduler.requests} counts every frame ever requested.
 */
export class ManualFrameScheduler implements FrameScheduler {
  /** Current time (ms). */
  now = 0;
  /** Number of frames requested so far. */
  requests = 0;
  private pending: ((timeMs: number) => void) | null = null;
  private nextHandle = 1;
  private pendingHandle = 0;

  /** Starts the clock at `startMs` (ms). */
  constructor(startMs = 0) {
    this.now = startMs;
  }

  /** True when a frame is requested and not yet run. */
  get hasPendingFrame(): boolean {
    return this.pending !== null;
  }

  /** {@inheritDoc FrameScheduler.requestFrame} */
  requestFrame(callback: (timeMs: number) => void): number {
    this.requests++;
    this.pending = callback;
    this.pendingHandle = this.nextHandle++;
    return this.pendingHandle;
  }

  /** {@inheritDoc FrameScheduler.cancelFrame} */
  cancelFrame(handle: number): void {
    if (handle === this.pendingHandle) this.pending = null;
  }

  /**
   * Moves the clock forward by `ms` and runs the pending frame, if any. Returns true if a frame
   * ran (false means the loop had stopped requesting frames).
   */
  advance(ms: number): boolean {
    this.now += ms;
    const callback = this.pending;
    if (callback === null) return false;
    this.pending = null;
    callback(this.now);
    return true;
  }
}
