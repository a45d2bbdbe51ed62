import type { FrameLoop } from '@physical/canvas';

/** What {@link watchEnvironment} reports. */
export interface EnvironmentListener {
  /** The container or a watched element changed size: measure again. */
  resized(): void;
  /** Something scrolled: the container's place on screen may have changed. */
  scrolled(): void;
  /** `prefers-reduced-motion: reduce` started or stopped matching. */
  reducedMotionChanged(reduce: boolean): void;
  /** The device pixel ratio is `ratio` (also called once at start). */
  densityChanged(ratio: number): void;
}

/** A running watch: elements to observe for size, and the way to stop. */
export interface EnvironmentWatch {
  /** True while the user prefers reduced motion. */
  readonly prefersReducedMotion: boolean;
  /** Reports `resized` when `element` changes size too. */
  observe(element: Element): void;
  unobserve(element: Element): void;
  /** Stops watching and lifts the suspensions it made. */
  stop(): void;
}

/**
 * Watches what a Physical UI depends on outside itself: sizes (ResizeObserver), scrolling, the
 * motion preference and the pixel density; and suspends `loop` while the page is hidden or the
 * container is off screen, when nothing moving would be seen.
 */
export function watchEnvironment(
  container: HTMLElement,
  loop: FrameLoop,
  listener: EnvironmentListener,
): EnvironmentWatch {
  const undo: (() => void)[] = [];

  const resize = new ResizeObserver(() => listener.resized());
  resize.observe(container);
  undo.push(() => resize.disconnect());

  const onScroll = (): void => listener.scrolled();
  window.addEventListener('scroll', onScroll, { capture: true, passive: true });
  undo.push(() => window.removeEventListener('scroll', onScroll, { capture: true }));

  const motion = matchMedia('(prefers-reduced-motion: reduce)');
  const onMotion = (): void => listener.reducedMotionChanged(motion.matches);
  motion.addEventListener('change', onMotion);
  undo.push(() => motion.removeEventListener('change', onMotion));

  // A resolution query matches one density only: re-armed at the new one after each change.
  let density: MediaQueryList | null = null;
  const onDensity = (): void => {
    density?.removeEventListener('change', onDensity);
    const ratio = window.devicePixelRatio || 1;
    density = matchMedia(`(resolution: ${ratio}dppx)`);
    density.addEventListener('change', onDensity);
    listener.densityChanged(ratio);
  };
  onDensity();
  undo.push(() => density?.removeEventListener('change', onDensity));

  undo.push(loop.suspendWhileUnseen(container));

  return {
    get prefersReducedMotion() {
      return motion.matches;
    },
    observe: (element) => resize.observe(element),
    unobserve: (element) => resize.unobserve(element),
    stop: () => {
      for (const step of undo) step();
      undo.length = 0;
    },
  };
}
