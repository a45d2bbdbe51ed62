import type { Body } from '@physical/engine';
import type { Pose } from './pose.ts';

/** What a custom draw function gets besides the context. */
export interface BodyDrawInfo {
  /** The body being drawn. */
  readonly body: Body;
  /** The interpolated pose it is drawn at (m, rad). */
  readonly pose: Readonly<Pose>;
  /** CSS px per metre: divide a width in CSS px by it to get metres. */
  readonly pixelsPerMeter: number;
  /** The body's resolved style. */
  readonly style: ResolvedBodyStyle;
}

/**
 * How a body looks. The engine holds no styling: set it with `canvas.setStyle(body, style)` or
 * a `canvas.styleFor` callback; every field is optional and falls back to a default derived from
 * the body's type (a Material-dark palette).
 */
export interface BodyStyle {
  /** Fill colour (any CSS colour); `'transparent'` for none. */
  readonly fill?: string;
  /** Outline colour; `'transparent'` for none. */
  readonly stroke?: string;
  /** Opacity, 0 to 1. Default 1. */
  readonly opacity?: number;
  /** Outline width (CSS px). Default 1 (2 for walls). */
  readonly lineWidth?: number;
  /** Drawing order: higher is drawn later, on top. Default 0; ties keep the world's order. */
  readonly zIndex?: number;
  /** Text drawn at the body's position, upright, in CSS px. */
  readonly label?: string;
  /** Label colour. Default: a light grey. */
  readonly labelColor?: string;
  /** False hides the body. Default true. */
  readonly visible?: boolean;
  /**
   * Draws the body instead of its shapes (images, sprites). The context is in body-local metres:
   * the origin is the body's position and +x its rotated x axis, so
   * `context.drawImage(image, -w / 2, -h / 2, w, h)` draws a `w` x `h` metre image centred on it.
   */
  readonly draw?: (context: CanvasRenderingContext2D, info: BodyDrawInfo) => void;
}

/** A {@link BodyStyle} with every default filled in. */
export interface ResolvedBodyStyle {
  readonly fill: string;
  readonly stroke: string;
  readonly opacity: number;
  readonly lineWidth: number;
  readonly zIndex: number;
  readonly label: string | null;
  readonly labelColor: string;
  readonly visible: boolean;
  readonly draw: ((context: CanvasRenderingContext2D, info: BodyDrawInfo) => void) | null;
}

/**
 * Fills of dynamic bodies, cycled in the order bodies are first drawn: Material Design's 300
 * tones, readable on the dark background.
 */
export const DYNAMIC_PALETTE: readonly string[] = [
  '#4fc3f7', // light blue
  '#ffb74d', // orange
  '#81c784', // green
  '#f06292', // pink
  '#ba68c8', // purple
  '#4db6ac', // teal
  '#ffd54f', // amber
  '#7986cb', // indigo
];

/** The element's default background: Material's dark surface. */
export const DEFAULT_BACKGROUND = '#121212';

const STATIC_STYLE: ResolvedBodyStyle = {
  fill: '#37474f',
  stroke: '#90a4ae',
  opacity: 1,
  lineWidth: 2,
  zIndex: 0,
  label: null,
  labelColor: '#eceff1',
  visible: true,
  draw: null,
};

const KINEMATIC_STYLE: ResolvedBodyStyle = { ...STATIC_STYLE, fill: '#546e7a', stroke: '#cfd8dc' };

const dynamicStyles: readonly ResolvedBodyStyle[] = DYNAMIC_PALETTE.map((fill) => ({
  ...STATIC_STYLE,
  fill,
  stroke: 'rgba(0, 0, 0, 0.45)',
  lineWidth: 1,
}));

/**
 * The default style of a body: static and kinematic bodies in blue-greys, dynamic bodies in the
 * palette colour number `serial` (cycled).
 */
export function defaultBodyStyle(body: Body, serial: number): ResolvedBodyStyle {
  if (body.type === 'static') return STATIC_STYLE;
  if (body.type === 'kinematic') return KINEMATIC_STYLE;
  return dynamicStyles[serial % dynamicStyles.length]!;
}

/** Fills the fields `style` leaves out with those of `base`. */
export function resolveBodyStyle(
  style: BodyStyle | null | undefined,
  base: ResolvedBodyStyle,
): ResolvedBodyStyle {
  if (style === null || style === undefined) return base;
  return {
    fill: style.fill ?? base.fill,
    stroke: style.stroke ?? base.stroke,
    opacity: style.opacity ?? base.opacity,
    lineWidth: style.lineWidth ?? base.lineWidth,
    zIndex: style.zIndex ?? base.zIndex,
    label: style.label ?? base.label,
    labelColor: style.labelColor ?? base.labelColor,
    visible: style.visible ?? base.visible,
    draw: style.draw ?? base.draw,
  };
}
