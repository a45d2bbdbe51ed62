import { mouseJoint, type Body, type MouseJoint, type World } from '@physical/engine';

/**
 * A pointer holding a body: the engine's mouse joint (Box2D v3's soft, force-limited pull)
 * from the point the pointer pressed toward the pointer, so the body swings and collides while
 * held and keeps its velocity when let go. Defaults: 5 Hz, damping ratio 0.7, at most 1000 times
 * the body's mass in newtons.
 */
export class Grab {
  private readonly world: World;
  private joint: MouseJoint;
  private readonly localX: number;
  private readonly localY: number;

  /** Holds `body` at the world point (x, y) (m), which is also the first target. */
  constructor(world: World, body: Body, x: number, y: number) {
    this.world = world;
    const local = body.getLocalPoint({ x, y });
    this.localX = local.x;
    this.localY = local.y;
    this.joint = world.addJoint(mouseJoint({ body, target: { x, y } }));
  }

  /** The held body. */
  get body(): Body {
    return this.joint.body;
  }

  /** Moves the target (m); wakes the body. */
  setTarget(x: number, y: number): void {
    this.joint.target = { x, y };
  }

  /**
   * Holds `body` instead, by the same local point and toward the same target (the element's
   * body was rebuilt in place: it changed size or state).
   */
  rebind(body: Body): void {
    const target = this.joint.target;
    const targetX = target.x;
    const targetY = target.y;
    this.release();
    this.joint = this.world.addJoint(
      mouseJoint({ body, target: body.getWorldPoint({ x: this.localX, y: this.localY }) }),
    );
    this.joint.target = { x: targetX, y: targetY };
  }

  /** Lets go (removing the body already took its joint away). */
  release(): void {
    if (this.joint.world === this.world) this.world.removeJoint(this.joint);
  }
}
