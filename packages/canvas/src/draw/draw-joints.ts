import type { Body, Vec2 } from '@physical/engine';
import type { Pose } from './pose.ts';
import type { HeldPoint, Scene } from './scene.ts';

/** The joints' lines: the light grey of labels, half transparent, like a thin rod. */
const LINK_COLOR = 'rgba(236, 239, 241, 0.6)';
/** Outline of the anchor dots: the static bodies' stroke, readable on every fill. */
const DOT_STROKE = '#90a4ae';
/** Line width and anchor-dot radius, in CSS px. */
const LINE_WIDTH = 1.5;
const DOT_RADIUS = 3;

// Scratch kept between frames, so drawing allocates nothing once the buffer has grown. Drawing is
// synchronous, so one set serves every element.
const pose: Pose = { x: 0, y: 0, angle: 0 };
const point: Vec2 = { x: 0, y: 0 };
const NONE: readonly HeldPoint[] = [];
/** Per joint: anchor A x, y, anchor B x, y (m), at the drawn poses. */
let anchors = new Float64Array(4 * 64);
/** Each body's index in `world.bodies` when last looked up: checked before use. */
const indexHints = new WeakMap<Body, number>();

/**
 * Writes the points of every joint of the scene's world, then of every held point (the drag's
 * line, from the pointer to the held point, as a mouse joint's), at the bodies' drawn
 * (interpolated) poses, into `out` (anchor A x, y, anchor B x, y per link) and returns how many
 * were written. Links with a hidden body are left out. Reads only `world.joints`,
 * `joint.anchorA` / `anchorB`, `scene.held` and the bodies' poses.
 */
export function jointAnchors(scene: Scene, out: Float64Array): number {
  const world = scene.world;
  if (world === null) return 0;
  const joints = world.joints;
  let count = 0;
  for (let j = 0; j < joints.length && 4 * count + 3 < out.length; j++) {
    const joint = joints[j]!;
    if (!scene.styleOf(joint.bodyA).visible || !scene.styleOf(joint.bodyB).visible) continue;
    const k = 4 * count++;
    const a = joint.anchorA;
    // A mouse joint's anchor A is its target: a point of the world, not of a body.
    if (joint.type === 'mouse') {
      out[k] = a.x;
      out[k + 1] = a.y;
    } else drawnPoint(scene, joint.bodyA, a.x, a.y, out, k);
    const b = joint.anchorB;
    drawnPoint(scene, joint.bodyB, b.x, b.y, out, k + 2);
  }
  const held = scene.held ?? NONE;
  for (let i = 0; i < held.length && 4 * count + 3 < out.length; i++) {
    const hold = held[i]!;
    if (!scene.styleOf(hold.body).visible) continue;
    const k = 4 * count++;
    out[k] = hold.target.x;
    out[k + 1] = hold.target.y;
    hold.body.getWorldPoint(hold.local, point);
    drawnPoint(scene, hold.body, point.x, point.y, out, k + 2);
  }
  return count;
}

/**
 * Draws every joint, and every point held by a pointer, as a thin line between its anchors with
 * a small dot at each, the dot filled with its body's colour, on a context in world metres.
 */
export function drawJoints(context: CanvasRenderingContext2D, scene: Scene): void {
  const world = scene.world;
  const held = scene.held ?? NONE;
  if (world === null || world.joints.length + held.length === 0) return;
  const links = world.joints.length + held.length;
  if (anchors.length < 4 * links)
    anchors = new Float64Array(Math.max(4 * links, 2 * anchors.length));
  const count = jointAnchors(scene, anchors);
  if (count === 0) return;
  const pixel = 1 / scene.viewport.scale;
  context.globalAlpha = 1;
  context.beginPath();
  for (let k = 0; k < 4 * count; k += 4) {
    context.moveTo(anchors[k]!, anchors[k + 1]!);
    context.lineTo(anchors[k + 2]!, anchors[k + 3]!);
  }
  context.strokeStyle = LINK_COLOR;
  context.lineWidth = LINE_WIDTH * pixel;
  context.lineCap = 'round';
  context.stroke();
  // Dots, one path per run of the same fill (joints of one chain share colours).
  const radius = DOT_RADIUS * pixel;
  const joints = world.joints;
  context.strokeStyle = DOT_STROKE;
  context.lineWidth = pixel;
  let fill: string | null = null;
  let drawn = 0;
  for (let j = 0; j < joints.length && drawn < count; j++) {
    const joint = joints[j]!;
    if (!scene.styleOf(joint.bodyA).visible || !scene.styleOf(joint.bodyB).visible) continue;
    const k = 4 * drawn++;
    fill = dot(context, joint.bodyA, anchors[k]!, anchors[k + 1]!, radius, fill, scene);
    fill = dot(context, joint.bodyB, anchors[k + 2]!, anchors[k + 3]!, radius, fill, scene);
  }
  for (let i = 0; i < held.length && drawn < count; i++) {
    const body = held[i]!.body;
    if (!scene.styleOf(body).visible) continue;
    const k = 4 * drawn++;
    fill = dot(context, body, anchors[k]!, anchors[k + 1]!, radius, fill, scene);
    fill = dot(context, body, anchors[k + 2]!, anchors[k + 3]!, radius, fill, scene);
  }
  if (fill !== null) finishDots(context, fill);
}

/** Adds a dot to the current run, first closing the run if the colour changes. */
function dot(
  context: CanvasRenderingContext2D,
  body: Body,
  x: number,
  y: number,
  radius: number,
  fill: string | null,
  scene: Scene,
): string {
  const color = scene.styleOf(body).fill;
  if (color !== fill) {
    if (fill !== null) finishDots(context, fill);
    context.beginPath();
  }
  context.moveTo(x + radius, y);
  context.arc(x, y, radius, 0, 2 * Math.PI);
  return color;
}

function finishDots(context: CanvasRenderingContext2D, fill: string): void {
  context.fillStyle = fill;
  context.fill();
  context.stroke();
}

/**
 * Moves a point of `body` (world, at its current pose) to where the body is drawn: its offset
 * from the body's origin, turned by the difference between the drawn angle and the current one.
 */
function drawnPoint(
  scene: Scene,
  body: Body,
  x: number,
  y: number,
  out: Float64Array,
  k: number,
): void {
  scene.poseOf(body, indexOf(scene, body), pose);
  const position = body.position;
  const rx = x - position.x;
  const ry = y - position.y;
  const turn = pose.angle - body.angle;
  const cos = Math.cos(turn);
  const sin = Math.sin(turn);
  out[k] = pose.x + cos * rx - sin * ry;
  out[k + 1] = pose.y + sin * rx + cos * ry;
}

/** The body's index in `scene.bodies` (poses are kept by index), -1 if absent. */
function indexOf(scene: Scene, body: Body): number {
  const hint = indexHints.get(body);
  if (hint !== undefined && scene.bodies[hint] === body) return hint;
  const index = scene.bodies.indexOf(body);
  indexHints.set(body, index);
  return index;
}
