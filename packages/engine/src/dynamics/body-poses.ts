import type { Body } from './body.ts';

// What the narrow phase's gates need of each body, by world index, copied in one pass over the
// bodies at the start of the narrow phase, so the contact loop decides most contacts (far apart,
// or resting with a reusable manifold) from numbers and never loads their Contact, Body or
// Transform objects (contact-manager.ts). Layout per body, stride 8 doubles (one cache line):
//   0 x, 1 y, 2 c, 3 s   the transform (origin, cosine, sine)
//   4 vx, 5 vy           linear velocity (m/s)
//   6 spin reach         |angular velocity| * maxExtent (m/s): the rim speed the gate allows for
//   7 origin reach       the farthest point of the body's shapes from its origin (m)
// The offsets are literals in contact-manager.ts, the one loop that reads them.
export const POSE_STRIDE = 8;

/** Each body's pose and speed for the narrow phase, by world index, and whether it is awake. */
export class BodyPoses {
  data: Float64Array = new Float64Array(POSE_STRIDE * 64);
  /** 1 where the body is awake (Body.awake), else 0. */
  awake: Uint8Array = new Uint8Array(64);

  /** Frees the room of a world that shrank (the next load grows it again). */
  shrink(): void {
    if (this.awake.length <= 64) return;
    this.awake = new Uint8Array(64);
    this.data = new Float64Array(POSE_STRIDE * 64);
  }

  /** Copies every body's numbers; `bodies` is the world's body list (index = world index). */
  load(bodies: readonly Body[]): void {
    const count = bodies.length;
    if (this.awake.length < count) {
      let size = this.awake.length;
      while (size < count) size *= 2;
      this.awake = new Uint8Array(size);
      this.data = new Float64Array(size * POSE_STRIDE);
    }
    const d = this.data;
    const awake = this.awake;
    for (let n = 0; n < count; n++) {
      const body = bodies[n]!;
      const xf = body.transform;
      const p = n * POSE_STRIDE;
      d[p] = xf.x;
      d[p + 1] = xf.y;
      d[p + 2] = xf.c;
      d[p + 3] = xf.s;
      d[p + 4] = body.velocityX;
      d[p + 5] = body.velocityY;
      d[p + 6] = Math.abs(body.angularVelocityValue) * body.maxExtent;
      d[p + 7] = body.originReach;
      awake[n] = body.awake ? 1 : 0;
    }
  }

  /** Marks bodies woken during the narrow phase (the first `count` of `bodies`) awake. */
  markAwake(bodies: readonly Body[], count: number): void {
    const awake = this.awake;
    for (let i = 0; i < count; i++) awake[bodies[i]!.worldIndex] = 1;
  }
}
