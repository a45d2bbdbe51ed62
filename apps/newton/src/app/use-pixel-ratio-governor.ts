import { useEffect, useState, type RefObject } from 'react';
import type { PhysicalCanvasElement } from '@physical/canvas';
import { PixelRatioGovernor, SAMPLE_MS } from './pixel-ratio-governor.ts';

/**
 * The device pixels per CSS px a simulation canvas draws at (its `maxPixelRatio`): fewer once it
 * runs too slowly for them ({@link PixelRatioGovernor}). Looks at the canvas' frame count every
 * {@link SAMPLE_MS} while `active`: no work in its frames.
 */
export function usePixelRatioGovernor(
  canvasRef: RefObject<PhysicalCanvasElement | null>,
  active: boolean,
): number {
  const [governor] = useState(() => new PixelRatioGovernor());
  const [ratio, setRatio] = useState(governor.ratio);
  useEffect(() => {
    if (!active) return;
    let frames = canvasRef.current?.frameCount ?? 0;
    let time = performance.now();
    let wasRunning = canvasRef.current?.isRunning ?? false;
    const id = setInterval(() => {
      const canvas = canvasRef.current;
      const now = performance.now();
      const count = canvas?.frameCount ?? 0;
      const running = canvas !== null && wasRunning && canvas.isRunning;
      setRatio(governor.sample(count - frames, now - time, running));
      frames = count;
      time = now;
      wasRunning = canvas?.isRunning ?? false;
    }, SAMPLE_MS);
    return () => clearInterval(id);
  }, [active, canvasRef, governor]);
  return ratio;
}
