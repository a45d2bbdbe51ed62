import { MAX_FORCE, POLYGON_RADIUS } from './inertia-scene.ts';

/**
 * A push by hand (PhET's "Forces and Motion" lets a learner push the object): the learner
 * presses on the body and pulls out an arrow; the push points the way the finger moved from
 * where it pressed and grows with that distance, up to the dialog's largest force. A finger that
 * stays put keeps the push constant while the body moves away under it: F = m a, plainly.
 */

/** Newtons of push per metre the finger moved from where it pressed. */
export const PUSH_PER_METRE = 2;
/** A press this close to the body's centre (m) starts a push: the body and a finger's width. */
export const PUSH_REACH = POLYGON_RADIUS + 0.3;
/** The push of a held arrow key (N): the keyboard's equal of a drag. */
export const KEY_PUSH = 2;

/** The push (N, y-down) for a finger pressed at `start` and now at `finger` (m). */
export function pushFromDrag(
  start: { x: number; y: number },
  finger: { x: number; y: number },
): { x: number; y: number } {
  const dx = finger.x - start.x;
  const dy = finger.y - start.y;
  const size = Math.hypot(dx, dy) * PUSH_PER_METRE;
  if (size === 0) return { x: 0, y: 0 };
  const scale = Math.min(size, MAX_FORCE) / size;
  return { x: dx * PUSH_PER_METRE * scale, y: dy * PUSH_PER_METRE * scale };
}

/** Whether a press at `point` (m) is on the body centred at `centre`: it starts a push. */
export function startsPush(
  centre: { x: number; y: number },
  point: { x: number; y: number },
): boolean {
  return Math.hypot(point.x - centre.x, point.y - centre.y) <= PUSH_REACH;
}

/** Arrow keys and the direction (y-down) each pushes in. */
export const PUSH_KEYS: Readonly<Record<string, { x: number; y: number }>> = {
  ArrowRight: { x: 1, y: 0 },
  ArrowLeft: { x: -1, y: 0 },
  ArrowUp: { x: 0, y: -1 },
  ArrowDown: { x: 0, y: 1 },
};

/**
 * The push of the arrow keys held down (N, y-down): {@link KEY_PUSH} along their summed
 * direction (two keys push diagonally with the same size), zero when none or opposite ones.
 */
export function pushFromKeys(held: ReadonlySet<string>): { x: number; y: number } {
  let x = 0;
  let y = 0;
  for (const key of held) {
    const direction = PUSH_KEYS[key];
    if (direction === undefined) continue;
    x += direction.x;
    y += direction.y;
  }
  const size = Math.hypot(x, y);
  return size === 0 ? { x: 0, y: 0 } : { x: (x / size) * KEY_PUSH, y: (y / size) * KEY_PUSH };
}
