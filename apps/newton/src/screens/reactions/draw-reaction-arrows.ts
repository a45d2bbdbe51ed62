import { ARROW_COLORS, ArrowBatch } from '@physical/canvas';
import {
  averageForce,
  reactionArrowLength,
  type ArrowMeasure,
  type VisibleArrow,
} from './collision-arrows.ts';

/**
 * Opacity steps the fading arrows are filled in: one batch per colour and step. Four read as a
 * fade and cost half the fills of eight (each fill a pass of a slow phone's CPU raster).
 */
const FADE_STEPS = 4;
/** Arrow width in CSS px. */
const WIDTH_PX = 3;
const batch = new ArrowBatch();

/**
 * Draws each visible collision's two arrows, the force on A (`force` colour, along the normal)
 * and the equal and opposite one on B (`impulse` colour), as impulses or average forces over
 * `contactTime` (s). Filled in batches of one colour and opacity step: a pile of 50 particles
 * on a tilted tray collides in every step, and an arrow with its own stroke, fill and styles
 * each, two per contact, cost a slow phone more than drawing the particles.
 */
export function drawReactionArrows(
  context: CanvasRenderingContext2D,
  scale: number,
  visible: readonly VisibleArrow[],
  measure: ArrowMeasure,
  contactTime: number,
  reducedMotion: boolean,
): void {
  if (visible.length === 0) return;
  for (let side = 0; side < 2; side++) {
    const color = side === 0 ? ARROW_COLORS.force : ARROW_COLORS.impulse;
    const sign = side === 0 ? 1 : -1;
    for (let step = FADE_STEPS; step >= 1; step--) {
      let begun = false;
      for (const { arrow, opacity } of visible) {
        if ((reducedMotion ? FADE_STEPS : Math.ceil(opacity * FADE_STEPS)) !== step) continue;
        if (!begun) {
          batch.begin(context, WIDTH_PX, 1 / scale, color, step / FADE_STEPS);
          begun = true;
        }
        const value =
          measure === 'impulse' ? arrow.impulse : averageForce(arrow.impulse, contactTime);
        const length = sign * reactionArrowLength(value, measure);
        batch.add(arrow.x, arrow.y, arrow.nx * length, arrow.ny * length);
      }
      if (begun) batch.finish();
    }
  }
}
