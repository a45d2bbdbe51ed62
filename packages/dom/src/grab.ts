import type { Body } from '@physical/engine';

/** Spring frequency (Hz) and damping ratio of a grab: firm, and without wobble. */
export const GRAB_HERTZ = 5;
export const GRAB_DAMPING_RATIO = 0.7;
/** The grab's force limit, in multiples of the body's weight under standard gravity. */
export const GRAB_MAX_FORCE_PER_WEIGHT = 1000;

/**
 * A pointer holding a body at a point: pulls that point toward the pointer with a soft spring
 * (frequency {@link GRAB_HERTZ}, damping ratio {@link GRAB_DAMPING_RATIO}), so the body swings
 * and collides while held, and keeps the velocity it had when let go.
 */
export class Grab {
  body: Body;
  private readonly localX: number;
  private readonly localY: number;
  private targetX: number;
  private targetY: number;
  private readonly point = { x: 0, y: 0 };
  private readonly velocity = { x: 0, y: 0 };
  private readonly force = { x: 0, y: 0 };
  private readonly options = { point: this.point };

  /** Holds `body` at the world point (x, y) (m), which is also the first target. */
  constructor(body: Body, x: number, y: number) {
    this.body = body;
    const local = body.getLocalPoint({ x, y });
    this.localX = local.x;
    this.localY = local.y;
    this.targetX = x;
    this.targetY = y;
  }

  /** Moves the target (m). */
  setTarget(x: number, y: number): void {
    this.targetX = x;
    this.targetY = y;
    this.body.wake();
  }

  /** Applies this step's spring force at the held point (call before each world step). */
  apply(): void {
    const body = this.body;
    const mass = body.mass;
    const omega = 2 * Math.PI * GRAB_HERTZ;
    const point = body.getWorldPoint({ x: this.localX, y: this.localY }, this.point);
    const velocity = body.getVelocityAt(point, this.velocity);
    let fx =
      mass *
      (omega * omega * (this.targetX - point.x) - 2 * GRAB_DAMPING_RATIO * omega * velocity.x);
    let fy =
      mass *
      (omega * omega * (this.targetY - point.y) - 2 * GRAB_DAMPING_RATIO * omega * velocity.y);
    const limit = GRAB_MAX_FORCE_PER_WEIGHT * mass * 9.81;
    const size = Math.hypot(fx, fy);
    if (size > limit) {
      fx *= limit / size;
      fy *= limit / size;
    }
    this.force.x = fx;
    this.force.y = fy;
    body.applyForce(this.force, this.options);
  }

  /** Holds `body` instead, at the same local point (the element's body was rebuilt in place). */
  rebind(body: Body): void {
    this.body = body;
  }

  /** Lets go. */
  release(): void {}
}
