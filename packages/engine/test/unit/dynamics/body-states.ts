import type { Body } from '@physical/engine';

/** Each body's position, angle, linear and angular velocity, 6 numbers a body, in list order. */
export function bodyStates(bodies: readonly Body[]): Float64Array {
  const states = new Float64Array(bodies.length * 6);
  bodies.forEach((b, i) => {
    states.set(
      [
        b.position.x,
        b.position.y,
        b.angle,
        b.linearVelocity.x,
        b.linearVelocity.y,
        b.angularVelocity,
      ],
      i * 6,
    );
  });
  return states;
}

/** How many numbers differ bit for bit (Object.is: -0 and 0 differ, NaN equals NaN). */
export function differingBits(a: Float64Array, b: Float64Array): number {
  if (a.length !== b.length) return Math.max(a.length, b.length);
  let count = 0;
  for (let i = 0; i < a.length; i++) if (!Object.is(a[i], b[i])) count++;
  return count;
}
