import { describe, expect, it } from 'vitest';
import { World, particle } from '@physical/engine';
import { StepBlend } from '../src/screens/reactions/step-blend.ts';

describe('StepBlend: where the overlay draws the particles between two steps', () => {
  const STEP_MS = 1000 / 60;

  it('goes from where each particle was before the last step to where it is, as the step time passes', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const a = world.add(particle({ position: { x: 0, y: 0 }, radius: 0.1 }));
    const b = world.add(particle({ position: { x: 5, y: 1 }, radius: 0.1 }));
    a.linearVelocity = { x: 6, y: 0 };
    b.linearVelocity = { x: 0, y: -3 };
    const blend = new StepBlend();
    blend.before([a, b]);
    world.step(1 / 60);
    blend.after(1000);
    const out = { x: NaN, y: NaN };
    // Slow motion (0.25x): a step's time is four frames.
    const slowStep = STEP_MS / 0.25;
    for (const [now, share] of [
      [1000, 0],
      [1000 + slowStep / 4, 0.25],
      [1000 + slowStep / 2, 0.5],
      [1000 + slowStep, 1],
      [1000 + 3 * slowStep, 1],
    ] as const) {
      const fraction = blend.fraction(now, slowStep, false);
      expect(fraction).toBeCloseTo(share, 12);
      blend.at(a, 0, fraction, out);
      expect(out.x).toBeCloseTo(share * a.position.x, 12);
      expect(out.y).toBeCloseTo(0, 12);
      blend.at(b, 1, fraction, out);
      expect(out.x).toBeCloseTo(5, 12);
      expect(out.y).toBeCloseTo(1 + share * (b.position.y - 1), 12);
    }
    expect(a.position.x).toBeGreaterThan(0.09);
  });

  it('shows where a particle is while paused, and for one it did not see before the step', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    const a = world.add(particle({ position: { x: 1, y: 1 }, radius: 0.1 }));
    const blend = new StepBlend();
    blend.before([a]);
    world.step(1 / 60);
    blend.after(0);
    const out = { x: NaN, y: NaN };
    expect(blend.fraction(0, STEP_MS, true)).toBe(1);
    const later = world.add(particle({ position: { x: 3, y: 2 }, radius: 0.1 }));
    blend.at(later, 0, 0, out);
    expect(out).toEqual({ x: 3, y: 2 });
    blend.at(a, 5, 0, out);
    expect(out.y).toBe(a.position.y);
  });

  it('keeps room for a crowd larger than its first arrays', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const bodies = Array.from({ length: 150 }, (_, i) =>
      world.add(particle({ position: { x: i, y: -i }, radius: 0.1 })),
    );
    const blend = new StepBlend();
    blend.before(bodies);
    for (const body of bodies) body.position = { x: body.position.x + 1, y: body.position.y };
    blend.after(0);
    const out = { x: NaN, y: NaN };
    blend.at(bodies[149]!, 149, 0.5, out);
    expect(out).toEqual({ x: 149.5, y: -149 });
  });
});
