import type { Vec2Like, World } from '@physical/engine';
import type { DebugOverlays } from '../draw/debug-overlays.ts';
import type { FitMode, ViewBox } from '../draw/viewport.ts';
import type { StyleResolver } from './body-styles.ts';
import type { PhysicalCanvasEvents } from './canvas-events.ts';
import type { FrameScheduler } from './frame-scheduler.ts';
import type { OverlayDrawer, PhysicalCanvasElement } from './physical-canvas-element.ts';

/**
 * The properties of `<physical-canvas>` a template may set, with the types their setters accept.
 * The framework declarations (`@physical/canvas/jsx`, `/vue`, `/svelte`) are built from it.
 */
export interface PhysicalCanvasProperties {
  world?: World | null;
  styleFor?: StyleResolver | null;
  drawOverlay?: OverlayDrawer | null;
  frameScheduler?: FrameScheduler | null;
  pixelsPerMeter?: number;
  origin?: Vec2Like;
  fit?: FitMode;
  viewBox?: ViewBox | null;
  paused?: boolean;
  timeScale?: number;
  background?: string;
  debug?: string | readonly string[] | Partial<DebugOverlays>;
  collisionArrows?: boolean;
  collisionArrowDuration?: number;
  forceScale?: number;
  velocityScale?: number;
  stepsPerSecond?: number;
  maxStepsPerFrame?: number;
  /** Pointer dragging and throwing of dynamic bodies (not air drag). Default true. */
  drag?: boolean;
  /** Cap on device pixels per CSS px (sharpness against frame rate). Default: no cap. */
  maxPixelRatio?: number;
}

/** The attributes of `<physical-canvas>` as written in HTML (each mirrors a property). */
export interface PhysicalCanvasAttributes {
  'pixels-per-meter'?: number | string;
  origin?: string;
  fit?: FitMode;
  'view-box'?: string;
  paused?: boolean | string;
  'time-scale'?: number | string;
  background?: string;
  debug?: string;
  'collision-arrows'?: boolean | string;
  'collision-arrow-duration'?: number | string;
  'force-scale'?: number | string;
  'velocity-scale'?: number | string;
  'steps-per-second'?: number | string;
  'max-steps-per-frame'?: number | string;
  /** `"off"` turns pointer dragging off. */
  drag?: boolean | 'on' | 'off' | 'true' | 'false';
  'max-pixel-ratio'?: number | string;
}

/** Listener props `on<event>` for the element's own events (React 19 and Svelte 5 style). */
export type PhysicalCanvasEventProps = {
  [K in keyof PhysicalCanvasEvents as `on${K}`]?: (event: PhysicalCanvasEvents[K]) => void;
};

declare global {
  interface HTMLElementTagNameMap {
    'physical-canvas': PhysicalCanvasElement;
  }
  // Merges the element's events into every element's map: listeners on ancestors (the events
  // bubble) and on `querySelector('physical-canvas')` results are typed.
  // eslint-disable-next-line @typescript-eslint/no-empty-object-type
  interface HTMLElementEventMap extends PhysicalCanvasEvents {}
}
