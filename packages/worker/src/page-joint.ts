import type { Body, JointAnchors, JointType, Vec2 } from '@physical/engine';

/**
 * A worker world's page copy of a joint: its type, its bodies' page copies and its anchors, what
 * `<physical-canvas>` draws (`workerWorld.joints`). The joint itself, with its solver passes,
 * lives in the worker; the page checks its options with the engine's `checkJointOptions` and
 * keeps this copy, so a page ships no joint classes.
 */
export class PageJoint {
  /** The joint's type, as `joint.type`. */
  readonly type: JointType;
  /** Its first body's page copy (for a mouse joint, the dragged body, as `bodyB`). */
  readonly bodyA: Body;
  /** Its second body's page copy. */
  readonly bodyB: Body;
  private readonly localA: Vec2;
  private readonly localB: Vec2;
  private readonly viewA: Vec2 = { x: 0, y: 0 };
  private readonly viewB: Vec2 = { x: 0, y: 0 };

  /** A copy joining `bodyA` and `bodyB` at `anchors` (world points, as the joint is made). */
  constructor(type: JointType, bodyA: Body, bodyB: Body, anchors: JointAnchors) {
    this.type = type;
    this.bodyA = bodyA;
    this.bodyB = bodyB;
    // A mouse joint's anchor A is its target, a world point; every other anchor rides its body.
    this.localA =
      type === 'mouse'
        ? { x: anchors.anchorA.x, y: anchors.anchorA.y }
        : bodyA.getLocalPoint(anchors.anchorA);
    this.localB = bodyB.getLocalPoint(anchors.anchorB);
  }

  /**
   * The point on body A in world coordinates (m) at its page copy's pose (for a mouse joint, the
   * target it was made with). A reused view, as `joint.anchorA`.
   */
  get anchorA(): Readonly<Vec2> {
    if (this.type === 'mouse') {
      this.viewA.x = this.localA.x;
      this.viewA.y = this.localA.y;
      return this.viewA;
    }
    return this.bodyA.getWorldPoint(this.localA, this.viewA);
  }

  /** The point on body B in world coordinates (m) at its page copy's pose. A reused view. */
  get anchorB(): Readonly<Vec2> {
    return this.bodyB.getWorldPoint(this.localB, this.viewB);
  }
}
