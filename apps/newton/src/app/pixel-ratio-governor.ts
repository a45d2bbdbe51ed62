import { CANVAS_PIXEL_RATIO } from './theme.ts';

/** Below this many frames a second a canvas is too slow for its pixels. */
export const SLOW_FRAME_RATE = 45;
/** Milliseconds between two looks at a canvas's frame count. */
export const SAMPLE_MS = 250;
/**
 * Slow looks in a row before the canvas draws fewer pixels: 0.75 s. A hiccup (a collection, a
 * layout) costs one look, or two; three in a row are a canvas too slow for its pixels. 1.5 s,
 * as before, left a slow phone stuttering at the sharper ratio through the first second and a
 * half of every run (Reactions with 50 particles at 4x CPU slowdown: 32-35 frames/s, then 50).
 */
export const SLOW_SAMPLES = 3;
/** The fewest device pixels per CSS px: one, the page's own resolution. */
export const MIN_PIXEL_RATIO = 1;

/**
 * Dynamic resolution for a simulation canvas: it draws at {@link CANVAS_PIXEL_RATIO} device px
 * per CSS px, and at one once its frame rate stayed under {@link SLOW_FRAME_RATE} for
 * {@link SLOW_SAMPLES} looks ({@link SAMPLE_MS} apart) of running. On a phone whose CPU draws the canvas (no GPU raster),
 * filling the pixels is most of a frame: 4 device px per CSS px cost about three times the raster
 * of one (Reactions with 50 particles, Chromium's software raster, 4x CPU slowdown). It does not
 * go back up: a sharper canvas that then stutters is worse than a softer one that does not.
 */
export class PixelRatioGovernor {
  /** The device pixels per CSS px to draw at now. */
  ratio = CANVAS_PIXEL_RATIO;
  private slow = 0;

  /**
   * Counts one sample: `frames` drawn in `ms` milliseconds, `running` when the canvas ran all
   * that time (a canvas at rest or hidden draws nothing and says nothing of its speed). Returns
   * the ratio to draw at.
   */
  sample(frames: number, ms: number, running: boolean): number {
    if (!running || !(ms > 0)) {
      this.slow = 0;
      return this.ratio;
    }
    const rate = (frames * 1000) / ms;
    this.slow = rate < SLOW_FRAME_RATE ? this.slow + 1 : 0;
    if (this.slow >= SLOW_SAMPLES && this.ratio > MIN_PIXEL_RATIO) {
      this.ratio = MIN_PIXEL_RATIO;
      this.slow = 0;
    }
    return this.ratio;
  }
}
