import type { ContactView } from '@physical/engine';
import { ARROW_COLORS, arrowHeadLength } from './draw-arrow.ts';
import { PATH_BATCH_SIZE } from './path-batch.ts';
import type { Pose } from './pose.ts';
import type { Scene } from './scene.ts';

const CONTACT_COLOR = '#ff5252';
const NORMAL_COLOR = '#ffeb3b';
const AABB_COLOR = 'rgba(178, 255, 89, 0.7)';
const CENTER_COLOR = '#e0e0e0';

// Scratch kept between frames, so the overlays allocate nothing once the buffers have grown to
// the largest scene seen. Drawing is synchronous, so one set serves every element.
const bounds = { minX: 0, minY: 0, maxX: 0, maxY: 0 };
const pose: Pose = { x: 0, y: 0, angle: 0 };
/** Per drawn body: centre of mass x, y, then velocity arrow x, y (m). */
let centers = new Float64Array(4 * 256);
/** Per contact point: x, y, normal x, normal y. */
let contacts = new Float64Array(4 * 256);
let contactCount = 0;

/**
 * Draws the debug overlays the scene asks for, on a context in world metres. Bounding boxes and
 * contacts are those of the last step (not interpolated); centres of mass and velocity arrows
 * follow the interpolated pose.
 *
 * Each overlay sets its style once and draws all its items as one path (dots: a few paths of
 * {@link PATH_BATCH_SIZE}). Lines are 1 CSS px: hairlines, far cheaper to rasterise than wider
 * strokes or filled quads. Per-item draws and style changes, and 1.5 px lines, made these
 * overlays cost twice the bodies they annotate.
 */
export function drawDebugOverlays(context: CanvasRenderingContext2D, scene: Scene): void {
  const debug = scene.debug;
  const pixel = 1 / scene.viewport.scale;
  if (debug.aabbs) drawBounds(context, scene, pixel);
  if (debug.centers || debug.velocities) drawCenters(context, scene, pixel);
  if ((debug.contacts || debug.normals) && scene.world !== null) {
    contactCount = 0;
    scene.world.forEachContact(collectContact);
    drawContacts(context, debug.contacts, debug.normals, pixel);
  }
}

/** forEachContact visitor: copies the points out (the view object is reused). */
function collectContact(contact: ContactView): void {
  const needed = 4 * (contactCount + contact.pointCount);
  if (needed > contacts.length) {
    const grown = new Float64Array(Math.max(needed, 2 * contacts.length));
    grown.set(contacts);
    contacts = grown;
  }
  for (let i = 0; i < contact.pointCount; i++) {
    const point = contact.points[i]!;
    const k = 4 * contactCount++;
    contacts[k] = point.x;
    contacts[k + 1] = point.y;
    contacts[k + 2] = contact.normalX;
    contacts[k + 3] = contact.normalY;
  }
}

/**
 * Every contact point as a square dot and/or its normal as a short line. Squares, not circles:
 * axis-aligned rectangles rasterise several times faster than arcs.
 */
function drawContacts(
  context: CanvasRenderingContext2D,
  showPoints: boolean,
  showNormals: boolean,
  pixel: number,
): void {
  const end = 4 * contactCount;
  if (end === 0) return;
  if (showNormals) {
    const length = 12 * pixel;
    context.beginPath();
    for (let k = 0; k < end; k += 4) {
      const x = contacts[k]!;
      const y = contacts[k + 1]!;
      context.moveTo(x, y);
      context.lineTo(x + contacts[k + 2]! * length, y + contacts[k + 3]! * length);
    }
    strokeHairlines(context, NORMAL_COLOR, pixel);
  }
  if (showPoints) {
    const half = 2.5 * pixel;
    context.fillStyle = CONTACT_COLOR;
    context.beginPath();
    for (let k = 0; k < end; k += 4) {
      context.rect(contacts[k]! - half, contacts[k + 1]! - half, 2 * half, 2 * half);
      if ((k / 4 + 1) % PATH_BATCH_SIZE === 0) {
        context.fill();
        context.beginPath();
      }
    }
    context.fill();
  }
}

/**
 * Strokes the current path 1 CSS px wide: on a 1x display that is Skia's hairline, about eight
 * times cheaper to rasterise than the 1.5 px lines these overlays once used.
 */
