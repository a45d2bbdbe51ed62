import type { BroadPhase } from '../collision/broad-phase.ts';
import { AABB_MARGIN, SPECULATIVE_DISTANCE } from '../core/constants.ts';
import { AABB } from '../geometry/aabb.ts';
import type { Body } from './body.ts';
import { B_MAX_EXTENT, B_VX, B_VY, B_W } from './body-memory.ts';
import type { Shape } from './shape.ts';
import {
  ESCAPE_ID,
  ESCAPE_MAX_X,
  ESCAPE_MAX_Y,
  ESCAPE_MIN_X,
  ESCAPE_MIN_Y,
  ESCAPE_STRIDE,
} from './shape-escapes.ts';

/**
 * Keeps a body's shapes' broad-phase boxes around them: each shape's box at the body's pose, grown
 * by the speculative distance and by the motion the body would make in the next step of `dt`
 * seconds (its velocity, and its spin swept over its extent), so contacts exist before shapes
 * touch. The broad phase moves a proxy only when this box leaves its fat box (Box2D v3 computes
 * the same box while finalizing bodies, "b2FinalizeBodiesTask").
 */
export class BodyBounds {
  private readonly box = new AABB();
  /** A shape's fat box, read from the broad phase on its way into the shape table. */
  private readonly fat = new AABB();
  // The growth of the body last passed to measureMotion.
  private grow = -0;
  private backX = -0;
  private backY = -0;
  private aheadX = -0;
  private aheadY = -0;

  /**
   * The step the boxes look ahead (s), set before refresh. A field, not an argument: V8 boxes a
   * fractional argument of a call it does not inline, and refresh runs per moving body per step.
   */
  dt: number = 1 / 60;

  constructor(
    private readonly broadPhase: BroadPhase,
    private readonly shapesById: readonly (Shape | null)[],
  ) {}

  /**
   * Moves the proxies of the `count` shapes the kernel's shapeBounds (wasm/shape-bounds.ts) found
   * out of their fat boxes in a step's finalize, listed in `escaped` (shape-escapes.ts) in the
   * order the TypeScript of {@link refresh} would have moved them, and stores their new fat boxes.
   */
  moveEscaped(escaped: Float64Array, count: number): void {
    const broadPhase = this.broadPhase;
    const box = this.box;
    for (let i = 0; i < count; i++) {
      const e = i * ESCAPE_STRIDE;
      const shape = this.shapesById[escaped[e + ESCAPE_ID]!]!;
      box.minX = escaped[e + ESCAPE_MIN_X]!;
      box.minY = escaped[e + ESCAPE_MIN_Y]!;
      box.maxX = escaped[e + ESCAPE_MAX_X]!;
      box.maxY = escaped[e + ESCAPE_MAX_Y]!;
      // Listed because the box left the fat box, which the tree holds too: this moves it.
      broadPhase.moveProxy(shape.proxyKey, box);
      shape.setFatBox(broadPhase.getFatAABB(shape.proxyKey, this.fat));
    }
  }

  /** The speculative box of a shape at its body's pose (m); valid until the next call. */
  speculativeBox(shape: Shape, dt: number): AABB {
    this.dt = dt;
    this.measureMotion(shape.body);
    return this.place(shape.computeAABB(shape.body.transform));
  }

  /**
   * Moves the proxies of `body`'s shapes whose speculative box left their fat box. With
   * `forcePairs`, a static body's proxies look for new pairs even if they did not move.
   */
  refresh(body: Body, forcePairs: boolean): void {
    this.measureMotion(body);
    const broadPhase = this.broadPhase;
    const shapes = body.shapeList;
    for (let i = 0; i < shapes.length; i++) {
      const shape = shapes[i]!;
      const box = this.place(shape.computeAABB(body.transform));
      if (broadPhase.moveProxy(shape.proxyKey, box)) {
        shape.setFatBox(broadPhase.getFatAABB(shape.proxyKey, this.fat));
      } else if (forcePairs && body.type === 'static') {
        broadPhase.bufferMove(shape.proxyKey);
      }
    }
  }

  private measureMotion(body: Body): void {
    const dt = this.dt;
    // The body's numbers in place (body-memory.ts).
    const d = body.store.data;
    const b = body.base;
    const spin = Math.abs(d[b + B_W]!) * d[b + B_MAX_EXTENT]! * dt;
    let grow = SPECULATIVE_DISTANCE;
    if (spin > AABB_MARGIN) grow += spin;
    let dx = d[b + B_VX]! * dt;
    let dy = d[b + B_VY]! * dt;
    // A body that moves farther in a step than the fat margin gets its box stretched along its
    // velocity, so the pair exists (and its speculative contact can stop the motion) before it
    // reaches what it will hit; stretching slower bodies would only make idle pairs.
    if (dx * dx + dy * dy <= AABB_MARGIN * AABB_MARGIN) {
      dx = 0;
      dy = 0;
    }
    this.grow = grow;
    this.backX = Math.min(dx, 0);
    this.backY = Math.min(dy, 0);
    this.aheadX = Math.max(dx, 0);
    this.aheadY = Math.max(dy, 0);
  }

  private place(tight: AABB): AABB {
    const box = this.box;
    const grow = this.grow;
    box.minX = tight.minX - grow + this.backX;
    box.minY = tight.minY - grow + this.backY;
    box.maxX = tight.maxX + grow + this.aheadX;
    box.maxY = tight.maxY + grow + this.aheadY;
    return box;
  }
}
