import type { BroadPhase } from '../collision/broad-phase.ts';
import { AABB } from '../geometry/aabb.ts';
import type { Body } from './body.ts';
import type { Shape } from './shape.ts';
import {
  ESCAPE_ID,
  ESCAPE_MAX_X,
  ESCAPE_MAX_Y,
  ESCAPE_MIN_X,
  ESCAPE_MIN_Y,
  ESCAPE_STRIDE,
} from './shape-escapes.ts';
import { A_BOUNDS_DT } from './kernel-arguments.ts';
import {
  BODIES,
  ESCAPED_SHAPES,
  KERNEL_ARGUMENTS,
  SHAPE_BOXES,
  SHAPE_GEOMETRY,
  SHAPE_NEXT,
  type SolverMemory,
} from './solver-memory.ts';

/**
 * Keeps a body's shapes' broad-phase boxes around them: each shape's box at the body's pose, grown
 * by the speculative distance and by the motion the body would make in the next step of `dt`
 * seconds (its velocity, and its spin swept over its extent), so contacts exist before shapes
 * touch. The broad phase moves a proxy only when this box leaves its fat box (Box2D v3 computes
 * the same box while finalizing bodies, "b2FinalizeBodiesTask"). The boxes are the kernel's
 * (wasm/shape-bounds.ts: shapeBounds in a step's finalize, bodyBounds for one body outside it),
 * their one source; this moves the proxies the kernel lists.
 */
export class BodyBounds {
  private readonly box = new AABB();
  /** A shape's fat box, read from the broad phase on its way into the shape table. */
  private readonly fat = new AABB();

  /**
   * The step the boxes look ahead (s), set before refresh. A field, not an argument: V8 boxes a
   * fractional argument of a call it does not inline, and refresh runs per swept body per step.
   */
  dt: number = 1 / 60;

  constructor(
    private readonly broadPhase: BroadPhase,
    private readonly shapesById: readonly (Shape | null)[],
    private readonly memory: SolverMemory,
  ) {}

  /**
   * Moves the proxies of the `count` shapes the kernel's shapeBounds (wasm/shape-bounds.ts) found
   * out of their fat boxes in a step's finalize, listed in `escaped` (shape-escapes.ts) in the
   * bodies' awake order and each body's shape order, and stores their new fat boxes.
   */
  moveEscaped(escaped: Float64Array, count: number): void {
    this.moveListed(escaped, count, false);
  }

  /** The speculative box of a shape at its body's pose (m); valid until the next call. */
  speculativeBox(shape: Shape, dt: number): AABB {
    const escaped = this.measure(shape.body, shape.id, dt, true);
    const box = this.box;
    box.minX = escaped[ESCAPE_MIN_X]!;
    box.minY = escaped[ESCAPE_MIN_Y]!;
    box.maxX = escaped[ESCAPE_MAX_X]!;
    box.maxY = escaped[ESCAPE_MAX_Y]!;
    return box;
  }

  /**
   * Moves the proxies of `body`'s shapes whose speculative box left their fat box. With
   * `forcePairs`, a static body's proxies look for new pairs even if they did not move.
   */
  refresh(body: Body, forcePairs: boolean): void {
    const every = forcePairs && body.type === 'static';
    const escaped = this.measure(body, -1, this.dt, every);
    this.moveListed(escaped, this.listed, every);
  }

  /** How many shapes the last {@link measure} listed. */
  private listed = 0;

  /**
   * The kernel's boxes of `body`'s shapes (only shape `only` when it is not -1), each tight box
   * written into the shape table; lists those that left their fat box (all, with `every`).
   */
  private measure(body: Body, only: number, dt: number, every: boolean): Float64Array {
    const memory = this.memory;
    const o = memory.offsets;
    // Through the memory: V8 can box a double passed to WebAssembly, and this runs per swept body
    // (~16 KB of garbage a step in tumbler as an argument; kernel-arguments.ts).
    memory.kernelArguments[A_BOUNDS_DT] = dt;
    this.listed = memory.kernel.bodyBounds(
      o[BODIES]!,
      body.base,
      only,
      o[SHAPE_BOXES]!,
      o[SHAPE_GEOMETRY]!,
      o[SHAPE_NEXT]!,
      o[KERNEL_ARGUMENTS]!,
      o[ESCAPED_SHAPES]!,
      every ? 1 : 0,
    );
    return memory.escapedShapes;
  }

  /**
   * Moves the listed proxies whose box left their fat box (all of them, when the kernel listed
   * only those) and stores their new fat boxes; with `forcePairs`, the others look for new pairs.
   */
  private moveListed(escaped: Float64Array, count: number, forcePairs: boolean): void {
    const broadPhase = this.broadPhase;
    const box = this.box;
    for (let i = 0; i < count; i++) {
      const e = i * ESCAPE_STRIDE;
      const shape = this.shapesById[escaped[e + ESCAPE_ID]!]!;
      box.minX = escaped[e + ESCAPE_MIN_X]!;
      box.minY = escaped[e + ESCAPE_MIN_Y]!;
      box.maxX = escaped[e + ESCAPE_MAX_X]!;
      box.maxY = escaped[e + ESCAPE_MAX_Y]!;
      // The tree holds the fat box the kernel tested against: a box listed as escaped moves.
      if (broadPhase.moveProxy(shape.proxyKey, box)) {
        shape.setFatBox(broadPhase.getFatAABB(shape.proxyKey, this.fat));
      } else if (forcePairs) {
        broadPhase.bufferMove(shape.proxyKey);
      }
    }
  }
}
