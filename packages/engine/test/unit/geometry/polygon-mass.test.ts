import { describe, expect, it } from 'vitest';
import { expectRelative, points } from './helpers.ts';
import { MassData } from '../../../src/geometry/mass-data.ts';
import { makeBox, makePolygon } from '../../../src/geometry/polygon.ts';
import { computePolygonMass } from '../../../src/geometry/polygon-mass.ts';

describe('computePolygonMass', () => {
  it('matches a box: m = rho w h, I = m (w^2 + h^2) / 12 about the centre', () => {
    const box = makeBox(1.5, 0.25, 7, -3, 0.3, 0, 's');
    const mass = computePolygonMass(box, 4, new MassData());
    const w = 3;
    const h = 0.5;
    expectRelative(mass.mass, 4 * w * h);
    expectRelative(mass.rotationalInertia, (mass.mass * (w * w + h * h)) / 12);
    expect(mass.centerX).toBeCloseTo(7, 12);
    expect(mass.centerY).toBeCloseTo(-3, 12);
  });

  it('matches a scalene triangle: centroid at the vertex mean, I = m (a^2 + b^2 + c^2) / 36', () => {
    const triangle = makePolygon(points(1, 1, 5, 2, 2, 4), 0, 's');
    const mass = computePolygonMass(triangle, 0.5, new MassData());
    const area = 0.5 * Math.abs((5 - 1) * (4 - 1) - (2 - 1) * (2 - 1));
    expectRelative(mass.mass, 0.5 * area);
    expectRelative(mass.centerX, 8 / 3);
    expectRelative(mass.centerY, 7 / 3);
    const sides =
      (5 - 1) ** 2 + (2 - 1) ** 2 + (2 - 5) ** 2 + (4 - 2) ** 2 + (1 - 2) ** 2 + (1 - 4) ** 2;
    expectRelative(mass.rotationalInertia, (mass.mass * sides) / 36);
  });

  it('matches a regular hexagon: A = 3 sqrt(3) R^2 / 2, I = 5 m R^2 / 12', () => {
    const R = 0.8;
    const hexagon: { x: number; y: number }[] = [];
    for (let i = 0; i < 6; i++) {
      hexagon.push({
        x: 10 + R * Math.cos((i * Math.PI) / 3),
        y: -4 + R * Math.sin((i * Math.PI) / 3),
      });
    }
    const mass = computePolygonMass(makePolygon(hexagon, 0, 's'), 2, new MassData());
    expectRelative(mass.mass, 2 * ((3 * Math.sqrt(3)) / 2) * R * R);
    expectRelative(mass.rotationalInertia, (5 * mass.mass * R * R) / 12);
    expectRelative(mass.centerX, 10);
    expectRelative(mass.centerY, -4);
  });

  it('is exact for a rounded box: A + P r + pi r^2 and the pieces inertia', () => {
    const a = 1.2;
    const b = 0.4;
    const r = 0.15;
    const mass = computePolygonMass(makeBox(a, b, 0, 0, 0, r, 's'), 3, new MassData());
    const area = 4 * a * b + 2 * (2 * a + 2 * b) * r + Math.PI * r * r;
    expectRelative(mass.mass, 3 * area);
    // Core, four edge slabs, four quarter discs, each about the box centre.
    const rectangle = (w: number, h: number, cx: number, cy: number): number =>
      (w * h * (w * w + h * h)) / 12 + w * h * (cx * cx + cy * cy);
    const quarter =
      (Math.PI * r ** 4) / 8 +
      2 * ((a * r ** 3) / 3 + (b * r ** 3) / 3) +
      ((Math.PI * r * r) / 4) * (a * a + b * b);
    const polar =
      rectangle(2 * a, 2 * b, 0, 0) +
      2 * rectangle(2 * a, r, 0, b + r / 2) +
      2 * rectangle(r, 2 * b, a + r / 2, 0) +
      4 * quarter;
    expectRelative(mass.rotationalInertia, 3 * polar);
    expect(Math.abs(mass.centerX)).toBeLessThan(1e-12);
    expect(Math.abs(mass.centerY)).toBeLessThan(1e-12);
  });

  it('gives a rounded polygon the same inertia wherever it sits and however it turns', () => {
    const here = computePolygonMass(makeBox(0.7, 0.3, 0, 0, 0, 0.1, 's'), 1, new MassData());
    const there = computePolygonMass(makeBox(0.7, 0.3, 40, -25, 1.1, 0.1, 's'), 1, new MassData());
    expectRelative(there.mass, here.mass);
    expectRelative(there.rotationalInertia, here.rotationalInertia, 1e-10);
    expect(there.centerX).toBeCloseTo(40, 10);
    expect(there.centerY).toBeCloseTo(-25, 10);
  });

  it('moves the centre of a rounded triangle towards the rounding, not only the core', () => {
    const triangle = makePolygon(points(0, 0, 3, 0, 0, 3), 0.5, 's');
    const mass = computePolygonMass(triangle, 1, new MassData());
    const perimeter = 6 + 3 * Math.SQRT2;
    expectRelative(mass.mass, 4.5 + perimeter * 0.5 + Math.PI * 0.25);
    // The hypotenuse is the longest edge, so its slab pulls the centre towards (1.5, 1.5).
    expect(mass.centerX).toBeGreaterThan(1);
    expect(mass.centerX).toBeCloseTo(mass.centerY, 12);
  });
});
