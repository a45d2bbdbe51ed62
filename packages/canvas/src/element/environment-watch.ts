import type { FrameLoop } from './frame-loop.ts';

/** What the element hears from its environment. */
export interface EnvironmentListener {
  /** The element's content box changed size (CSS px). */
  resized(width: number, height: number): void;
  /** `prefers-reduced-motion: reduce` started or stopped matching. */
  reducedMotionChanged(reduce: boolean): void;
  /** The device pixel ratio changed (a window moved to another screen, or a zoom). */
  densityChanged(): void;
  /** Space was pressed while the element had focus. */
  togglePause(): void;
}

/**
 * Watches what decides whether and how the element draws: its size (ResizeObserver), whether
 * it is on screen (IntersectionObserver) and the page visible (visibilitychange) — each
 * suspends the loop while false — the pixel density, the motion preference and the keyboard.
 * Returns the function that stops watching and lifts the suspensions.
 */
export function watchEnvironment(
  element: HTMLElement,
  loop: FrameLoop,
  listener: EnvironmentListener,
): () => void {
  const undo: (() => void)[] = [];

  const resize = new ResizeObserver((entries) => {
    const box = entries[entries.length - 1]!.contentRect;
    listener.resized(box.width, box.height);
  });
  resize.observe(element);
  undo.push(() => resize.disconnect());

  undo.push(loop.suspendWhileUnseen(element));

  const motion = matchMedia('(prefers-reduced-motion: reduce)');
  const onMotion = (): void => listener.reducedMotionChanged(motion.matches);
  onMotion();
  motion.addEventListener('change', onMotion);
  undo.push(() => motion.removeEventListener('change', onMotion));

  // A resolution query matches one density only: re-armed at the new one after each change.
  let density: MediaQueryList | null = null;
  const onDensity = (): void => {
    density?.removeEventListener('change', onDensity);
    density = matchMedia(`(resolution: ${window.devicePixelRatio}dppx)`);
    density.addEventListener('change', onDensity);
    listener.densityChanged();
  };
  onDensity();
  undo.push(() => density?.removeEventListener('change', onDensity));

  const onKey = (event: KeyboardEvent): void => {
    if (event.key !== ' ' || event.repeat || event.target !== element) return;
    event.preventDefault();
    listener.togglePause();
  };
  element.addEventListener('keydown', onKey);
  undo.push(() => element.removeEventListener('keydown', onKey));

  return () => {
    for (const step of undo) step();
  };
}
