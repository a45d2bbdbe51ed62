// The pose stream: per step, [id, x, y, angle] per body (float32, 16 bytes a body).
//
// Transferred: one Float32Array per step, moved to the page (no copy), with the bodies that
// moved in the step (awake, or asleep since this step: their resting pose).
//
// Shared (cross-origin isolated pages): two pose buffers in one SharedArrayBuffer. The worker
// writes every non-static body into the buffer the page is not reading, then publishes it by
// bumping the frame counter (Atomics.store, which orders the writes before it); the page reads
// the counter with Atomics.load and then the buffer of that frame. A page that skips frames still
// gets every body's latest pose.

/** Floats per body in the stream. */
export const POSE_STRIDE = 4;

/** Int32 header of the shared memory: frame counter, then per buffer: body count and awake count. */
const HEADER_INTS = 8;
const FRAME = 0;
const COUNT = 1; // + buffer
const AWAKE = 3; // + buffer
const STEP = 5; // + buffer

/** The SharedArrayBuffer of a shared pose stream for `capacity` bodies. */
export function createSharedPoses(capacity: number): SharedArrayBuffer {
  return new SharedArrayBuffer(HEADER_INTS * 4 + 2 * capacity * POSE_STRIDE * 4);
}

/** Views of a shared pose stream. */
export class SharedPoses {
  readonly header: Int32Array;
  readonly buffers: readonly [Float32Array, Float32Array];
  readonly capacity: number;

  constructor(memory: SharedArrayBuffer) {
    this.header = new Int32Array(memory, 0, HEADER_INTS);
    this.capacity = Math.floor((memory.byteLength - HEADER_INTS * 4) / (2 * POSE_STRIDE * 4));
    const size = this.capacity * POSE_STRIDE;
    this.buffers = [
      new Float32Array(memory, HEADER_INTS * 4, size),
      new Float32Array(memory, HEADER_INTS * 4 + size * 4, size),
    ];
  }

  /** The last published frame (0 before the first). */
  get frame(): number {
    return Atomics.load(this.header, FRAME);
  }

  /** The buffer to write the next frame into (worker). */
  next(): Float32Array {
    return this.buffers[(this.frame + 1) & 1];
  }

  /** Publishes the buffer `next()` returned, holding `count` bodies (worker). */
  publish(count: number, awake: number, step: number): void {
    const buffer = (this.frame + 1) & 1;
    Atomics.store(this.header, COUNT + buffer, count);
    Atomics.store(this.header, AWAKE + buffer, awake);
    Atomics.store(this.header, STEP + buffer, step);
    Atomics.add(this.header, FRAME, 1);
  }

  /** Reads frame `frame`'s buffer and counts (page). */
  read(frame: number): { poses: Float32Array; count: number; awake: number; step: number } {
    const buffer = frame & 1;
    return {
      poses: this.buffers[buffer],
      count: Atomics.load(this.header, COUNT + buffer),
      awake: Atomics.load(this.header, AWAKE + buffer),
      step: Atomics.load(this.header, STEP + buffer),
    };
  }
}