function strokeHairlines(context: CanvasRenderingContext2D, color: string, pixel: number): void {
  context.strokeStyle = color;
  context.lineWidth = pixel;
  context.lineCap = 'butt';
  context.stroke();
}

/** Every shape's bounding box, in one path. */
function drawBounds(context: CanvasRenderingContext2D, scene: Scene, pixel: number): void {
  const bodies = scene.bodies;
  context.beginPath();
  for (let i = 0; i < bodies.length; i++) {
    const shapes = bodies[i]!.shapes;
    for (let s = 0; s < shapes.length; s++) {
      shapes[s]!.getBounds(bounds);
      context.rect(bounds.minX, bounds.minY, bounds.maxX - bounds.minX, bounds.maxY - bounds.minY);
    }
  }
  context.lineJoin = 'miter';
  strokeHairlines(context, AABB_COLOR, pixel);
}

/** Crosshairs at the centres of mass, then velocity arrows from them; one path each. */
function drawCenters(context: CanvasRenderingContext2D, scene: Scene, pixel: number): void {
  const bodies = scene.bodies;
  if (centers.length < 4 * bodies.length) {
    centers = new Float64Array(Math.max(4 * bodies.length, 2 * centers.length));
  }
  const velocityScale = scene.velocityScale;
  let end = 0;
  for (let i = 0; i < bodies.length; i++) {
    const body = bodies[i]!;
    if (body.type === 'static') continue;
    scene.poseOf(body, i, pose);
    // The centre of mass at the drawn pose: its offset from the origin, turned by the difference
    // between the drawn angle and the current one.
    const position = body.position;
    const com = body.centerOfMass;
    const rx = com.x - position.x;
    const ry = com.y - position.y;
    const turn = pose.angle - body.angle;
    const cos = Math.cos(turn);
    const sin = Math.sin(turn);
    centers[end] = pose.x + cos * rx - sin * ry;
    centers[end + 1] = pose.y + sin * rx + cos * ry;
    // Sleeping bodies get no arrow: a zero vector is below the drawing threshold.
    const v = body.isAwake ? body.linearVelocity : null;
    centers[end + 2] = v === null ? 0 : v.x * velocityScale;
    centers[end + 3] = v === null ? 0 : v.y * velocityScale;
    end += 4;
  }
  if (end === 0) return;
  if (scene.debug.centers) {
    const size = 5 * pixel;
    context.beginPath();
    for (let k = 0; k < end; k += 4) {
      const x = centers[k]!;
      const y = centers[k + 1]!;
      context.moveTo(x - size, y);
      context.lineTo(x + size, y);
      context.moveTo(x, y - size);
      context.lineTo(x, y + size);
    }
    strokeHairlines(context, CENTER_COLOR, pixel);
  }
  if (scene.debug.velocities) {
    context.beginPath();
    for (let k = 0; k < end; k += 4) {
      appendLineArrow(
        context,
        centers[k]!,
        centers[k + 1]!,
        centers[k + 2]!,
        centers[k + 3]!,
        pixel,
      );
    }
    context.lineJoin = 'miter';
    strokeHairlines(context, ARROW_COLORS.velocity, pixel);
  }
}

/**
 * Adds a line arrow (a shaft and two barbs, the proportions of `drawArrow` for a 1 px shaft) to
 * the current path. Filled heads would cost more than the rest of the overlays together: a
 * thousand small rotated triangles, where hairlines are nearly free. Nothing under half a pixel.
 */
function appendLineArrow(
  context: CanvasRenderingContext2D,
  fromX: number,
  fromY: number,
  vectorX: number,
  vectorY: number,
  pixel: number,
): void {
  const length = Math.hypot(vectorX, vectorY);
  if (!(length >= 0.5 * pixel)) return;
  const head = arrowHeadLength(length, pixel, pixel);
  const ux = vectorX / length;
  const uy = vectorY / length;
  const tipX = fromX + vectorX;
  const tipY = fromY + vectorY;
  const baseX = tipX - ux * head;
  const baseY = tipY - uy * head;
  const half = head * 0.5;
  context.moveTo(fromX, fromY);
  context.lineTo(tipX, tipY);
  context.moveTo(baseX - uy * half, baseY + ux * half);
  context.lineTo(tipX, tipY);
  context.lineTo(baseX + uy * half, baseY - ux * half);
}
