import { describe, expect, it } from 'vitest';
import { World, particle, type CollisionEvent } from '@physical/engine';
import {
  ARROW_HOLD,
  ARROW_LIFETIME,
  CollisionArrows,
  MAX_SHOWN_PAIRS,
} from '../src/screens/reactions/collision-arrows.ts';

// A crowd's collisions: the arrows drawn are the strongest MAX_SHOWN_PAIRS pairs, strongest
// first; a few collisions all show.

const world = new World();
const bodies = Array.from({ length: 80 }, (_, i) =>
  world.add(particle({ position: { x: 2 * i, y: 0 }, radius: 0.5 })),
);

/** A collision of body `a` with body `b` of impulse `impulse` (N s). */
function collision(a: number, b: number, impulse: number): CollisionEvent {
  const bodyA = bodies[a]!;
  const bodyB = bodies[b]!;
  return {
    bodyA,
    bodyB,
    shapeA: bodyA.shapes[0]!,
    shapeB: bodyB.shapes[0]!,
    normalX: 1,
    normalY: 0,
    pointCount: 1,
    points: [{ x: a, y: 0, separation: 0, normalImpulse: impulse, tangentImpulse: 0 }],
    normalImpulse: impulse,
    tangentImpulse: 0,
    approachSpeed: 1,
  } as unknown as CollisionEvent;
}

describe('collision arrows in a crowd', () => {
  it('shows every pair of a few collisions', () => {
    const arrows = new CollisionArrows();
    for (let i = 0; i < 5; i++) arrows.record(collision(i, i + 1, 0.1 * (i + 1)), 1 / 60, 0);
    expect(arrows.visible(0).map(({ arrow }) => arrow.impulse)).toHaveLength(5);
  });

  it(`shows the ${MAX_SHOWN_PAIRS} strongest pairs, strongest first, of more`, () => {
    const arrows = new CollisionArrows();
    // 79 pairs with impulses in a scrambled order: 0.01 ... 0.79 N s.
    const impulses = Array.from({ length: 79 }, (_, i) => ((i * 37) % 79) + 1);
    impulses.forEach((k, i) => arrows.record(collision(i, i + 1, k / 100), 1 / 60, 0));
    const shown = arrows.visible(0).map(({ arrow }) => arrow.impulse);
    const expected = [...impulses]
      .sort((a, b) => b - a)
      .slice(0, MAX_SHOWN_PAIRS)
      .map((k) => k / 100);
    expect(shown).toEqual(expected);
  });

  it('ranks a fading pair by what it still shows: impulse times opacity', () => {
    const arrows = new CollisionArrows();
    // An old strong collision, now at opacity 0.2 (0.2 * 1 = 0.2 N s shown), and a crowd of new
    // 0.5 N s ones that fill the list.
    arrows.record(collision(0, 1, 1), 1 / 60, 0);
    const now = ARROW_HOLD + 0.8 * (ARROW_LIFETIME - ARROW_HOLD);
    for (let i = 0; i < MAX_SHOWN_PAIRS; i++) {
      arrows.record(collision(i + 2, i + 3, 0.5), 1 / 60, now);
    }
    const shown = arrows.visible(now);
    expect(shown).toHaveLength(MAX_SHOWN_PAIRS);
    expect(shown.every(({ arrow }) => arrow.impulse === 0.5)).toBe(true);
    // With room left, the fading one shows, at its opacity.
    const fewer = new CollisionArrows();
    fewer.record(collision(0, 1, 1), 1 / 60, 0);
    const [fading] = fewer.visible(now);
    expect(fading!.opacity).toBeCloseTo(0.2, 12);
  });

  it('reuses its list: the same array, frame after frame', () => {
    const arrows = new CollisionArrows();
    for (let i = 0; i < 60; i++) arrows.record(collision(i, i + 1, 1 + i), 1 / 60, 0);
    const first = arrows.visible(0);
    const entries = new Set(first);
    const second = arrows.visible(0.1);
    expect(second).toBe(first);
    expect(second.every((entry) => entries.has(entry))).toBe(true);
  });
});
