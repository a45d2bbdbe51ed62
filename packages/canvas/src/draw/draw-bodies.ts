import type { Body } from '@physical/engine';
import type { BodyDrawInfo, ResolvedBodyStyle } from './body-style.ts';
import type { Pose } from './pose.ts';
import type { Scene } from './scene.ts';
import { PATH_BATCH_SIZE } from './path-batch.ts';
import { appendAreaPath, appendSegmentPath } from './shape-path.ts';

/**
 * Scratch memory for {@link drawBodies}, kept between frames so a frame allocates nothing once
 * the set of styles is stable.
 */
export class BodyBatches {
  /** Body indices per style, in the order styles are first met. */
  readonly byStyle: Map<ResolvedBodyStyle, number[]> = new Map();
  /** Styles with bodies this frame, sorted by zIndex. */
  readonly order: ResolvedBodyStyle[] = [];
  /** Indices of bodies with a label. */
  readonly labelled: number[] = [];
  readonly pose: Pose = { x: 0, y: 0, angle: 0 };
}

const bySortKey = (a: ResolvedBodyStyle, b: ResolvedBodyStyle): number => a.zIndex - b.zIndex;

/**
 * Draws every visible body, on a context in world metres (see {@link drawScene}). Bodies that
 * share a style are drawn as one path, filled and stroked once: 1,000 boxes in the default
 * palette cost eight fills, not a thousand. Styles are drawn by increasing zIndex; the order of
 * bodies within one style is the world's.
 */
export function drawBodies(
  context: CanvasRenderingContext2D,
  scene: Scene,
  batches: BodyBatches,
): void {
  const bodies = scene.bodies;
  const byStyle = batches.byStyle;
  for (const list of byStyle.values()) list.length = 0;
  batches.labelled.length = 0;
  for (let i = 0; i < bodies.length; i++) {
    const style = scene.styleOf(bodies[i]!);
    if (!style.visible || style.opacity <= 0) continue;
    let list = byStyle.get(style);
    if (list === undefined) {
      list = [];
      byStyle.set(style, list);
    }
    list.push(i);
    if (style.label !== null) batches.labelled.push(i);
  }
  const order = batches.order;
  order.length = 0;
  for (const [style, list] of byStyle) {
    if (list.length === 0) byStyle.delete(style);
    else order.push(style);
  }
  order.sort(bySortKey);
  const pixelsPerMeter = scene.viewport.scale;
  for (const style of order) {
    const list = byStyle.get(style)!;
    if (style.draw !== null) drawCustom(context, scene, style, list, pixelsPerMeter, batches.pose);
    else drawBatch(context, scene, style, list, pixelsPerMeter, batches.pose);
  }
}

function drawBatch(
  context: CanvasRenderingContext2D,
  scene: Scene,
  style: ResolvedBodyStyle,
  list: readonly number[],
  pixelsPerMeter: number,
  pose: Pose,
): void {
  const bodies = scene.bodies;
  const dimSleeping = scene.debug.sleep;
  context.globalAlpha = style.opacity;
  context.lineWidth = style.lineWidth / pixelsPerMeter;
  context.lineJoin = 'round';
  context.lineCap = 'round';
  for (let pass = 0; pass < (dimSleeping ? 2 : 1); pass++) {
    // With the sleep overlay, awake bodies are drawn in pass 0 and sleeping ones, dimmed, in 1.
    if (pass === 1) context.globalAlpha = style.opacity * 0.4;
    let hasArea = false;
    let hasSegment = false;
    let inPath = 0;
    if (style.fill !== 'transparent') context.fillStyle = style.fill;
    if (style.stroke !== 'transparent') context.strokeStyle = style.stroke;
    context.beginPath();
    for (let k = 0; k < list.length; k++) {
      const index = list[k]!;
      const body = bodies[index]!;
      if (dimSleeping && isSleeping(body) !== (pass === 1)) continue;
      scene.poseOf(body, index, pose);
      const cos = Math.cos(pose.angle);
      const sin = Math.sin(pose.angle);
      const shapes = body.shapes;
      for (let s = 0; s < shapes.length; s++) {
        if (appendAreaPath(context, shapes[s]!.geometry, pose, cos, sin)) {
          hasArea = true;
          inPath++;
        } else hasSegment = true;
      }
      // Software raster slows down on very long paths (see PATH_BATCH_SIZE): paint in chunks.
      if (inPath >= PATH_BATCH_SIZE) {
        paintArea(context, style);
        context.beginPath();
        inPath = 0;
      }
    }
    if (hasArea && inPath > 0) paintArea(context, style);
    if (hasSegment) {
      context.beginPath();
      for (let k = 0; k < list.length; k++) {
        const index = list[k]!;
        const body = bodies[index]!;
        if (dimSleeping && isSleeping(body) !== (pass === 1)) continue;
        scene.poseOf(body, index, pose);
        const cos = Math.cos(pose.angle);
        const sin = Math.sin(pose.angle);
        for (const shape of body.shapes) appendSegmentPath(context, shape.geometry, pose, cos, sin);
      }
      context.strokeStyle = style.stroke === 'transparent' ? style.fill : style.stroke;
      context.stroke();
    }
  }
  context.globalAlpha = 1;
}

/** Fills and strokes the current path in the style's colours (already set on the context). */
function paintArea(context: CanvasRenderingContext2D, style: ResolvedBodyStyle): void {
  if (style.fill !== 'transparent') context.fill();
  if (style.stroke !== 'transparent') context.stroke();
}

function drawCustom(
  context: CanvasRenderingContext2D,
  scene: Scene,
  style: ResolvedBodyStyle,
  list: readonly number[],
  pixelsPerMeter: number,
  pose: Pose,
): void {
  const draw = style.draw!;
  for (let k = 0; k < list.length; k++) {
    const index = list[k]!;
    const body = scene.bodies[index]!;
    scene.poseOf(body, index, pose);
    const info: BodyDrawInfo = { body, pose, pixelsPerMeter, style };
    context.save();
    context.globalAlpha = style.opacity;
    context.translate(pose.x, pose.y);
    context.rotate(pose.angle);
    draw(context, info);
    context.restore();
  }
}

function isSleeping(body: Body): boolean {
  return body.type !== 'static' && !body.isAwake;
}

/**
 * Draws the labels of the bodies collected by {@link drawBodies}, upright and in CSS pixels, on a
 * context whose transform is device pixels (identity).
 */
export function drawLabels(
  context: CanvasRenderingContext2D,
  scene: Scene,
  batches: BodyBatches,
): void {
  const labelled = batches.labelled;
  if (labelled.length === 0) return;
  const { scale, originX, originY, devicePixelRatio } = scene.viewport;
  const pose = batches.pose;
  context.font = `${12 * devicePixelRatio}px system-ui, sans-serif`;
  context.textAlign = 'center';
  context.textBaseline = 'middle';
  for (let k = 0; k < labelled.length; k++) {
    const index = labelled[k]!;
    const body = scene.bodies[index]!;
    const style = scene.styleOf(body);
    scene.poseOf(body, index, pose);
    context.globalAlpha = style.opacity;
    context.fillStyle = style.labelColor;
    context.fillText(
      style.label!,
      (pose.x - originX) * scale * devicePixelRatio,
      (pose.y - originY) * scale * devicePixelRatio,
    );
  }
  context.globalAlpha = 1;
}
