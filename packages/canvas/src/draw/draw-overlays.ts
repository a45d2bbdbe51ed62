import { drawCollisionArrows } from './draw-collision-arrows.ts';
import { drawDebugOverlays } from './draw-debug.ts';
import type { Scene } from './scene.ts';

// The collision arrows and debug overlays, over the bodies and joints, on a context in world
// metres. A chunk of its own: <physical-canvas> loads it the first time a frame asks for either
// (CanvasRenderer), so pages that never show them do not load it (issue #33's 10 KB budget).

/** Draws the scene's collision arrows, then the debug overlays it asks for. */
export function drawOverlays(context: CanvasRenderingContext2D, scene: Scene): void {
  if (scene.collisionArrows.length > 0) {
    drawCollisionArrows(context, scene.viewport.scale, scene.collisionArrows, scene.forceScale);
  }
  drawDebugOverlays(context, scene);
}

/** Draws what {@link drawOverlays} draws, or nothing (the chunk not loaded yet). */
export type OverlaysDrawer = typeof drawOverlays;
