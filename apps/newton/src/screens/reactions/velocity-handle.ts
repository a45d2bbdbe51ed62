import type { Body } from '@physical/engine';
import { MAX_SPEED } from './reactions-scene.ts';

/** Metres of velocity arrow per m/s, from the particle's rim. */
export const VELOCITY_ARROW_SCALE = 0.5;
/** How near (m) a press must be to a handle to grab it. */
export const HANDLE_REACH = 0.3;
/** Dragged velocities snap to this step (m/s): round numbers, and a straight 1-D push is easy. */
export const VELOCITY_SNAP = 0.1;

function radiusOf(body: Body): number {
  const geometry = body.shapes[0]?.geometry;
  return geometry?.kind === 'circle' ? geometry.radius : 0;
}

/**
 * The tip of a particle's velocity arrow, its drag handle (m): from the rim along the velocity,
 * {@link VELOCITY_ARROW_SCALE} metres per m/s (at rest, on the rim at the right). Written into
 * `out` when given (a frame's drawing allocates nothing).
 */
export function handlePoint(
  body: Body,
  out: { x: number; y: number } = { x: 0, y: 0 },
): { x: number; y: number } {
  const v = body.linearVelocity;
  const speed = Math.hypot(v.x, v.y);
  const moving = speed > 1e-9;
  const dx = moving ? v.x / speed : 1;
  const dy = moving ? v.y / speed : 0;
  const length = radiusOf(body) + speed * VELOCITY_ARROW_SCALE;
  out.x = body.position.x + dx * length;
  out.y = body.position.y + dy * length;
  return out;
}

/**
 * The velocity (m/s) a handle dragged to `point` (m) sets: the arrow from the rim to the point,
 * each component snapped to {@link VELOCITY_SNAP} and kept within ±{@link MAX_SPEED}.
 */
export function velocityFromHandle(
  body: Body,
  point: { x: number; y: number },
): { x: number; y: number } {
  const dx = point.x - body.position.x;
  const dy = point.y - body.position.y;
  const distance = Math.hypot(dx, dy);
  if (distance < 1e-9) return { x: 0, y: 0 };
  const speed = Math.max(0, distance - radiusOf(body)) / VELOCITY_ARROW_SCALE;
  const snap = (value: number): number => {
    const snapped = Math.round(value / VELOCITY_SNAP) * VELOCITY_SNAP;
    const clamped = Math.min(MAX_SPEED, Math.max(-MAX_SPEED, snapped));
    // 0.30000000000000004 reads as 0.3.
    return Number(clamped.toFixed(6)) + 0;
  };
  return { x: snap((dx / distance) * speed), y: snap((dy / distance) * speed) };
}
