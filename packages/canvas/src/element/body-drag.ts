import { mouseJoint, type Body, type MouseJoint, type World } from '@physical/engine';

/** Fastest throw (m/s): a flick is fast, not ballistic. */
const MAX_THROW_SPEED = 50;

/**
 * Bodies held by pointers: one mouse joint (the engine's soft, force-limited pull; Box2D v3's
 * mouse joint) per pointer, so several fingers drag several bodies. Releasing sets the body's
 * velocity to the finger's: a throw.
 */
export class BodyDrag {
  private readonly joints = new Map<number, MouseJoint>();

  /** Number of bodies held now. */
  get size(): number {
    return this.joints.size;
  }

  /**
   * Grabs `body` at the world point (x, y) where the pointer pressed, and pulls that point to
   * (toX, toY). Only dynamic bodies in `world` can be dragged; returns false for others.
   */
  start(
    world: World,
    pointerId: number,
    body: Body,
    x: number,
    y: number,
    toX: number,
    toY: number,
  ): boolean {
    if (body.type !== 'dynamic' || !world.has(body)) return false;
    this.end(pointerId, 0, 0, false);
    const joint = world.addJoint(mouseJoint({ body, target: { x, y } }));
    joint.target = { x: toX, y: toY };
    this.joints.set(pointerId, joint);
    return true;
  }

  /** Moves the pointer's target (m). */
  move(pointerId: number, x: number, y: number): void {
    const joint = this.joints.get(pointerId);
    if (joint !== undefined && joint.world !== null) joint.target = { x, y };
  }

  /**
   * Lets go: the body leaves with the finger's velocity (vx, vy) (m/s, capped) when `isThrow`,
   * or with its own (a cancelled pointer).
   */
  end(pointerId: number, vx: number, vy: number, isThrow: boolean): void {
    const joint = this.joints.get(pointerId);
    if (joint === undefined) return;
    this.joints.delete(pointerId);
    const world = joint.world;
    if (world === null) return; // the body (and with it the joint) left the world
    world.removeJoint(joint);
    if (!isThrow) return;
    const speed = Math.hypot(vx, vy);
    const cap = speed > MAX_THROW_SPEED ? MAX_THROW_SPEED / speed : 1;
    joint.body.linearVelocity = { x: vx * cap, y: vy * cap };
  }

  /** Lets go of everything, without throwing (drag turned off, world replaced, detached). */
  clear(): void {
    for (const pointerId of [...this.joints.keys()]) this.end(pointerId, 0, 0, false);
  }
}
