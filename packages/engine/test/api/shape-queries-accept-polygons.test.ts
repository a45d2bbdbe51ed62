import { describe, expect, it } from 'vitest';
import { World, box, wall } from '@physical/engine';

// Finding 3: the shape queries take every shape a body takes, polygons (convex and concave) too.

function world(): World {
  const w = new World({ gravity: { x: 0, y: 0 } });
  w.add(wall({ from: { x: 5, y: -5 }, to: { x: 5, y: 5 } }));
  w.add(box({ position: { x: 0, y: 3 }, width: 1, height: 1 }));
  return w;
}

const triangle = {
  type: 'polygon' as const,
  vertices: [
    { x: -0.5, y: -0.5 },
    { x: 0.5, y: 0 },
    { x: -0.5, y: 0.5 },
  ],
};
// An L: concave, split into convex parts; its arm reaches 1.5 m right of the origin.
const ell = {
  type: 'polygon' as const,
  vertices: [
    { x: -0.5, y: -0.5 },
    { x: 1.5, y: -0.5 },
    { x: 1.5, y: 0 },
    { x: 0, y: 0 },
    { x: 0, y: 1.5 },
    { x: -0.5, y: 1.5 },
  ],
};

describe('shape queries accept polygons', () => {
  it('shapeCast sweeps a convex polygon to the wall', () => {
    const hit = world().shapeCast(triangle, { position: { x: 0, y: 0 } }, { x: 10, y: 0 });
    expect(hit).not.toBeNull();
    // The tip at x = 0.5 reaches the wall at x = 5 after 4.5 m of 10, stopping within 0.005 m.
    expect(hit!.fraction).toBeGreaterThan(0.44);
    expect(hit!.fraction).toBeLessThanOrEqual(0.45);
    expect(hit!.normal.x).toBeCloseTo(-1, 6);
  });

  it('shapeCast sweeps a concave polygon by its farthest part', () => {
    const hit = world().shapeCast(ell, { position: { x: 0, y: 0 } }, { x: 10, y: 0 });
    expect(hit).not.toBeNull();
    // The arm's tip at x = 1.5 reaches x = 5 after 3.5 m of 10.
    expect(hit!.fraction).toBeGreaterThan(0.34);
    expect(hit!.fraction).toBeLessThanOrEqual(0.35);
  });

  it('overlapShape finds the bodies a polygon overlaps, each part counted', () => {
    const w = world();
    expect(w.overlapShape(triangle, { position: { x: 0, y: 2.6 } }).length).toBe(1);
    expect(w.overlapShape(triangle, { position: { x: 0, y: 1 } }).length).toBe(0);
    // Only the L's vertical arm reaches down to the box at y = 2.5 .. 3.5.
    expect(w.overlapShape(ell, { position: { x: 0, y: 1.2 } }).length).toBe(1);
    expect(w.overlapShape(ell, { position: { x: 1.2, y: 1.2 } }).length).toBe(0);
  });
});
