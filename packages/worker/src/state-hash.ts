import type { World } from '@physical/engine';

const scratch = new Float64Array(1);
const bytes = new Uint8Array(scratch.buffer);

/**
 * FNV-1a (32-bit) over every body's float64 position, angle and velocities, in world order: two
 * worlds that stepped identically hash equally, any bit of difference almost surely not.
 */
export function worldStateHash(world: World): string {
  let hash = 0x811c9dc5;
  const mix = (value: number): void => {
    scratch[0] = value;
    for (let i = 0; i < 8; i++) {
      hash ^= bytes[i]!;
      hash = Math.imul(hash, 0x01000193);
    }
  };
  for (const body of world.bodies) {
    mix(body.position.x);
    mix(body.position.y);
    mix(body.angle);
    mix(body.linearVelocity.x);
    mix(body.linearVelocity.y);
    mix(body.angularVelocity);
  }
  return (hash >>> 0).toString(16).padStart(8, '0');
}
