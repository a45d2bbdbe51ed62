import type { World } from '@physical/engine';

/** Numbers recorded per body: x, y, angle, vx, vy, angular velocity. */
const FIELDS = 6;

/** Every body's state as float64s, in `world.bodies` order. */
export function bodyStates(world: World): Float64Array {
  const bodies = world.bodies;
  const state = new Float64Array(FIELDS * bodies.length);
  for (let i = 0; i < bodies.length; i++) {
    const body = bodies[i]!;
    state[FIELDS * i] = body.position.x;
    state[FIELDS * i + 1] = body.position.y;
    state[FIELDS * i + 2] = body.angle;
    state[FIELDS * i + 3] = body.linearVelocity.x;
    state[FIELDS * i + 4] = body.linearVelocity.y;
    state[FIELDS * i + 5] = body.angularVelocity;
  }
  return state;
}

/**
 * 32-bit FNV-1a (Fowler, Noll, Vo) over the bytes of every body's state: the exact float64 bits,
 * so any change in the last bit of any body shows. Returned as 8 hex digits.
 */
export function hashWorld(world: World): string {
  const bytes = new Uint8Array(bodyStates(world).buffer);
  let hash = 0x811c9dc5;
  for (let i = 0; i < bytes.length; i++) {
    hash ^= bytes[i]!;
    hash = Math.imul(hash, 0x01000193) >>> 0;
  }
  return hash.toString(16).padStart(8, '0');
}
