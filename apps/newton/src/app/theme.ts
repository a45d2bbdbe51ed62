/** The learner asked for less motion: no transitions, no ripples, no fading arrows. */
export const REDUCED_MOTION =
  typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;

/** A touch screen with no hover (a phone or tablet): tooltips wait for a long press. */
export const TOUCH = typeof matchMedia === 'function' && matchMedia('(hover: none)').matches;

/** Colours of the two squares on the Forces screen (and of their graph lines). */
export const SQUARE_COLORS = ['#4fc3f7', '#ffb74d'] as const;

/**
 * Device pixels per CSS px the simulation canvases draw at, at most: on a 3x phone a full-density
 * canvas fills 9 device pixels per CSS px each frame, and under 4x CPU throttling Reactions with
 * 50 particles drew 37-43 frames/s at 3x, 45-54 at 2x and 60 at 1x (npm run bench:newton).
 * Reactions drops to 1x when its frames stay slow (`PixelRatioGovernor`).
 */
export const CANVAS_PIXEL_RATIO = 2;
