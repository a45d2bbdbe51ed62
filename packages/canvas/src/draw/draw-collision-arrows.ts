import { drawArrow } from './draw-arrow.ts';

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

/**
 * Draws each collision as two equal and opposite force arrows from the contact point (Newton's
 * third law): `force * forceScale` metres long, on a context in world coordinates.
 */
export function drawCollisionArrows(
  context: CanvasRenderingContext2D,
  pixelsPerMeter: number,
  arrows: readonly CollisionArrowView[],
  forceScale: number,
): void {
  const from = { x: 0, y: 0 };
  const vector = { x: 0, y: 0 };
  for (let i = 0; i < arrows.length; i++) {
    const arrow = arrows[i]!;
    if (arrow.opacity <= 0) continue;
    from.x = arrow.x;
    from.y = arrow.y;
    vector.x = arrow.forceX * forceScale;
    vector.y = arrow.forceY * forceScale;
    const style = { kind: 'force', opacity: arrow.opacity } as const;
    drawArrow(context, pixelsPerMeter, from, vector, style);
    vector.x = -vector.x;
    vector.y = -vector.y;
    drawArrow(context, pixelsPerMeter, from, vector, style);
  }
}
