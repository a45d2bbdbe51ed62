import { arrowHeadLength } from './draw-arrow.ts';
import { PATH_BATCH_SIZE } from './path-batch.ts';

/**
 * Many arrows of one colour and opacity (collision arrows of one step), filled as outlines: shaft
 * and head in one polygon, one fill per batch of arrows (path-batch.ts: longer paths raster
 * slower), where `drawArrow` strokes the shaft and fills the head of each arrow with its own style.
 * Same proportions as `drawArrow`; the shaft starts square rather than round.
 */
export class ArrowBatch {
  private context: CanvasRenderingContext2D | null = null;
  private width = 0;
  private pixel = 0;
  private count = 0;
  private alpha = 1;

  /**
   * Starts a batch on `context` (in world metres): arrows `widthPx` CSS px wide, where a CSS
   * pixel is `pixel` metres, filled in `color` at `opacity` (times the context's alpha, which
   * {@link finish} puts back).
   */
  begin(
    context: CanvasRenderingContext2D,
    widthPx: number,
    pixel: number,
    color: string,
    opacity = 1,
  ): void {
    this.context = context;
    this.width = widthPx * pixel;
    this.pixel = pixel;
    this.count = 0;
    this.alpha = context.globalAlpha;
    context.globalAlpha = this.alpha * opacity;
    context.fillStyle = color;
    context.beginPath();
  }

  /** Adds an arrow from (`fromX`, `fromY`) along (`vectorX`, `vectorY`), in metres. */
  add(fromX: number, fromY: number, vectorX: number, vectorY: number): void {
    const length = Math.hypot(vectorX, vectorY);
    // Like drawArrow: nothing under half a pixel (and nothing for NaN).
    if (!(length >= 0.5 * this.pixel)) return;
    const context = this.context!;
    const head = arrowHeadLength(length, this.width, this.pixel);
    const ux = vectorX / length;
    const uy = vectorY / length;
    const tipX = fromX + vectorX;
    const tipY = fromY + vectorY;
    const baseX = tipX - ux * head;
    const baseY = tipY - uy * head;
    // Left of the arrow: (-uy, ux). Shaft half-width s, head half-width h.
    const s = this.width * 0.5;
    const h = head * 0.5;
    context.moveTo(fromX - uy * s, fromY + ux * s);
    context.lineTo(baseX - uy * s, baseY + ux * s);
    context.lineTo(baseX - uy * h, baseY + ux * h);
    context.lineTo(tipX, tipY);
    context.lineTo(baseX + uy * h, baseY - ux * h);
    context.lineTo(baseX + uy * s, baseY - ux * s);
    context.lineTo(fromX + uy * s, fromY - ux * s);
    context.closePath();
    if (++this.count % PATH_BATCH_SIZE === 0) {
      context.fill();
      context.beginPath();
    }
  }

  /** Fills what is left and restores the context's alpha. */
  finish(): void {
    const context = this.context!;
    if (this.count % PATH_BATCH_SIZE !== 0) context.fill();
    context.globalAlpha = this.alpha;
    this.context = null;
  }
}
