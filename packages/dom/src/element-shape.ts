import type { ShapeOptions } from '@physical/engine';

/**
 * The smallest core (CSS px) a rounded box keeps: the engine's box needs a width and a height
 * greater than 0.
 */
const MIN_CORE = 1;

/** An element's box as laid out, in CSS px: its border box and its corner radius. */
export interface ElementBox {
  readonly width: number;
  readonly height: number;
  /** Corner radius (CSS px), already clamped to at most half the smaller side. */
  readonly radius: number;
}

/**
 * The corner radius (CSS px) of a computed `border-*-radius` value: `"12px"`, `"50%"`, or an
 * elliptical `"10px 20px"` (the smaller of the two). Percentages are of the width (horizontal)
 * and the height (vertical), as in CSS. Unparseable text counts as 0 (a sharp corner).
 */
export function parseCornerRadius(text: string, width: number, height: number): number {
  const parts = text.trim().split(/\s+/);
  const horizontal = parseLength(parts[0] ?? '', width);
  const vertical =
    parts.length > 1 ? parseLength(parts[1]!, height) : parseLength(parts[0] ?? '', height);
  return Math.max(0, Math.min(horizontal, vertical));
}

function parseLength(text: string, basis: number): number {
  const value = Number.parseFloat(text);
  if (!Number.isFinite(value)) return 0;
  return text.endsWith('%') ? (value / 100) * basis : value;
}

/**
 * The radius of the body: the smallest of the four corners (so the body never leaves a visible
 * corner out), clamped to half the smaller side as CSS itself does for overlapping radii.
 */
export function cornerRadius(corners: readonly number[], width: number, height: number): number {
  const smallest = corners.length === 0 ? 0 : Math.min(...corners);
  return Math.max(0, Math.min(smallest, width / 2, height / 2));
}

/** Capsule ends closer than this (m) are refused by the engine; such pills are circles. */
const MIN_CAPSULE_LENGTH = 0.005;

/**
 * The engine shape of an element's box, centred on the body (m): a circle for a round element
 * (square within 1 px, fully rounded), a capsule for a pill (fully rounded along its short
 * side), otherwise a box rounded by the corner radius. Each has the element's outline.
 */
export function shapeForBox(
  box: ElementBox,
  pixelsPerMeter: number,
  material: { density: number; friction: number; restitution: number },
): ShapeOptions {
  const { width, height } = box;
  const smaller = Math.min(width, height);
  const radius = Math.max(0, Math.min(box.radius, smaller / 2));
  const fullyRounded = radius >= smaller / 2 - 0.5;
  const length = Math.abs(width - height) / pixelsPerMeter; // between the capsule's end centres
  if (fullyRounded && (Math.abs(width - height) <= 1 || length < MIN_CAPSULE_LENGTH)) {
    return { type: 'circle', radius: (width + height) / 4 / pixelsPerMeter, ...material };
  }
  if (fullyRounded) {
    const half = length / 2;
    const wide = width > height;
    return {
      type: 'capsule',
      center1: wide ? { x: -half, y: 0 } : { x: 0, y: -half },
      center2: wide ? { x: half, y: 0 } : { x: 0, y: half },
      radius: smaller / 2 / pixelsPerMeter,
      ...material,
    };
  }
  const rounding = Math.min(radius, (smaller - MIN_CORE) / 2);
  const r = Math.max(0, rounding);
  return {
    type: 'box',
    width: (width - 2 * r) / pixelsPerMeter,
    height: (height - 2 * r) / pixelsPerMeter,
    radius: r / pixelsPerMeter,
    ...material,
  };
}
