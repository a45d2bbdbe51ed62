import type { Vec2, Vec2Like } from '@physical/engine';

/**
 * How the world is fitted into the element:
 * - `'none'`: `pixelsPerMeter` CSS pixels per metre, with the world point `origin` at the
 *   element's top-left corner. Resizing shows more or less of the world to the right and below;
 *   the scale and the origin stay.
 * - `'contain'`: the whole `viewBox` is visible, as large as fits, centred (letterboxed).
 * - `'cover'`: the `viewBox` fills the element, centred, cropped on one axis.
 */
export type FitMode = 'none' | 'contain' | 'cover';

/** A rectangle of the world (m, y-down): its top-left corner and its size. */
export interface ViewBox {
  readonly x: number;
  readonly y: number;
  readonly width: number;
  readonly height: number;
}

/** What decides the mapping from world to element: the element's settings and its size. */
export interface ViewportInput {
  /** Element width and height (CSS px). */
  readonly width: number;
  readonly height: number;
  /** Device pixels per CSS pixel. */
  readonly devicePixelRatio: number;
  readonly fit: FitMode;
  /** CSS px per metre, used when `fit` is `'none'` (or when there is no view box). */
  readonly pixelsPerMeter: number;
  /** World point (m) at the top-left corner when `fit` is `'none'`. */
  readonly origin: Vec2Like;
  /** World rectangle fitted by `'contain'` and `'cover'`; null means `'none'`. */
  readonly viewBox: ViewBox | null;
}

/**
 * The mapping from world coordinates (m, y-down) to element coordinates (CSS px from the
 * element's top-left corner): `screen = (world - origin) * scale`. Device pixels are CSS pixels
 * times `devicePixelRatio`.
 */
export interface Viewport {
  /** Element size (CSS px). */
  readonly width: number;
  readonly height: number;
  readonly devicePixelRatio: number;
  /** CSS px per metre actually used (the fitted scale for `'contain'` and `'cover'`). */
  readonly scale: number;
  /** World point (m) at the element's top-left corner. */
  readonly originX: number;
  readonly originY: number;
}

/**
 * Computes the viewport for an element size and its settings. With `'contain'` or `'cover'`, the
 * view box's centre is at the element's centre and the scale is the smaller (contain) or larger
 * (cover) of `width / viewBox.width` and `height / viewBox.height`.
 */
export function computeViewport(input: ViewportInput): Viewport {
  const { width, height, devicePixelRatio, fit, viewBox } = input;
  if (fit === 'none' || viewBox === null || width <= 0 || height <= 0) {
    return {
      width,
      height,
      devicePixelRatio,
      scale: input.pixelsPerMeter,
      originX: input.origin.x,
      originY: input.origin.y,
    };
  }
  const scaleX = width / viewBox.width;
  const scaleY = height / viewBox.height;
  const scale = fit === 'contain' ? Math.min(scaleX, scaleY) : Math.max(scaleX, scaleY);
  const centerX = viewBox.x + viewBox.width / 2;
  const centerY = viewBox.y + viewBox.height / 2;
  return {
    width,
    height,
    devicePixelRatio,
    scale,
    originX: centerX - width / 2 / scale,
    originY: centerY - height / 2 / scale,
  };
}

/** Element point (CSS px from the top-left corner) to world point (m). Writes and returns `out`. */
export function screenToWorld(
  viewport: Viewport,
  point: Vec2Like,
  out: Vec2 = { x: 0, y: 0 },
): Vec2 {
  out.x = viewport.originX + point.x / viewport.scale;
  out.y = viewport.originY + point.y / viewport.scale;
  return out;
}

/** World point (m) to element point (CSS px from the top-left corner). Writes and returns `out`. */
export function worldToScreen(
  viewport: Viewport,
  point: Vec2Like,
  out: Vec2 = { x: 0, y: 0 },
): Vec2 {
  out.x = (point.x - viewport.originX) * viewport.scale;
  out.y = (point.y - viewport.originY) * viewport.scale;
  return out;
}

/**
 * The world rectangle (m) the viewport shows, for culling. Writes and returns `out`.
 */
export function visibleWorldBounds(
  viewport: Viewport,
  out: { minX: number; minY: number; maxX: number; maxY: number } = {
    minX: 0,
    minY: 0,
    maxX: 0,
    maxY: 0,
  },
): { minX: number; minY: number; maxX: number; maxY: number } {
  out.minX = viewport.originX;
  out.minY = viewport.originY;
  out.maxX = viewport.originX + viewport.width / viewport.scale;
  out.maxY = viewport.originY + viewport.height / viewport.scale;
  return out;
}
