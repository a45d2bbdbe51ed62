import type { Body, CollisionEvent } from '@physical/engine';

/** One pair of equal and opposite arrows at a contact. */
export interface ReactionArrow {
  /** Contact point (m). */
  x: number;
  y: number;
  /** Unit normal from A to B. */
  nx: number;
  ny: number;
  /**
   * Impulse (N s) of the collision: the normal impulses of the steps the pair kept pushing on
   * each other, summed (an inelastic pair pushes over several steps).
   */
  impulse: number;
  /** Simulated time (s) it was last recorded at. */
  time: number;
}

/** What the collision arrows and messages show. */
export type ArrowMeasure = 'impulse' | 'force';

/**
 * Contact times (s) a learner can assume for the average force F = J / Δt. The simulation
 * resolves a collision within one step, so no duration comes out of it: the time is stated, not
 * measured (a tennis ball touches a racket for about 5 ms, a billiard ball another for 0.2 ms).
 */
export const CONTACT_TIMES = [0.001, 0.01, 0.1] as const;
export const DEFAULT_CONTACT_TIME = 0.01;

/** The average force (N) of an impulse (N s) spread over `contactTime` (s): F = J / Δt. */
export function averageForce(impulse: number, contactTime: number): number {
  return impulse / contactTime;
}

/** Seconds of simulated time an arrow pair stays fully visible, then fades over the same again. */
export const ARROW_HOLD = 0.5;
export const ARROW_LIFETIME = 1;
/** Impulses below this (N s) are resting contact noise, not drawn. */
const MIN_IMPULSE = 1e-4;
/**
 * Most arrow pairs shown at once: the strongest (impulse times opacity). A pile of 50 particles
 * crossing a tilted tray collides in some 130 pairs at a time; all their arrows cover the
 * particles, so that no one collision can be read, and filling them took a slow phone's CPU
 * raster more than half of each frame. At 24 pairs the arrows still crossed each other in a
 * pile and cost 3 ms of a 15 ms frame (4x CPU); at 12 each pair reads apart, for 1.5 ms. Two
 * particles, or a few, show every collision.
 */
export const MAX_SHOWN_PAIRS = 12;

/**
 * The thesis's onCollision drawing: every collision leaves two arrows at the contact, the force
 * on A and the force on B, equal in size and opposite in direction. One pair per pair of bodies
 * (the newest), held for {@link ARROW_HOLD} and gone after {@link ARROW_LIFETIME}.
 */
export class CollisionArrows {
  /** By pair of bodies: A's id times 2^21 plus B's (a number key: no string per event). */
  private readonly pairs = new Map<number, ReactionArrow>();
  private readonly ids = new WeakMap<Body, number>();
  private nextId = 0;
  /** {@link visible}'s list and its entries, reused from frame to frame. */
  private readonly shown: VisibleArrow[] = [];
  private readonly pool: VisibleArrow[] = [];

  private idOf(body: Body): number {
    let id = this.ids.get(body);
    if (id === undefined) {
      id = this.nextId++;
      this.ids.set(body, id);
    }
    return id;
  }

  /** Records a collision event (copying what it needs: events are reused). */
  record(event: CollisionEvent, dt: number, time: number): void {
    if (event.normalImpulse < MIN_IMPULSE || event.pointCount === 0) return;
    let x = 0;
    let y = 0;
    for (let i = 0; i < event.pointCount; i++) {
      x += event.points[i]!.x;
      y += event.points[i]!.y;
    }
    const key = this.idOf(event.bodyA) * 2 ** 21 + this.idOf(event.bodyB);
    let arrow = this.pairs.get(key);
    // Pushing on in the very next step: the same collision, its impulse adds up.
    const going = arrow !== undefined && time - arrow.time <= 1.5 * dt;
    const impulse = (going ? arrow!.impulse : 0) + event.normalImpulse;
    // A pile on a tilted tray collides in every step: the pair's arrow is rewritten in place.
    if (arrow === undefined) {
      arrow = { x: 0, y: 0, nx: 0, ny: 0, impulse: 0, time: 0 };
      this.pairs.set(key, arrow);
    }
    arrow.x = x / event.pointCount;
    arrow.y = y / event.pointCount;
    arrow.nx = event.normalX;
    arrow.ny = event.normalY;
    arrow.impulse = impulse;
    arrow.time = time;
  }

  /**
   * The arrow pairs still visible at `time`, with their opacity (1 new, 0 gone): at most
   * {@link MAX_SHOWN_PAIRS}, the strongest first when there are more. The list and its entries
   * are reused by the next call (drawn every frame, they make no garbage).
   */
  visible(time: number): readonly VisibleArrow[] {
    const result = this.shown;
    result.length = 0;
    for (const [key, arrow] of this.pairs) {
      const age = time - arrow.time;
      if (age > ARROW_LIFETIME || age < 0) {
        this.pairs.delete(key);
        continue;
      }
      const fade = (age - ARROW_HOLD) / (ARROW_LIFETIME - ARROW_HOLD);
      const opacity = fade <= 0 ? 1 : 1 - fade;
      const strength = arrow.impulse * opacity;
      // Kept sorted strongest first once full: an insertion into a list of MAX_SHOWN_PAIRS.
      let at = result.length;
      if (at === MAX_SHOWN_PAIRS) {
        if (strength <= strengthOf(result[at - 1]!)) continue;
        at--;
      } else {
        result.push((this.pool[at] ??= { arrow, opacity }));
      }
      const entry = result[at]!;
      while (at > 0 && strength > strengthOf(result[at - 1]!)) {
        result[at] = result[at - 1]!;
        at--;
      }
      result[at] = entry;
      entry.arrow = arrow;
      entry.opacity = opacity;
    }
    return result;
  }

  clear(): void {
    this.pairs.clear();
  }
}

function strengthOf(entry: VisibleArrow): number {
  return entry.arrow.impulse * entry.opacity;
}

/** One arrow pair of {@link CollisionArrows.visible}, with its opacity (1 new, 0 gone). */
export interface VisibleArrow {
  arrow: ReactionArrow;
  opacity: number;
}

/**
 * Arrow length (m) for an impulse (N s), or an average force (N) in `force` mode: grows with
 * the value, capped to stay readable.
 */
export function reactionArrowLength(value: number, measure: ArrowMeasure = 'impulse'): number {
  const perUnit = measure === 'impulse' ? 0.8 : 0.01;
  return Math.min(1.2, 0.15 + perUnit * value);
}
