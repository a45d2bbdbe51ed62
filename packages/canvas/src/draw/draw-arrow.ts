import type { Vec2Like } from '@physical/engine';

/** What an arrow stands for: each kind has its own colour. */
export type ArrowKind = 'force' | 'velocity' | 'impulse';

/** Colours of the arrow kinds (Material-dark accents). */
export const ARROW_COLORS: Readonly<Record<ArrowKind, string>> = {
  force: '#ff8a65',
  velocity: '#64ffda',
  impulse: '#ffd740',
};

/** How an arrow looks. */
export interface ArrowStyle {
  /** Picks the colour from {@link ARROW_COLORS}. Default `'force'`. */
  readonly kind?: ArrowKind;
  /** Overrides the colour. */
  readonly color?: string;
  /** Shaft width (CSS px). Default 2. */
  readonly width?: number;
  /** Opacity, 0 to 1. Default 1. */
  readonly opacity?: number;
}

/**
 * Draws an arrow from `from` along `vector`, both in world metres, on a context already in world
 * coordinates (as in `canvas.drawOverlay`). `pixelsPerMeter` (CSS px per metre) keeps the width
 * and head size constant on screen. Vectors shorter than half a CSS pixel are not drawn.
 *
 * @example
 * // a force of 20 N drawn at 0.05 m per newton:
 * drawArrow(context, 40, body.centerOfMass, { x: 0, y: 20 * 0.05 }, { kind: 'force' });
 */
export function drawArrow(
  context: CanvasRenderingContext2D,
  pixelsPerMeter: number,
  from: Vec2Like,
  vector: Vec2Like,
  style: ArrowStyle = {},
): void {
  const length = Math.hypot(vector.x, vector.y);
  const pixel = 1 / pixelsPerMeter;
  if (!(length >= 0.5 * pixel)) return;
  const width = (style.width ?? 2) * pixel;
  const head = arrowHeadLength(length, width, pixel);
  const ux = vector.x / length;
  const uy = vector.y / length;
  const tipX = from.x + vector.x;
  const tipY = from.y + vector.y;
  const baseX = tipX - ux * head;
  const baseY = tipY - uy * head;
  const half = head * 0.5;
  const color = style.color ?? ARROW_COLORS[style.kind ?? 'force'];
  const alpha = context.globalAlpha;
  context.globalAlpha = alpha * (style.opacity ?? 1);
  context.strokeStyle = color;
  context.fillStyle = color;
  context.lineWidth = width;
  context.lineCap = 'round';
  context.beginPath();
  context.moveTo(from.x, from.y);
  context.lineTo(baseX, baseY);
  context.stroke();
  context.beginPath();
  context.moveTo(tipX, tipY);
  context.lineTo(baseX - uy * half, baseY + ux * half);
  context.lineTo(baseX + uy * half, baseY - ux * half);
  context.closePath();
  context.fill();
  context.globalAlpha = alpha;
}

/**
 * Length (m) of the head of an arrow `length` metres long with a shaft `width` metres wide, where
 * a CSS pixel is `pixel` metres: four shaft widths plus four pixels, at most half the arrow. The
 * head is as wide as half its length.
 */
export function arrowHeadLength(length: number, width: number, pixel: number): number {
  return Math.min(length * 0.5, width * 4 + 4 * pixel);
}
