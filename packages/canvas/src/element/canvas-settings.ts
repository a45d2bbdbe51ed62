import type { Vec2 } from '@physical/engine';
import { DEFAULT_BACKGROUND } from '../draw/body-style.ts';
import { noDebugOverlays, type DebugOverlays } from '../draw/debug-overlays.ts';
import type { FitMode, ViewBox } from '../draw/viewport.ts';
import {
  parseColor,
  parseDebug,
  parseDrag,
  parseFit,
  parseNonNegative,
  parsePoint,
  parsePositive,
  parsePositiveInteger,
  parseViewBox,
} from './attribute-parsers.ts';

/** The attributes `<physical-canvas>` observes; each is also a property. */
export const SETTING_ATTRIBUTES = [
  'pixels-per-meter',
  'origin',
  'fit',
  'view-box',
  'paused',
  'time-scale',
  'background',
  'debug',
  'collision-arrows',
  'collision-arrow-duration',
  'force-scale',
  'velocity-scale',
  'steps-per-second',
  'max-steps-per-frame',
  'drag',
  'max-pixel-ratio',
] as const;

/** One of {@link SETTING_ATTRIBUTES}. */
export type SettingAttribute = (typeof SETTING_ATTRIBUTES)[number];

/** The value of each setting while its attribute is absent. */
export const SETTING_DEFAULTS = {
  pixelsPerMeter: 50,
  timeScale: 1,
  collisionArrowDuration: 1,
  forceScale: 0.01,
  velocityScale: 0.25,
  stepsPerSecond: 60,
  maxStepsPerFrame: 4,
} as const;

/**
 * The element's settings as parsed from its attributes: the attributes are the source of truth
 * (property setters reflect to them), and this keeps the last good value of each.
 */
export class CanvasSettings {
  pixelsPerMeter: number = SETTING_DEFAULTS.pixelsPerMeter;
  origin: Vec2 = { x: 0, y: 0 };
  fit: FitMode = 'none';
  viewBox: ViewBox | null = null;
  paused = false;
  timeScale: number = SETTING_DEFAULTS.timeScale;
  background: string = DEFAULT_BACKGROUND;
  debug: DebugOverlays = noDebugOverlays();
  collisionArrows = false;
  collisionArrowDuration: number = SETTING_DEFAULTS.collisionArrowDuration;
  forceScale: number = SETTING_DEFAULTS.forceScale;
  velocityScale: number = SETTING_DEFAULTS.velocityScale;
  stepsPerSecond: number = SETTING_DEFAULTS.stepsPerSecond;
  maxStepsPerFrame: number = SETTING_DEFAULTS.maxStepsPerFrame;
  /** Pointers drag dynamic bodies (attribute `drag`, on unless `"off"`). */
  drag = true;
  /** Cap on the backing store's device pixels per CSS px (attribute `max-pixel-ratio`). */
  maxPixelRatio: number = Infinity;

  /**
   * Parses an attribute's new text (null when removed: back to the default) into its setting.
   * Throws a `CanvasSettingError` for a value the element cannot use, leaving the setting as it
   * was.
   */
  apply(name: SettingAttribute, value: string | null): void {
    const present = value !== null;
    switch (name) {
      case 'pixels-per-meter':
        this.pixelsPerMeter = present
          ? parsePositive(name, value)
          : SETTING_DEFAULTS.pixelsPerMeter;
        break;
      case 'origin':
        this.origin = present ? parsePoint(name, value) : { x: 0, y: 0 };
        break;
      case 'fit':
        this.fit = present ? parseFit(name, value) : 'none';
        break;
      case 'view-box':
        this.viewBox = parseViewBox(name, value);
        break;
      case 'paused':
        this.paused = present;
        break;
      case 'time-scale':
        this.timeScale = present ? parseNonNegative(name, value) : SETTING_DEFAULTS.timeScale;
        break;
      case 'background':
        this.background = present ? parseColor(name, value) : DEFAULT_BACKGROUND;
        break;
      case 'debug':
        this.debug = parseDebug(name, value);
        break;
      case 'collision-arrows':
        this.collisionArrows = present;
        break;
      case 'collision-arrow-duration':
        this.collisionArrowDuration = present
          ? parsePositive(name, value)
          : SETTING_DEFAULTS.collisionArrowDuration;
        break;
      case 'force-scale':
        this.forceScale = present ? parsePositive(name, value) : SETTING_DEFAULTS.forceScale;
        break;
      case 'velocity-scale':
        this.velocityScale = present ? parsePositive(name, value) : SETTING_DEFAULTS.velocityScale;
        break;
      case 'steps-per-second':
        this.stepsPerSecond = present
          ? parsePositive(name, value)
          : SETTING_DEFAULTS.stepsPerSecond;
        break;
      case 'max-steps-per-frame':
        this.maxStepsPerFrame = present
          ? parsePositiveInteger(name, value)
          : SETTING_DEFAULTS.maxStepsPerFrame;
        break;
      case 'drag':
        this.drag = parseDrag(name, value);
        break;
      case 'max-pixel-ratio':
        this.maxPixelRatio = present ? parsePositive(name, value) : Infinity;
        break;
    }
  }
}
