import type { Body, World } from '@physical/engine';

/** One slider of a sample: a number the scene is built from. */
export interface SceneParameter {
  /** Key in the values handed to `build` (`count`, `angle`...). */
  readonly name: string;
  /** What the slider says, with its unit (`Angle (deg)`). */
  readonly label: string;
  readonly min: number;
  readonly max: number;
  readonly step: number;
  readonly default: number;
}

/** The world rectangle (m) a sample is framed in: the canvas's `view-box`. */
export interface SceneCamera {
  readonly x: number;
  readonly y: number;
  readonly width: number;
  readonly height: number;
  /**
   * A body the view follows (optional), for a sample whose action travels: the view stays as
   * declared while the body is inside a band of it, and slides with the body when it leaves
   * the band (see `sceneView`).
   */
  readonly follow?: SceneFollow;
}

/** The body a sample's camera follows. */
export interface SceneFollow {
  /** Finds the followed body in a world the sample built (undefined: the view stays put). */
  body(world: World): Body | undefined;
  /** The axes the view slides along: `'x'` (default, the ground stays in view) or `'xy'`. */
  readonly axes?: 'x' | 'xy';
  /**
   * The band of the view (fractions of its width, and of its height with `'xy'`, from the left
   * or top) the body is kept in; the view slides only when it leaves it. Default `[0.35, 0.65]`.
   * Put the band ahead of where the body starts, or the view slides at once.
   */
  readonly within?: readonly [number, number];
}

/** Parameter values by name. Every declared parameter is present (defaults filled in). */
export type SceneValues = Readonly<Record<string, number>>;

/**
 * A sample: a small world built from Physical's public API, with what the gallery needs to show
 * it and what the regression suite needs to check it.
 */
export interface Scene {
  /** URL-safe id, the module's file name (`vertical-stack`). */
  readonly id: string;
  readonly title: string;
  /** One or two sentences: what to look at. */
  readonly description: string;
  readonly parameters: readonly SceneParameter[];
  /** The framing the gallery uses (`fit="contain"`). */
  readonly camera: SceneCamera;
  /** Suggested scale for a full-size canvas (CSS px per metre). */
  readonly pixelsPerMeter: number;
  /** Fixed steps of 1/60 s the regression suite runs (and the thumbnail shows). */
  readonly steps: number;
  /**
   * A fill colour (CSS) the gallery gives a body this frame, or null for the default: a sample
   * colours what its events found (a sensor's visitors). Optional.
   */
  fill?(body: Body): string | null;
  /** Builds a fresh world from the parameter values. */
  build(values: SceneValues): World;
  /**
   * The physical check after `steps` steps at the default values: null when the scene behaved,
   * else what went wrong.
   */
  check(world: World, values: SceneValues): string | null;
}

/** Declares a sample (an identity function that checks the shape at compile time). */
export function defineScene(scene: Scene): Scene {
  return scene;
}

/** The default values of a scene, overridden by `overrides` (clamped to each range). */
export function sceneValues(scene: Scene, overrides: Readonly<Record<string, number>> = {}) {
  const values: Record<string, number> = {};
  for (const parameter of scene.parameters) {
    const given = overrides[parameter.name];
    values[parameter.name] =
      given === undefined || !Number.isFinite(given)
        ? parameter.default
        : Math.min(parameter.max, Math.max(parameter.min, given));
  }
  return values as SceneValues;
}

/** The regression suite's step: 1/60 s, like `<physical-canvas>`. */
export const STEP = 1 / 60;

/** Builds a scene at `values` and steps it `steps` times. */
export function runScene(
  scene: Scene,
  values: SceneValues = sceneValues(scene),
  steps = scene.steps,
) {
  const world = scene.build(values);
  for (let i = 0; i < steps; i++) world.step(STEP);
  return world;
}
