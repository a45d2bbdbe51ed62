import { DEFAULT_BACKGROUND, DYNAMIC_PALETTE } from '@physical/canvas';
import type { Body, Geometry, World } from '@physical/engine';

/** How a worker draws its world into an OffscreenCanvas (see {@link WorkerWorldOptions.offscreen}). */
export interface OffscreenView {
  /** The canvas, from `canvasElement.transferControlToOffscreen()`. */
  readonly canvas: OffscreenCanvas;
  /** CSS px per metre. Default 50. */
  readonly pixelsPerMeter?: number;
  /** World point (m) at the canvas's top-left corner. Default (0, 0). */
  readonly origin?: { readonly x: number; readonly y: number };
  /** Device pixels per CSS px (the page's `devicePixelRatio`). Default 1. */
  readonly devicePixelRatio?: number;
  /** Background colour. Default `<physical-canvas>`'s. */
  readonly background?: string;
}

const STATIC_FILL = '#37474f';
const STATIC_STROKE = '#90a4ae';
const KINEMATIC_FILL = '#546e7a';
/** Bodies per path: `<physical-canvas>`'s measured sweet spot for software raster. */
const PATH_BATCH_SIZE = 64;

/**
 * Draws a world in the worker, after each step, in `<physical-canvas>`'s default look (its
 * palette and background): one path per colour. Styles and overlays are the page canvas's; here
 * only the default look.
 */
export class OffscreenRenderer {
  private readonly context: OffscreenCanvasRenderingContext2D;
  private readonly scale: number;
  private readonly originX: number;
  private readonly originY: number;
  private readonly background: string;

  constructor(view: OffscreenView) {
    this.context = view.canvas.getContext('2d')!;
    const ratio = view.devicePixelRatio ?? 1;
    this.scale = (view.pixelsPerMeter ?? 50) * ratio;
    this.originX = view.origin?.x ?? 0;
    this.originY = view.origin?.y ?? 0;
    this.background = view.background ?? DEFAULT_BACKGROUND;
  }

  draw(world: World): void {
    const context = this.context;
    const { width, height } = context.canvas;
    context.setTransform(1, 0, 0, 1, 0, 0);
    context.fillStyle = this.background;
    context.fillRect(0, 0, width, height);
    const k = this.scale;
    context.setTransform(k, 0, 0, k, -this.originX * k, -this.originY * k);
    context.lineWidth = 1 / k;
    const bodies = world.bodies;
    // Colour i of the palette: dynamic bodies number i, i + 8, ... (as the canvas's default).
    for (let colour = -2; colour < DYNAMIC_PALETTE.length; colour++) {
      context.fillStyle =
        colour === -2 ? STATIC_FILL : colour === -1 ? KINEMATIC_FILL : DYNAMIC_PALETTE[colour]!;
      context.strokeStyle = colour < 0 ? STATIC_STROKE : 'rgba(0, 0, 0, 0.45)';
      context.beginPath();
      let inPath = 0;
      let dynamic = 0;
      for (let i = 0; i < bodies.length; i++) {
        const body = bodies[i]!;
        const own =
          body.type === 'static'
            ? -2
            : body.type === 'kinematic'
              ? -1
              : dynamic++ % DYNAMIC_PALETTE.length;
        if (own !== colour) continue;
        appendBody(context, body);
        // Software raster slows down on very long paths: paint in chunks (as the page canvas).
        if (++inPath === PATH_BATCH_SIZE) {
          context.fill();
          context.stroke();
          context.beginPath();
          inPath = 0;
        }
      }
      if (inPath > 0) {
        context.fill();
        context.stroke();
      }
    }
  }
}

function appendBody(context: OffscreenCanvasRenderingContext2D, body: Body): void {
  const position = body.position;
  const angle = body.angle;
  const cos = Math.cos(angle);
  const sin = Math.sin(angle);
  const px = position.x;
  const py = position.y;
  for (const shape of body.shapes) {
    const g: Geometry = shape.geometry;
    if (g.kind === 'circle') {
      const x = px + cos * g.centerX - sin * g.centerY;
      const y = py + sin * g.centerX + cos * g.centerY;
      context.moveTo(x + g.radius, y);
      context.arc(x, y, g.radius, 0, 2 * Math.PI);
    } else if (g.kind === 'polygon') {
      // Rounded corners are drawn sharp here: a small difference of look, not of physics.
      for (let i = 0; i < g.count; i++) {
        const lx = g.vertices[2 * i]!;
        const ly = g.vertices[2 * i + 1]!;
        const x = px + cos * lx - sin * ly;
        const y = py + sin * lx + cos * ly;
        if (i === 0) context.moveTo(x, y);
        else context.lineTo(x, y);
      }
      context.closePath();
    } else if (g.kind === 'capsule') {
      const x1 = px + cos * g.x1 - sin * g.y1;
      const y1 = py + sin * g.x1 + cos * g.y1;
      const x2 = px + cos * g.x2 - sin * g.y2;
      const y2 = py + sin * g.x2 + cos * g.y2;
      const side = Math.atan2(y2 - y1, x2 - x1) + Math.PI / 2;
      context.moveTo(
        x2 + g.radius * Math.cos(side - Math.PI),
        y2 + g.radius * Math.sin(side - Math.PI),
      );
      context.arc(x2, y2, g.radius, side - Math.PI, side);
      context.arc(x1, y1, g.radius, side, side + Math.PI);
      context.closePath();
    } else {
      context.moveTo(px + cos * g.x1 - sin * g.y1, py + sin * g.x1 + cos * g.y1);
      context.lineTo(px + cos * g.x2 - sin * g.y2, py + sin * g.x2 + cos * g.y2);
    }
  }
}
