import type { FrameScheduler } from './frame-scheduler.ts';

/** What a {@link FrameLoop} drives. */
export interface FrameLoopTarget {
  /** Advances the simulation by `dt` seconds (always the loop's fixed step). */
  step(dt: number): void;
  /**
   * Draws a frame. `alpha` in [0, 1] is how far the display time is between the previous step
   * and the last one (for interpolation); `elapsed` is the scaled time since the last frame (s),
   * for things that fade (0 while paused).
   */
  render(alpha: number, elapsed: number): void;
  /**
   * True when nothing will change without an outside event (every body sleeps, nothing fades):
   * the loop then stops requesting frames until {@link FrameLoop.invalidate}.
   */
  isSettled(): boolean;
  /**
   * False while the simulation cannot take another step yet (a worker world still busy with
   * the last ones): the loop then takes no more steps this frame and drops the time, as after
   * a stall. Absent means always.
   */
  canStep?(): boolean;
}

/** Reasons the loop may be suspended; it runs only when none holds. */
export type SuspendReason = 'hidden' | 'offscreen' | 'detached';

/**
 * Below this (s), leftover time counts as a whole step: frame times are rounded milliseconds
 * or sums of 1000/60, and 60 frames of a 60 Hz display must give exactly 60 steps, not 59.
 */
const STEP_TOLERANCE = 1e-7;

/**
 * The fixed-step loop: display frames in, simulation steps of exactly `fixedStep` seconds out.
 *
 * Each frame adds the real time since the previous frame, times `timeScale`, to an
 * accumulator, then takes as many fixed steps as fit (at most `maxStepsPerFrame`: after a stall
 * the backlog is dropped rather than replayed, so a slow device slows the simulation down
 * instead of freezing in a spiral of ever longer frames). What is left, as a fraction of a step,
 * is `alpha`: the renderer blends the poses before and after the last step by it, so motion is
 * smooth on a 120 Hz display while the physics stays the same as at 60 Hz.
 *
 * The first frame after a (re)start counts no time: a hidden tab, a sleeping world or a
 * suspended loop resumes without a jump.
 */
export class FrameLoop {
  /** Simulation step (s). Default 1/60. */
  fixedStep: number = 1 / 60;
  /** Most steps taken in one frame before the backlog is dropped. Default 4. */
  maxStepsPerFrame = 4;
  /** Simulated seconds per real second (0.25 for slow motion). Default 1. */
  timeScale = 1;
  /** When true, frames still render on request but no time passes. */
  paused = false;
  /** Steps taken in total. */
  stepCount = 0;
  /** Frames rendered in total. */
  frameCount = 0;

  private readonly target: FrameLoopTarget;
  private scheduler: FrameScheduler;
  private handle = 0;
  private isScheduled = false;
  private lastTimeMs: number | null = null;
  private accumulator = 0;
  private readonly suspended = new Set<SuspendReason>();
  private readonly onFrame = (timeMs: number): void => {
    this.isScheduled = false;
    this.frame(timeMs);
  };

  constructor(target: FrameLoopTarget, scheduler: FrameScheduler) {
    this.target = target;
    this.scheduler = scheduler;
  }

  /** True while a frame is requested. */
  get isRunning(): boolean {
    return this.isScheduled;
  }

  /** True while suspended for at least one reason. */
  get isSuspended(): boolean {
    return this.suspended.size > 0;
  }

  /** Something changed: make sure a frame comes (unless suspended). */
  invalidate(): void {
    if (this.isScheduled || this.suspended.size > 0) return;
    this.isScheduled = true;
    this.handle = this.scheduler.requestFrame(this.onFrame);
  }

  /** Stops requesting frames until every reason is lifted by {@link resume}. */
  suspend(reason: SuspendReason): void {
    this.suspended.add(reason);
    this.cancel();
  }

  /** Lifts a suspension; the first frame after it counts no time. */
  resume(reason: SuspendReason): void {
    if (!this.suspended.delete(reason)) return;
    this.invalidate();
  }

  /**
   * Suspends the loop while `element` is off screen (IntersectionObserver) or the page is hidden
   * (visibilitychange), when nothing it draws would be seen. Browser only. Returns the function
   * that stops watching and lifts both suspensions.
   */
  suspendWhileUnseen(element: Element): () => void {
    const intersection = new IntersectionObserver((entries) => {
      if (entries[entries.length - 1]!.isIntersecting) this.resume('offscreen');
      else this.suspend('offscreen');
    });
    intersection.observe(element);
    const onVisibility = (): void => {
      if (document.visibilityState === 'hidden') this.suspend('hidden');
      else this.resume('hidden');
    };
    onVisibility();
    document.addEventListener('visibilitychange', onVisibility);
    return () => {
      intersection.disconnect();
      document.removeEventListener('visibilitychange', onVisibility);
      this.resume('offscreen');
      this.resume('hidden');
    };
  }

  /** Replaces the scheduler (a pending frame moves to the new one). */
  setScheduler(scheduler: FrameScheduler): void {
    const wasScheduled = this.isScheduled;
    this.cancel();
    this.scheduler = scheduler;
    if (wasScheduled) this.invalidate();
  }

  /** Forgets the time carried between frames (after the world is replaced). */
  reset(): void {
    this.accumulator = 0;
    this.lastTimeMs = null;
  }

  /**
   * Takes exactly one fixed step now, whatever the clock says, and renders it at `alpha` 1 (the
   * state after the step; no time passes for fading things). For stepping a paused simulation by
   * hand: the accumulator is untouched, so a running loop keeps its own pace.
   */
  stepOnce(): void {
    this.target.step(this.fixedStep);
    this.stepCount++;
    this.target.render(1, 0);
    this.frameCount++;
  }

  /** Runs one frame at `timeMs` (ms): steps, renders, and requests the next frame if needed. */
  frame(timeMs: number): void {
    const last = this.lastTimeMs;
    this.lastTimeMs = timeMs;
    const realElapsed = last === null ? 0 : Math.max(0, (timeMs - last) / 1000);
    const elapsed = this.paused ? 0 : realElapsed * this.timeScale;
    const fixedStep = this.fixedStep;
    this.accumulator += elapsed;
    let steps = 0;
    while (this.accumulator >= fixedStep - STEP_TOLERANCE && steps < this.maxStepsPerFrame) {
      if (this.target.canStep?.() === false) break;
      this.target.step(fixedStep);
      this.accumulator -= fixedStep;
      steps++;
    }
    this.stepCount += steps;
    // Catch-up cap reached (or the target is busy): drop the whole steps of the backlog, keep
    // the fraction.
    if (this.accumulator >= fixedStep - STEP_TOLERANCE) this.accumulator %= fixedStep;
    const alpha = this.paused ? 1 : Math.min(1, Math.max(0, this.accumulator / fixedStep));
    this.target.render(alpha, elapsed);
    this.frameCount++;
    if (this.target.isSettled()) {
      // Asleep: the next start counts no time, so the world does not leap forward.
      this.lastTimeMs = null;
    } else {
      this.invalidate();
    }
  }

  private cancel(): void {
    if (this.isScheduled) this.scheduler.cancelFrame(this.handle);
    this.isScheduled = false;
    this.lastTimeMs = null;
  }
}
