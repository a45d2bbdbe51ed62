import { ArrowBatch } from './arrow-batch.ts';
import { ARROW_COLORS } from './draw-arrow.ts';

/** A collision-force arrow pair as drawn: at a contact point, the force on B and its opposite on A. */
export interface CollisionArrowView {
  /** Contact point (m, world). */
  readonly x: number;
  readonly y: number;
  /** Average force on body B during the step (N, world); body A got the opposite. */
  readonly forceX: number;
  readonly forceY: number;
  /** 1 when new, falling to 0 as it fades. */
  readonly opacity: number;
}

const batch = new ArrowBatch();

/**
 * Draws each collision as two equal and opposite force arrows from the contact point (Newton's
 * third law): `force * forceScale` metres long, on a context in world coordinates.
 *
 * Arrows recorded in the same step have the same age, hence the same opacity, and sit next to
 * each other in `arrows`: each such run is drawn as one batch.
 */
export function drawCollisionArrows(
  context: CanvasRenderingContext2D,
  pixelsPerMeter: number,
  arrows: readonly CollisionArrowView[],
  forceScale: number,
): void {
  const pixel = 1 / pixelsPerMeter;
  const color = ARROW_COLORS.force;
  let i = 0;
  while (i < arrows.length) {
    const opacity = arrows[i]!.opacity;
    if (opacity <= 0) {
      i++;
      continue;
    }
    batch.begin(context, 2, pixel, color, opacity);
    for (; i < arrows.length && arrows[i]!.opacity === opacity; i++) {
      const arrow = arrows[i]!;
      const vectorX = arrow.forceX * forceScale;
      const vectorY = arrow.forceY * forceScale;
      batch.add(arrow.x, arrow.y, vectorX, vectorY);
      batch.add(arrow.x, arrow.y, -vectorX, -vectorY);
    }
    batch.finish();
  }
}
