import { describe, expect, it } from 'vitest';
import { PointerVelocity, VELOCITY_WINDOW_MS } from '../../src/index.ts';

describe('PointerVelocity', () => {
  it('measures a steady fling over the last window, ignoring older moves', () => {
    const tracker = new PointerVelocity();
    // Slowly for 200 ms, then 600 px/s to the right and 300 px/s down.
    for (let t = 0; t <= 200; t += 10) tracker.add(t, t * 0.01, 0);
    for (let t = 210; t <= 400; t += 10) tracker.add(t, 2 + (t - 200) * 0.6, (t - 200) * 0.3);
    const velocity = tracker.velocity(400, { x: 0, y: 0 });
    expect(velocity.x).toBeCloseTo(600, 9);
    expect(velocity.y).toBeCloseTo(300, 9);
  });

  it('gives 0 when the pointer stopped before the release, or moved once', () => {
    const tracker = new PointerVelocity();
    tracker.add(0, 0, 0);
    expect(tracker.velocity(0, { x: 1, y: 1 })).toEqual({ x: 0, y: 0 });
    tracker.add(10, 50, 0);
    expect(tracker.velocity(10 + VELOCITY_WINDOW_MS + 1, { x: 1, y: 1 })).toEqual({ x: 0, y: 0 });
    tracker.reset();
    expect(tracker.velocity(0, { x: 1, y: 1 })).toEqual({ x: 0, y: 0 });
  });
});
