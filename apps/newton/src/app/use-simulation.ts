import { useCallback, useReducer, useState } from 'react';
import type { PhysicalCanvasElement } from '@physical/canvas';
import type { World } from '@physical/engine';

/** Simulated seconds per fixed step (the canvas's default rate). */
export const STEP = 1 / 60;
/** Time scale of slow motion. */
export const SLOW_MOTION = 0.25;

/** Play / pause and slow-motion state of a screen, and a single step for its worlds. */
export function useSimulation() {
  const [paused, setPaused] = useState(false);
  const [slow, setSlow] = useState(false);
  const togglePlay = useCallback(() => setPaused((value) => !value), []);
  const toggleSlow = useCallback(() => setSlow((value) => !value), []);
  // Readouts re-render after a single step (the live ticker stops while paused).
  const [, rerender] = useReducer((count: number) => count + 1, 0);
  const step = useCallback(
    (pairs: readonly { world: World; canvas: PhysicalCanvasElement | null }[]) => {
      stepOnce(pairs);
      rerender();
    },
    [],
  );
  return {
    paused,
    setPaused,
    slow,
    togglePlay,
    toggleSlow,
    step,
    timeScale: slow ? SLOW_MOTION : 1,
  };
}

/**
 * Advances paused worlds by one fixed step and draws them: through the canvas that runs each
 * (`canvas.step()`: its own fixed step, drawn at once), or the world alone while unmounted.
 */
export function stepOnce(
  pairs: readonly { world: World; canvas: PhysicalCanvasElement | null }[],
): void {
  for (const { world, canvas } of pairs) {
    if (canvas !== null && canvas.world === world) canvas.step();
    else world.step(STEP);
  }
}

/** Simulated time of a world stepped at the fixed rate (s). */
export function simulatedTime(world: World): number {
  return world.steps * STEP;
}
