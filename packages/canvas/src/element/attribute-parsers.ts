import type { DebugOverlays } from '../draw/debug-overlays.ts';
import { DEBUG_OVERLAY_NAMES, noDebugOverlays } from '../draw/debug-overlays.ts';
import type { FitMode, ViewBox } from '../draw/viewport.ts';
import type { Vec2Like } from '@physical/engine';

/**
 * Thrown (by property setters) or reported (for attributes, through an `attributeerror` event)
 * for a setting the element cannot draw. The message names the setting, the value and what is
 * expected.
 */
export class CanvasSettingError extends Error {
  /** The attribute name, for example `"pixels-per-meter"`. */
  readonly setting: string;
  /** The rejected value, as given. */
  readonly value: unknown;

  constructor(setting: string, value: unknown, expected: string) {
    super(`<physical-canvas> ${setting}: expected ${expected}, got ${describe(value)}.`);
    this.name = 'CanvasSettingError';
    this.setting = setting;
    this.value = value;
  }
}

function describe(value: unknown): string {
  if (typeof value === 'string') return JSON.stringify(value);
  if (typeof value === 'object' && value !== null) {
    try {
      return JSON.stringify(value);
    } catch {
      return String(value);
    }
  }
  return String(value);
}

function toNumber(value: unknown): number {
  if (typeof value === 'number') return value;
  if (typeof value === 'string' && value.trim() !== '') return Number(value);
  return Number.NaN;
}

/** A finite number > 0 (attribute text or number). */
export function parsePositive(setting: string, value: unknown): number {
  const number = toNumber(value);
  if (!Number.isFinite(number) || number <= 0) {
    throw new CanvasSettingError(setting, value, 'a finite number greater than 0');
  }
  return number;
}

/** A finite number >= 0. */
export function parseNonNegative(setting: string, value: unknown): number {
  const number = toNumber(value);
  if (!Number.isFinite(number) || number < 0) {
    throw new CanvasSettingError(setting, value, 'a finite number, 0 or more');
  }
  return number;
}

/** A whole number >= 1. */
export function parsePositiveInteger(setting: string, value: unknown): number {
  const number = toNumber(value);
  if (!Number.isInteger(number) || number < 1) {
    throw new CanvasSettingError(setting, value, 'a whole number, 1 or more');
  }
  return number;
}

/** `"x y"` (or `"x, y"`) in metres, or an `{ x, y }` object. */
export function parsePoint(setting: string, value: unknown): { x: number; y: number } {
  let x = Number.NaN;
  let y = Number.NaN;
  if (typeof value === 'string') {
    const parts = splitNumbers(value);
    if (parts.length === 2) [x, y] = parts as [number, number];
  } else if (typeof value === 'object' && value !== null) {
    const point = value as Partial<Vec2Like>;
    x = toNumber(point.x);
    y = toNumber(point.y);
  }
  if (!Number.isFinite(x) || !Number.isFinite(y)) {
    throw new CanvasSettingError(setting, value, 'a point "x y" of two finite numbers (m)');
  }
  return { x, y };
}

/** `"x y width height"` in metres (size > 0), an object, or null/`""`/`"none"` for none. */
export function parseViewBox(setting: string, value: unknown): ViewBox | null {
  if (value === null || value === undefined || value === '' || value === 'none') return null;
  let numbers: number[] = [];
  if (typeof value === 'string') numbers = splitNumbers(value);
  else if (typeof value === 'object') {
    const box = value as Partial<ViewBox>;
    numbers = [toNumber(box.x), toNumber(box.y), toNumber(box.width), toNumber(box.height)];
  }
  const [x, y, width, height] = numbers as [number, number, number, number];
  if (numbers.length !== 4 || !numbers.every(Number.isFinite) || !(width > 0) || !(height > 0)) {
    throw new CanvasSettingError(
      setting,
      value,
      'a world rectangle "x y width height" (m) with width and height greater than 0',
    );
  }
  return { x, y, width, height };
}

/** `'none'`, `'contain'` or `'cover'`. */
export function parseFit(setting: string, value: unknown): FitMode {
  if (value === 'none' || value === 'contain' || value === 'cover') return value;
  throw new CanvasSettingError(setting, value, '"none", "contain" or "cover"');
}

/**
 * A space-separated list of overlay names (`"contacts normals"`), an array of names, or an
 * object of flags. `"all"` turns every overlay on.
 */
export function parseDebug(setting: string, value: unknown): DebugOverlays {
  const overlays = noDebugOverlays();
  if (value === null || value === undefined || value === '') return overlays;
  let names: unknown[];
  if (typeof value === 'string') names = value.trim().split(/[\s,]+/);
  else if (Array.isArray(value)) names = value;
  else if (typeof value === 'object') {
    names = Object.entries(value).flatMap(([name, on]) => (on === true ? [name] : []));
  } else names = [value];
  for (const name of names) {
    if (name === 'all') {
      for (const key of DEBUG_OVERLAY_NAMES) overlays[key] = true;
    } else if ((DEBUG_OVERLAY_NAMES as readonly unknown[]).includes(name)) {
      overlays[name as keyof DebugOverlays] = true;
    } else {
      throw new CanvasSettingError(
        setting,
        value,
        `overlay names among ${DEBUG_OVERLAY_NAMES.join(', ')} or all`,
      );
    }
  }
  return overlays;
}

/** The overlays that are on, as the attribute's text. */
export function formatDebug(overlays: DebugOverlays): string {
  return DEBUG_OVERLAY_NAMES.filter((name) => overlays[name]).join(' ');
}

function splitNumbers(text: string): number[] {
  const trimmed = text.trim();
  if (trimmed === '') return [];
  return trimmed.split(/[\s,]+/).map((part) => (part === '' ? Number.NaN : Number(part)));
}

/** Any CSS colour the browser supports (or `"transparent"`); trimmed. */
export function parseColor(setting: string, value: unknown): string {
  const text = typeof value === 'string' ? value.trim() : '';
  // Without CSS (Node, server rendering) any non-empty text passes; the browser checks it.
  const supported = text !== '' && (typeof CSS === 'undefined' || CSS.supports('color', text));
  if (!supported) throw new CanvasSettingError(setting, value, 'a CSS colour');
  return text;
}

/** `drag`: on unless `"off"` or `"false"` (absent, `""`, `"on"`, `"true"` and `true` are on). */
export function parseDrag(setting: string, value: unknown): boolean {
  if (value === null || value === undefined || value === true) return true;
  if (value === false) return false;
  const text = typeof value === 'string' ? value.trim().toLowerCase() : undefined;
  if (text === '' || text === 'on' || text === 'true') return true;
  if (text === 'off' || text === 'false') return false;
  throw new CanvasSettingError(setting, value, '"on" or "off" (or true / false)');
}
