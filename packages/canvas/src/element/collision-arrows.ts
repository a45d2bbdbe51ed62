import type { CollisionArrowView } from '../draw/draw-collision-arrows.ts';
import type { CollisionLike } from '../draw/drawing-source.ts';

/** One live arrow pair; the record is reused when it dies. */
class CollisionArrow implements CollisionArrowView {
  x = 0;
  y = 0;
  forceX = 0;
  forceY = 0;
  opacity = 0;
  age = 0;
}

/**
 * Collisions slower than this (m/s, approach speed along the normal) make no arrow: resting
 * contacts are pushed apart every step and would cover a pile in arrows.
 */
export const MIN_ARROW_APPROACH_SPEED = 0.1;

/** Most arrows alive at once; the oldest is replaced. */
const CAPACITY = 128;

/**
 * The collision-force arrows: copied out of the world's (reused) collision events, aged by the
 * frame loop, faded over `duration` seconds and then dropped.
 */
export class CollisionArrows {
  /** Lifetime (s) of an arrow. */
  duration = 1;
  /** With reduced motion, arrows do not fade: full opacity, then gone. */
  fade = true;
  private readonly live: CollisionArrow[] = [];
  private readonly pool: CollisionArrow[] = [];

  /** The arrows to draw. */
  get arrows(): readonly CollisionArrowView[] {
    return this.live;
  }

  /** True while an arrow is alive (the loop keeps drawing until they have faded). */
  get isEmpty(): boolean {
    return this.live.length === 0;
  }

  /** Records a collision of a step of `dt` seconds, if it was an impact. */
  record(event: CollisionLike, dt: number): void {
    const count = event.pointCount ?? event.points.length;
    if (event.approachSpeed < MIN_ARROW_APPROACH_SPEED || count === 0) return;
    let arrow: CollisionArrow;
    if (this.live.length >= CAPACITY) arrow = this.live.shift()!;
    else arrow = this.pool.pop() ?? new CollisionArrow();
    let x = 0;
    let y = 0;
    for (let i = 0; i < count; i++) {
      x += event.points[i]!.x;
      y += event.points[i]!.y;
    }
    const force = event.normalImpulse / dt;
    arrow.x = x / count;
    arrow.y = y / count;
    arrow.forceX = event.normalX * force;
    arrow.forceY = event.normalY * force;
    arrow.age = 0;
    arrow.opacity = 1;
    this.live.push(arrow);
  }

  /** Ages every arrow by `elapsed` seconds and drops the dead. */
  advance(elapsed: number): void {
    const live = this.live;
    let kept = 0;
    for (let i = 0; i < live.length; i++) {
      const arrow = live[i]!;
      arrow.age += elapsed;
      if (arrow.age >= this.duration) {
        this.pool.push(arrow);
        continue;
      }
      arrow.opacity = this.fade ? 1 - arrow.age / this.duration : 1;
      live[kept++] = arrow;
    }
    live.length = kept;
  }

  /** Drops every arrow. */
  clear(): void {
    for (const arrow of this.live) this.pool.push(arrow);
    this.live.length = 0;
  }
}
