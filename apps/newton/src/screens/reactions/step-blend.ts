import type { Body } from '@physical/engine';

/**
 * Where to draw the particles between two steps. The overlay draws them (disc-sprites.ts); drawn
 * where the last step left them, a particle in slow motion (a step every fourth frame) stood
 * still for three frames and jumped on the fourth. The canvas blends its own bodies' poses between
 * the last two steps by its frame loop's fraction, which it does not publish, so this keeps the
 * same blend for the particles: their positions before the last step, and when it was taken.
 *
 * Fed by the step hook (`before`, then `after`); allocates nothing once it has room for them.
 */
export class StepBlend {
  private readonly bodies: Body[] = [];
  private xs = new Float64Array(64);
  private ys = new Float64Array(64);
  /** Wall-clock time (ms) the last step ended, or -Infinity before the first. */
  private stepAt = -Infinity;

  /** Just before a step: where each particle is, in the order the overlay will draw them. */
  before(particles: Iterable<Body>): void {
    let k = 0;
    for (const body of particles) {
      if (k === this.xs.length) {
        const xs = new Float64Array(2 * k);
        const ys = new Float64Array(2 * k);
        xs.set(this.xs);
        ys.set(this.ys);
        this.xs = xs;
        this.ys = ys;
      }
      const position = body.position;
      this.xs[k] = position.x;
      this.ys[k] = position.y;
      this.bodies[k] = body;
      k++;
    }
    this.bodies.length = k;
  }

  /** Just after the step, at `now` (ms, `performance.now()`). */
  after(now: number): void {
    this.stepAt = now;
  }

  /**
   * How far from the positions before the last step to those after it a frame at `now` (ms)
   * shows: 0 at the step, 1 once a step's time has passed on the wall clock (`stepMs`: the step
   * divided by the time scale), and 1 while `paused` (a single step shows where it ended).
   */
  fraction(now: number, stepMs: number, paused: boolean): number {
    if (paused) return 1;
    return Math.min(1, Math.max(0, (now - this.stepAt) / stepMs));
  }

  /**
   * Writes to `out` where to draw `body`, the `k`th particle in the order of {@link before}:
   * blended by `fraction`, or where it is when the `k`th is another body (added or removed since).
   */
  at(body: Body, k: number, fraction: number, out: { x: number; y: number }): void {
    const position = body.position;
    if (fraction >= 1 || this.bodies[k] !== body) {
      out.x = position.x;
      out.y = position.y;
      return;
    }
    const stay = 1 - fraction;
    out.x = stay * this.xs[k]! + fraction * position.x;
    out.y = stay * this.ys[k]! + fraction * position.y;
  }
}
