import type { Body, CollisionEvent } from '@physical/engine';

/** One pair of equal and opposite arrows at a contact. */
export interface ReactionArrow {
  /** Contact point (m). */
  x: number;
  y: number;
  /** Unit normal from A to B. */
  nx: number;
  ny: number;
  /** Average contact force over the step (N). */
  force: number;
  /** Simulated time (s) it was recorded at. */
  time: number;
}

/** Seconds of simulated time an arrow pair stays fully visible, then fades over the same again. */
export const ARROW_HOLD = 0.5;
export const ARROW_LIFETIME = 1;
/** Impulses below this (N s) are resting contact noise, not drawn. */
const MIN_IMPULSE = 1e-4;

/**
 * The thesis's onCollision drawing: every collision leaves two arrows at the contact, the force
 * on A and the force on B, equal in size and opposite in direction. One pair per pair of bodies
 * (the newest), held for {@link ARROW_HOLD} and gone after {@link ARROW_LIFETIME}.
 */
export class CollisionArrows {
  private readonly pairs = new Map<string, ReactionArrow>();
  private readonly ids = new WeakMap<Body, number>();
  private nextId = 0;

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
    const key = `${this.idOf(event.bodyA)}:${this.idOf(event.bodyB)}`;
    this.pairs.set(key, {
      x: x / event.pointCount,
      y: y / event.pointCount,
      nx: event.normalX,
      ny: event.normalY,
      force: event.normalImpulse / dt,
      time,
    });
  }

  /** The arrow pairs still visible at `time`, with their opacity (1 new, 0 gone). */
  visible(time: number): { arrow: ReactionArrow; opacity: number }[] {
    const result: { arrow: ReactionArrow; opacity: number }[] = [];
    for (const [key, arrow] of this.pairs) {
      const age = time - arrow.time;
      if (age > ARROW_LIFETIME || age < 0) {
        this.pairs.delete(key);
        continue;
      }
      const fade = (age - ARROW_HOLD) / (ARROW_LIFETIME - ARROW_HOLD);
      result.push({ arrow, opacity: fade <= 0 ? 1 : 1 - fade });
    }
    return result;
  }

  clear(): void {
    this.pairs.clear();
  }
}

/** Arrow length (m) for a contact force (N): grows with the force, capped to stay readable. */
export function reactionArrowLength(force: number): number {
  return Math.min(1.2, 0.15 + 0.04 * force);
}
