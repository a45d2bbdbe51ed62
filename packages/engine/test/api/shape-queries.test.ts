import { describe, expect, it } from 'vitest';
import { PhysicalError, World, box, particle, wall } from '@physical/engine';

// Slop of the engine's time of impact: a cast stops within this of the surface (m).
const SLOP = 0.005;

function scene() {
  const world = new World({ gravity: { x: 0, y: 0 } });
  const near = world.add(particle({ position: { x: 3, y: 0 }, radius: 0.5 }));
  const far = world.add(box({ position: { x: 7, y: 0 }, width: 1, height: 4 }));
  const floor = world.add(wall({ from: { x: -10, y: 2 }, to: { x: 10, y: 2 } }));
  const zone = world.add(
    particle({ type: 'static', position: { x: 5, y: 0 }, radius: 1, sensor: true }),
  );
  return { world, near, far, floor, zone };
}

describe('rayCastAll', () => {
  it('returns every shape crossed, sorted by fraction, sensors left out', () => {
    const { world, near, far } = scene();
    const hits = world.rayCastAll({ x: 0, y: 0 }, { x: 10, y: 0 });
    expect(hits.map((h) => h.body)).toEqual([near, far]);
    expect(hits[0]!.fraction).toBeCloseTo(0.25, 12);
    expect(hits[1]!.fraction).toBeCloseTo(0.65, 12);
    expect(hits[1]!.normal).toEqual({ x: -1, y: 0 });
    // The first of all hits is the single rayCast's hit.
    expect(world.rayCast({ x: 0, y: 0 }, { x: 10, y: 0 })!.body).toBe(near);
    expect(world.rayCastAll({ x: 0, y: -5 }, { x: 10, y: -5 })).toEqual([]);
  });

  it('rejects bad points, naming them', () => {
    const { world } = scene();
    expect(() => world.rayCastAll({ x: Number.NaN, y: 0 }, { x: 1, y: 0 })).toThrow(/from\.x/);
    expect(() => world.rayCastAll({ x: 0, y: 0 }, null as never)).toThrow(/to/);
  });
});

describe('shapeCast', () => {
  it('finds the first hit of a swept circle, with point, normal and fraction', () => {
    const { world, near } = scene();
    const hit = world.shapeCast(
      { type: 'circle', radius: 0.25 },
      { position: { x: 0, y: 0 } },
      { x: 10, y: 0 },
    );
    expect(hit!.body).toBe(near);
    // Touches when the centres are 0.75 m apart: after 2.25 m of 10.
    expect(Math.abs(hit!.fraction * 10 - 2.25)).toBeLessThanOrEqual(SLOP);
    expect(hit!.normal.x).toBeCloseTo(-1, 9);
    expect(hit!.point.x).toBeCloseTo(2.5, 2);
  });

  it('sweeps a rotated box past the ball to the wall, and misses when nothing is in the way', () => {
    const { world, far, floor } = scene();
    const pass = world.shapeCast(
      { type: 'box', width: 0.4, height: 0.4 },
      { position: { x: 0, y: -1.2 }, angle: Math.PI / 4 },
      { x: 10, y: 0 },
    );
    expect(pass!.body).toBe(far);
    // The diamond's tip reaches 0.2 sqrt(2) m ahead of its centre; the box face is at x = 6.5.
    expect(Math.abs(pass!.fraction * 10 - (6.5 - 0.2 * Math.SQRT2))).toBeLessThanOrEqual(2 * SLOP);
    const down = world.shapeCast(
      { type: 'box', width: 0.4, height: 0.4 },
      { position: { x: -5, y: 0 } },
      { x: 0, y: 5 },
    );
    expect(down!.body).toBe(floor);
    expect(Math.abs(down!.fraction * 5 - 1.8)).toBeLessThanOrEqual(SLOP);
    expect(down!.normal.y).toBeCloseTo(-1, 9);
    expect(
      world.shapeCast(
        { type: 'circle', radius: 0.1 },
        { position: { x: 0, y: -5 } },
        { x: 9, y: 0 },
      ),
    ).toBeNull();
  });

  it('reports fraction 0 for a shape that starts overlapping', () => {
    const { world, near } = scene();
    const hit = world.shapeCast(
      { type: 'circle', radius: 0.2 },
      { position: { x: 3, y: 0 } },
      { x: 1, y: 0 },
    );
    expect(hit!.body).toBe(near);
    expect(hit!.fraction).toBe(0);
  });

  it('rejects bad shapes, poses and translations, naming the field', () => {
    const { world } = scene();
    const at = { position: { x: 0, y: 0 } };
    expect(() => world.shapeCast({ type: 'circle', radius: -1 }, at, { x: 1, y: 0 })).toThrow(
      /shape\.radius/,
    );
    expect(() =>
      world.shapeCast(
        { type: 'circle', radius: 1 },
        { position: { x: 0, y: Infinity } },
        { x: 1, y: 0 },
      ),
    ).toThrow(/pose\.position\.y/);
    expect(() =>
      world.shapeCast(
        { type: 'circle', radius: 1 },
        { position: { x: 0, y: 0 }, angle: Number.NaN },
        { x: 1, y: 0 },
      ),
    ).toThrow(/pose\.angle/);
    expect(() =>
      world.shapeCast({ type: 'circle', radius: 1 }, at, { x: 1, y: Number.NaN }),
    ).toThrow(/translation\.y/);
    expect(() => world.shapeCast({ type: 'triangle' } as never, at, { x: 1, y: 0 })).toThrow(
      PhysicalError,
    );
  });
});

describe('overlapShape', () => {
  it('returns the bodies a placed shape overlaps or touches, in world order, not sensors', () => {
    const { world, near, far, floor } = scene();
    expect(
      world.overlapShape({ type: 'box', width: 10, height: 1 }, { position: { x: 5, y: 0 } }),
    ).toEqual([near, far]);
    expect(
      world.overlapShape({ type: 'circle', radius: 0.3 }, { position: { x: 5, y: 0 } }),
    ).toEqual([]);
    // A 45-degree square whose corner reaches just past the floor.
    expect(
      world.overlapShape(
        { type: 'box', width: 1, height: 1 },
        { position: { x: 0, y: 1.3 }, angle: Math.PI / 4 },
      ),
    ).toEqual([floor]);
    expect(
      world.overlapShape({ type: 'box', width: 1, height: 1 }, { position: { x: 0, y: 1.2 } }),
    ).toEqual([]);
    expect(() =>
      world.overlapShape({ type: 'box', width: 0, height: 1 }, { position: { x: 0, y: 0 } }),
    ).toThrow(/shape\.width/);
  });
});
