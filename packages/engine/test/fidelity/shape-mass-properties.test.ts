import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, capsule, polygon } from '@physical/engine';

// Mass properties of the shapes beyond circles and convex polygons, against closed forms derived
// independently of the engine's formulas: a concave L (two rectangles, parallel-axis theorem), a
// capsule (numerical integration over its outline), a rounded box (core, side strips, quarter
// discs). All within 1e-9 relative.

const TOLERANCE = 1e-9;

interface Part {
  area: number;
  x: number;
  y: number;
  /** Polar second moment of area about the part's own centroid (m^4). */
  polar: number;
}

/** Area, centroid and polar moment about the centroid of the union of disjoint parts. */
function combine(parts: Part[]): { area: number; x: number; y: number; polar: number } {
  const area = parts.reduce((sum, p) => sum + p.area, 0);
  const x = parts.reduce((sum, p) => sum + p.area * p.x, 0) / area;
  const y = parts.reduce((sum, p) => sum + p.area * p.y, 0) / area;
  const polar = parts.reduce(
    (sum, p) => sum + p.polar + p.area * ((p.x - x) ** 2 + (p.y - y) ** 2),
    0,
  );
  return { area, x, y, polar };
}

function rectangle(minX: number, minY: number, maxX: number, maxY: number): Part {
  const w = maxX - minX;
  const h = maxY - minY;
  return {
    area: w * h,
    x: (minX + maxX) / 2,
    y: (minY + maxY) / 2,
    polar: (w * h * (w * w + h * h)) / 12,
  };
}

function relativeError(measured: number, expected: number): number {
  return Math.abs(measured - expected) / Math.abs(expected);
}

describe('mass properties of concave, capsule and rounded shapes', () => {
  it('a concave L polygon has the mass, centre and inertia of its two rectangles', () => {
    const density = 2.5;
    // The L: [0, 2] x [0, 1] plus [0, 1] x [1, 3], listed clockwise on screen, body at (5, 7).
    const l = polygon({
      position: { x: 5, y: 7 },
      vertices: [
        { x: 0, y: 0 },
        { x: 0, y: 3 },
        { x: 1, y: 3 },
        { x: 1, y: 1 },
        { x: 2, y: 1 },
        { x: 2, y: 0 },
      ],
      density,
    });
    const expected = combine([rectangle(0, 0, 2, 1), rectangle(0, 1, 1, 3)]);
    const errors = [
      relativeError(l.mass, density * expected.area),
      Math.abs(l.localCenterOfMass.x - expected.x),
      Math.abs(l.localCenterOfMass.y - expected.y),
      relativeError(l.inertia, density * expected.polar),
    ];
    const worst = Math.max(...errors);
    reportMeasured(
      'concave L polygon: mass, centre, inertia, worst relative error',
      worst,
      TOLERANCE,
    );
    expect(worst).toBeLessThan(TOLERANCE);
    expect(l.shapes.length).toBe(2);
    // The body origin stays where the user put it.
    expect([l.position.x, l.position.y]).toEqual([5, 7]);
    expect(l.centerOfMass.x).toBeCloseTo(5 + expected.x, 12);
  });

  it('a capsule has the mass and inertia of its outline, integrated numerically', () => {
    const length = 1.2;
    const r = 0.35;
    const density = 3;
    const body = capsule({ position: { x: 0, y: 0 }, length, radius: r, density, angle: 0.7 });
    // Slices across the axis: half height h(x) = r over the straight part; over each end
    // x = L/2 + r sin t, h = r cos t (smooth in t, so Simpson's rule converges fast).
    // Area = integral 2h dx; polar moment = integral (2h x^2 + 2h^3 / 3) dx.
    const n = 2000;
    let endArea = 0;
    let endPolar = 0;
    for (let i = 0; i <= n; i++) {
      const t = ((Math.PI / 2) * i) / n;
      const weight = i === 0 || i === n ? 1 : i % 2 === 1 ? 4 : 2;
      const x = length / 2 + r * Math.sin(t);
      const h = r * Math.cos(t);
      const dx = r * Math.cos(t);
      endArea += weight * 2 * h * dx;
      endPolar += weight * (2 * h * x * x + (2 * h ** 3) / 3) * dx;
    }
    const step = Math.PI / 2 / n / 3;
    const area = 2 * r * length + 2 * endArea * step;
    const polar = (2 * r * length * (length * length + 4 * r * r)) / 12 + 2 * endPolar * step;
    const worst = Math.max(
      relativeError(body.mass, density * area),
      relativeError(body.inertia, density * polar),
    );
    reportMeasured('capsule: mass and inertia, worst relative error', worst, TOLERANCE);
    expect(worst).toBeLessThan(TOLERANCE);
  });

  it('a rounded box has the mass and inertia of its core, side strips and quarter discs', () => {
    const w = 1.6;
    const h = 0.6;
    const r = 0.15;
    const density = 1.5;
    const body = box({ width: w, height: h, radius: r, density });
    const quarterOffset = (4 * r) / (3 * Math.PI);
    const quarterArea = (Math.PI * r * r) / 4;
    const parts: Part[] = [
      rectangle(-w / 2, -h / 2, w / 2, h / 2),
      rectangle(-w / 2, h / 2, w / 2, h / 2 + r),
      rectangle(-w / 2, -h / 2 - r, w / 2, -h / 2),
      rectangle(w / 2, -h / 2, w / 2 + r, h / 2),
      rectangle(-w / 2 - r, -h / 2, -w / 2, h / 2),
    ];
    for (const sx of [-1, 1]) {
      for (const sy of [-1, 1]) {
        // Polar moment of a quarter disc about its corner is pi r^4 / 8; move it to its centroid.
        parts.push({
          area: quarterArea,
          x: sx * (w / 2 + quarterOffset),
          y: sy * (h / 2 + quarterOffset),
          polar: (Math.PI * r ** 4) / 8 - quarterArea * 2 * quarterOffset ** 2,
        });
      }
    }
    const expected = combine(parts);
    const worst = Math.max(
      relativeError(body.mass, density * expected.area),
      relativeError(body.inertia, density * expected.polar),
    );
    reportMeasured('rounded box: mass and inertia, worst relative error', worst, TOLERANCE);
    expect(worst).toBeLessThan(TOLERANCE);
    // A world query sees the rounding: inside the corner arc, not in the cut-off corner.
    const world = new World();
    world.add(body);
    expect(world.bodyAt({ x: w / 2 + 0.05, y: h / 2 + 0.05 })).toBe(body);
    expect(world.bodyAt({ x: w / 2 + 0.14, y: h / 2 + 0.14 })).toBeNull();
  });
});
