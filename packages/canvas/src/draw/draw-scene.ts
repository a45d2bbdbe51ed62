import { drawBodies, drawLabels, type BodyBatches } from './draw-bodies.ts';
import type { drawJoints } from './draw-joints.ts';
import type { OverlaysDrawer } from './draw-overlays.ts';
import type { Scene } from './scene.ts';

/** Draws the joints and held points (draw-joints.ts, loaded apart: see CanvasRenderer). */
export type JointsDrawer = typeof drawJoints;

/**
 * Sets the context's transform to world metres for a viewport: device px = (world - origin) *
 * scale * devicePixelRatio.
 */
export function setWorldTransform(
  context: CanvasRenderingContext2D,
  scene: Pick<Scene, 'viewport'>,
): void {
  const { scale, originX, originY, devicePixelRatio } = scene.viewport;
  const k = scale * devicePixelRatio;
  context.setTransform(k, 0, 0, k, -originX * k, -originY * k);
}

/**
 * Draws a whole frame: background, bodies, joints (with `joints`, draw-joints.ts, loaded apart),
 * collision arrows and debug overlays (with `overlays`, draw-overlays.ts, loaded apart), then `overlay` (in world metres, for app drawings
 * such as force arrows), then labels. The canvas's backing store must be
 * `viewport.width * devicePixelRatio` by `viewport.height * devicePixelRatio` pixels.
 */
export function drawScene(
  context: CanvasRenderingContext2D,
  scene: Scene,
  batches: BodyBatches,
  overlay: ((context: CanvasRenderingContext2D) => void) | null = null,
  overlays: OverlaysDrawer | null = null,
  joints: JointsDrawer | null = null,
): void {
  const canvas = context.canvas;
  context.setTransform(1, 0, 0, 1, 0, 0);
  context.globalAlpha = 1;
  context.clearRect(0, 0, canvas.width, canvas.height);
  if (scene.background !== 'transparent') {
    context.fillStyle = scene.background;
    context.fillRect(0, 0, canvas.width, canvas.height);
  }
  if (scene.world === null) return;
  setWorldTransform(context, scene);
  drawBodies(context, scene, batches);
  if (joints !== null) joints(context, scene);
  if (overlays !== null) overlays(context, scene);
  if (overlay !== null) {
    context.save();
    overlay(context);
    context.restore();
    setWorldTransform(context, scene);
  }
  context.setTransform(1, 0, 0, 1, 0, 0);
  drawLabels(context, scene, batches);
}
