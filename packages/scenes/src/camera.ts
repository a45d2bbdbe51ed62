import type { World } from '@physical/engine';
import type { Scene } from './scene.ts';

/** A world rectangle (m): what a `view-box` shows. */
export interface SceneView {
  readonly x: number;
  readonly y: number;
  readonly width: number;
  readonly height: number;
}

/** The band of the view a followed body is kept in, unless the sample says otherwise. */
export const FOLLOW_WITHIN: readonly [number, number] = [0.35, 0.65];

/**
 * What `scene` shows of `world` now: its camera, slid just enough to keep the followed body (if
 * the camera follows one) inside its band of the view. A function of the body's position only
 * (no state), so a thumbnail after any number of steps frames it as the live page does.
 */
export function sceneView(scene: Scene, world: World): SceneView {
  const { x, y, width, height, follow } = scene.camera;
  const body = follow?.body(world);
  if (follow === undefined || body === undefined) return { x, y, width, height };
  const { x: bodyX, y: bodyY } = body.position;
  const within = follow.within ?? FOLLOW_WITHIN;
  return {
    x: x + slide(bodyX, x, width, within),
    y: follow.axes === 'xy' ? y + slide(bodyY, y, height, within) : y,
    width,
    height,
  };
}

/** How far a view [start, start + size] must move so that `at` lies inside its band. */
function slide(
  at: number,
  start: number,
  size: number,
  [from, to]: readonly [number, number],
): number {
  const low = start + from * size;
  const high = start + to * size;
  return at < low ? at - low : at > high ? at - high : 0;
}
