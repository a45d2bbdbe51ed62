import type { ContactView, World } from '@physical/engine';
import { drawArrow } from './draw-arrow.ts';
import type { Pose } from './pose.ts';
import type { Scene } from './scene.ts';

const CONTACT_COLOR = '#ff5252';
const NORMAL_COLOR = '#ffeb3b';
const AABB_COLOR = 'rgba(178, 255, 89, 0.7)';
const CENTER_COLOR = '#e0e0e0';

/**
 * Draws the debug overlays the scene asks for, on a context in world metres. Bounding boxes and
 * contacts are those of the last step (not interpolated); centres of mass and velocity arrows
 * follow the interpolated pose.
 */
export function drawDebugOverlays(context: CanvasRenderingContext2D, scene: Scene): void {
  const debug = scene.debug;
  const pixel = 1 / scene.viewport.scale;
  if (debug.aabbs) drawBounds(context, scene, pixel);
  if (debug.centers || debug.velocities) drawCenters(context, scene, pixel);
  if ((debug.contacts || debug.normals) && scene.world !== null) {
    drawContacts(context, scene.world, debug.contacts, debug.normals, pixel);
  }
}

/** Every contact point as a dot and/or its normal as a short line, in one path each. */
function drawContacts(
  context: CanvasRenderingContext2D,
  world: World,
  showPoints: boolean,
  showNormals: boolean,
  pixel: number,
): void {
  const length = 12 * pixel;
  const radius = 3 * pixel;
  if (showNormals) {
    context.beginPath();
    world.forEachContact((contact: ContactView) => {
      for (let i = 0; i < contact.pointCount; i++) {
        const point = contact.points[i]!;
        context.moveTo(point.x, point.y);
        context.lineTo(point.x + contact.normalX * length, point.y + contact.normalY * length);
      }
    });
    context.strokeStyle = NORMAL_COLOR;
    context.lineWidth = 1.5 * pixel;
    context.stroke();
  }
  if (showPoints) {
    context.beginPath();
    world.forEachContact((contact: ContactView) => {
      for (let i = 0; i < contact.pointCount; i++) {
        const point = contact.points[i]!;
        context.moveTo(point.x + radius, point.y);
        context.arc(point.x, point.y, radius, 0, 2 * Math.PI);
      }
    });
    context.fillStyle = CONTACT_COLOR;
    context.fill();
  }
}

function drawBounds(context: CanvasRenderingContext2D, scene: Scene, pixel: number): void {
  const bounds = { minX: 0, minY: 0, maxX: 0, maxY: 0 };
  context.strokeStyle = AABB_COLOR;
  context.lineWidth = pixel;
  context.beginPath();
  for (const body of scene.bodies) {
    for (const shape of body.shapes) {
      shape.getBounds(bounds);
      context.rect(bounds.minX, bounds.minY, bounds.maxX - bounds.minX, bounds.maxY - bounds.minY);
    }
  }
  context.stroke();
}

function drawCenters(context: CanvasRenderingContext2D, scene: Scene, pixel: number): void {
  const pose: Pose = { x: 0, y: 0, angle: 0 };
  const center = { x: 0, y: 0 };
  const velocity = { x: 0, y: 0 };
  const bodies = scene.bodies;
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
    center.x = pose.x + cos * rx - sin * ry;
    center.y = pose.y + sin * rx + cos * ry;
    if (scene.debug.centers) {
      const size = 5 * pixel;
      context.strokeStyle = CENTER_COLOR;
      context.lineWidth = 1.5 * pixel;
      context.beginPath();
      context.moveTo(center.x - size, center.y);
      context.lineTo(center.x + size, center.y);
      context.moveTo(center.x, center.y - size);
      context.lineTo(center.x, center.y + size);
      context.stroke();
    }
    if (scene.debug.velocities && body.isAwake) {
      const v = body.linearVelocity;
      velocity.x = v.x * scene.velocityScale;
      velocity.y = v.y * scene.velocityScale;
      drawArrow(context, scene.viewport.scale, center, velocity, { kind: 'velocity', width: 1.5 });
    }
  }
}
