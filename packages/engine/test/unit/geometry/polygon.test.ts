import { describe, expect, it } from 'vitest';
import { catchError, ray } from './helpers.ts';
import { MAX_POLYGON_VERTICES } from '../../../src/core/constants.ts';
import { AABB } from '../../../src/geometry/aabb.ts';
import { MassData } from '../../../src/geometry/mass-data.ts';
import {
  computePolygonAABB,
  computePolygonMass,
  createEmptyPolygon,
  makeBox,
  makePolygon,
  polygonContainsPoint,
  rayCastPolygon,
  type Polygon,
} from '../../../src/geometry/polygon.ts';
import { RayHit } from '../../../src/geometry/ray.ts';
import { Transform } from '../../../src/math/transform.ts';

function points(...coordinates: number[]): { x: number; y: number }[] {
  const list: { x: number; y: number }[] = [];
  for (let i = 0; i < coordinates.length; i += 2) {
    list.push({ x: coordinates[i]!, y: coordinates[i + 1]! });
  }
  return list;
}

function vertexList(polygon: Polygon): number[][] {
  const list: number[][] = [];
  for (let i = 0; i < polygon.count; i++) {
    list.push([polygon.vertices[2 * i]!, polygon.vertices[2 * i + 1]!]);
  }
  return list;
}

function signedArea(polygon: Polygon): number {
  let sum = 0;
  for (let i = 0; i < polygon.count; i++) {
    const j = (i + 1) % polygon.count;
    sum +=
      polygon.vertices[2 * i]! * polygon.vertices[2 * j + 1]! -
      polygon.vertices[2 * j]! * polygon.vertices[2 * i + 1]!;
  }
  return sum / 2;
}

function expectRelative(actual: number, expected: number, tolerance = 1e-12): void {
  expect(Math.abs(actual - expected) / Math.abs(expected)).toBeLessThan(tolerance);
}

const square = points(0, 0, 2, 0, 2, 2, 0, 2);

describe('makePolygon', () => {
  it('stores counter-clockwise input as given, with outward unit normals and centroid', () => {
    const polygon = makePolygon(square, 0, 's');
    expect(polygon.count).toBe(4);
    expect(vertexList(polygon)).toEqual([
      [0, 0],
      [2, 0],
      [2, 2],
      [0, 2],
    ]);
    const normals = Array.from(polygon.normals.subarray(0, 8), (value) => value + 0);
    expect(normals).toEqual([0, -1, 1, 0, 0, 1, -1, 0]);
    expect(polygon.centroidX).toBeCloseTo(1, 14);
    expect(polygon.centroidY).toBeCloseTo(1, 14);
  });

  it('turns clockwise input counter-clockwise', () => {
    const polygon = makePolygon(points(0, 0, 0, 3, 3, 0), 0, 's');
    expect(signedArea(polygon)).toBeCloseTo(4.5, 12);
    expect(polygon.centroidX).toBeCloseTo(1, 14);
    expect(polygon.centroidY).toBeCloseTo(1, 14);
    for (let i = 0; i < 3; i++) {
      // Every other vertex lies behind each edge's outward normal.
      const nx = polygon.normals[2 * i]!;
      const ny = polygon.normals[2 * i + 1]!;
      expect(Math.hypot(nx, ny)).toBeCloseTo(1, 14);
      const k = (i + 2) % 3;
      const d =
        nx * (polygon.vertices[2 * k]! - polygon.vertices[2 * i]!) +
        ny * (polygon.vertices[2 * k + 1]! - polygon.vertices[2 * i + 1]!);
      expect(d).toBeLessThan(0);
    }
  });

  it('merges near-duplicate points, including a repeated closing point', () => {
    const polygon = makePolygon(points(0, 0, 2, 0, 2.001, 0.001, 2, 2, 0, 2, 0, 0), 0, 's');
    expect(polygon.count).toBe(4);
  });

  it('drops nearly straight vertices whichever way they bend', () => {
    expect(makePolygon(points(0, 0, 1, 0.0001, 2, 0, 2, 2, 0, 2), 0, 's').count).toBe(4);
    expect(makePolygon(points(0, 0, 1, -0.0001, 2, 0, 2, 2, 0, 2), 0, 's').count).toBe(4);
    expect(makePolygon(points(0, 0, 1, 0, 2, 0, 2, 2, 0, 2), 0, 's').count).toBe(4);
  });

  it('fills and returns the given polygon', () => {
    const out = createEmptyPolygon();
    expect(makePolygon(square, 0.1, 's', out)).toBe(out);
    expect(out.count).toBe(4);
    expect(out.radius).toBe(0.1);
  });

  it('rejects a non-finite coordinate naming the vertex', () => {
    const bad = points(0, 0, 1, 0, 1, 1);
    bad[2] = { x: Number.NaN, y: 1 };
    const error = catchError(() => makePolygon(bad, 0, 'shapes[1]'));
    expect(error.field).toBe('shapes[1].vertices[2].x');
    expect(error.message).toMatch(/finite number/);
    bad[2] = { x: 1, y: -Infinity };
    expect(catchError(() => makePolygon(bad, 0, 'shapes[1]')).field).toBe(
      'shapes[1].vertices[2].y',
    );
  });

  it('rejects a missing point and a non-list', () => {
    const sparse = [{ x: 0, y: 0 }, null, { x: 1, y: 1 }] as unknown as { x: number; y: number }[];
    expect(catchError(() => makePolygon(sparse, 0, 's')).field).toBe('s.vertices[1]');
    const error = catchError(() => makePolygon(null as unknown as [], 0, 's'));
    expect(error.field).toBe('s.vertices');
    expect(error.message).toMatch(/list of points/);
  });

  it('rejects a negative or non-finite radius', () => {
    expect(catchError(() => makePolygon(square, -0.1, 's')).field).toBe('s.radius');
    expect(catchError(() => makePolygon(square, Number.NaN, 's')).field).toBe('s.radius');
  });

  it('rejects fewer than three distinct points', () => {
    const error = catchError(() => makePolygon(points(0, 0, 1, 0, 1.001, 0), 0, 's'));
    expect(error.field).toBe('s.vertices');
    expect(error.message).toMatch(/needs at least 3 distinct points, got 2/);
    expect(catchError(() => makePolygon([], 0, 's')).message).toMatch(/got 0/);
  });

  it('rejects collinear points as having no area', () => {
    const error = catchError(() => makePolygon(points(0, 0, 1, 0.0001, 2, 0, 3, 0), 0, 's'));
    expect(error.field).toBe('s.vertices');
    expect(error.message).toMatch(/lie on one line/);
    expect(error.message).toMatch(/wall/);
  });

  it('rejects a self-intersecting outline, saying so', () => {
    const bowtie = catchError(() => makePolygon(points(0, 0, 2, 2, 2, 0, 0, 2), 0, 's'));
    expect(bowtie.field).toBe('s.vertices');
    expect(bowtie.message).toMatch(/self-intersecting/);
    const pentagram: { x: number; y: number }[] = [];
    for (let i = 0; i < 5; i++) {
      const angle = (4 * Math.PI * i) / 5;
      pentagram.push({ x: Math.cos(angle), y: Math.sin(angle) });
    }
    expect(catchError(() => makePolygon(pentagram, 0, 's')).message).toMatch(/self-intersecting/);
  });

  it('rejects a concave outline as one convex part, pointing to the polygon shape', () => {
    const arrow = points(0, 0, 2, 1, 0, 2, 0.5, 1);
    const error = catchError(() => makePolygon(arrow, 0, 'shapes[0]'));
    expect(error.field).toBe('shapes[0].vertices');
    expect(error.message).toMatch(/is concave at \(0.5, 1\)/);
    expect(error.message).toMatch(/splits concave outlines into convex parts/);
    // Same outline clockwise: still concave, never silently hulled.
    expect(catchError(() => makePolygon(arrow.slice().reverse(), 0, 's')).message).toMatch(
      /concave/,
    );
  });

  it('rejects more than MAX_POLYGON_VERTICES corners', () => {
    const ring: { x: number; y: number }[] = [];
    for (let i = 0; i < MAX_POLYGON_VERTICES + 1; i++) {
      const angle = (2 * Math.PI * i) / (MAX_POLYGON_VERTICES + 1);
      ring.push({ x: Math.cos(angle), y: Math.sin(angle) });
    }
    const error = catchError(() => makePolygon(ring, 0, 's'));
    expect(error.field).toBe('s.vertices');
    expect(error.message).toMatch(new RegExp(`at most ${MAX_POLYGON_VERTICES}`));
    expect(makePolygon(ring.slice(1), 0, 's').count).toBe(MAX_POLYGON_VERTICES);
  });
});

describe('makeBox', () => {
  it('places a rotated box around its centre', () => {
    const box = makeBox(2, 1, 3, 4, Math.PI / 2, 0, 's');
    expect(box.count).toBe(4);
    const corners = vertexList(box).map(([x, y]) => [
      Math.round(x! * 1e9) / 1e9,
      Math.round(y! * 1e9) / 1e9,
    ]);
    expect(corners).toEqual([
      [4, 2],
      [4, 6],
      [2, 6],
      [2, 2],
    ]);
    expect(box.normals[0]).toBeCloseTo(1, 14);
    expect(box.normals[1]).toBeCloseTo(0, 14);
    expect(box.centroidX).toBe(3);
    expect(box.centroidY).toBe(4);
    expect(signedArea(box)).toBeCloseTo(8, 12);
  });

  it('rejects non-positive half extents and bad numbers', () => {
    const error = catchError(() => makeBox(0, 1, 0, 0, 0, 0, 'shapes[4]'));
    expect(error.field).toBe('shapes[4].halfWidth');
    expect(error.message).toBe('shapes[4].halfWidth: must be greater than zero, got 0.');
    expect(catchError(() => makeBox(1, -2, 0, 0, 0, 0, 'b')).field).toBe('b.halfHeight');
    expect(catchError(() => makeBox(1, 1, Number.NaN, 0, 0, 0, 'b')).field).toBe('b.centerX');
    expect(catchError(() => makeBox(1, 1, 0, Infinity, 0, 0, 'b')).field).toBe('b.centerY');
    expect(catchError(() => makeBox(1, 1, 0, 0, Number.NaN, 0, 'b')).field).toBe('b.angle');
    expect(catchError(() => makeBox(1, 1, 0, 0, 0, -1, 'b')).field).toBe('b.radius');
  });
});

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

describe('computePolygonAABB', () => {
  it('bounds a box turned 45 degrees, radius included', () => {
    const box = makeBox(1, 1, 0, 0, 0, 0.1, 's');
    const aabb = computePolygonAABB(box, new Transform().set(5, -2, Math.PI / 4), new AABB());
    const reach = Math.SQRT2 + 0.1;
    expect(aabb.minX).toBeCloseTo(5 - reach, 12);
    expect(aabb.maxX).toBeCloseTo(5 + reach, 12);
    expect(aabb.minY).toBeCloseTo(-2 - reach, 12);
    expect(aabb.maxY).toBeCloseTo(-2 + reach, 12);
  });
});

describe('polygonContainsPoint', () => {
  const xf = new Transform().set(1, 1, Math.PI / 4);

  it('contains interior and boundary points of a placed box and excludes outside ones', () => {
    const box = makeBox(1, 1, 0, 0, 0, 0, 's');
    expect(polygonContainsPoint(box, xf, 1, 1)).toBe(true);
    expect(polygonContainsPoint(box, xf, 1 + Math.SQRT2 - 1e-9, 1)).toBe(true);
    expect(polygonContainsPoint(box, xf, 1 + Math.SQRT2 + 1e-6, 1)).toBe(false);
    expect(polygonContainsPoint(box, xf, 1.9, 1.9)).toBe(false);
  });

  it('follows the rounding at the corners of a rounded box', () => {
    const box = makeBox(1, 1, 0, 0, 0, 0.5, 's');
    const identity = new Transform();
    expect(polygonContainsPoint(box, identity, 1.4, 0)).toBe(true);
    expect(polygonContainsPoint(box, identity, 1.3, 1.3)).toBe(true);
    expect(polygonContainsPoint(box, identity, 1.4, 1.4)).toBe(false);
  });
});

describe('rayCastPolygon', () => {
  const box = makeBox(1, 1, 0, 0, 0, 0, 's');
  const identity = new Transform();

  it('hits a face at the analytic fraction with its normal', () => {
    const hit = new RayHit();
    expect(rayCastPolygon(box, identity, ray(-5, 0.3, 10, 0), hit)).toBe(true);
    expect(hit.fraction).toBeCloseTo(0.4, 14);
    expect(hit.x).toBeCloseTo(-1, 14);
    expect(hit.y).toBeCloseTo(0.3, 14);
    expect(hit.normalX).toBeCloseTo(-1, 14);
    expect(hit.normalY).toBeCloseTo(0, 14);
  });

  it('hits a box turned 45 degrees on the face the ray meets', () => {
    const hit = new RayHit();
    const xf = new Transform().set(0, 0, Math.PI / 4);
    expect(rayCastPolygon(box, xf, ray(-5, 0.1, 10, 0), hit)).toBe(true);
    expect(hit.x).toBeCloseTo(-Math.SQRT2 + 0.1, 12);
    expect(hit.fraction).toBeCloseTo((5 - Math.SQRT2 + 0.1) / 10, 12);
    expect(hit.normalX).toBeCloseTo(-Math.SQRT1_2, 12);
    expect(hit.normalY).toBeCloseTo(Math.SQRT1_2, 12);
  });

  it('misses beside, short of, from inside, and parallel outside', () => {
    const hit = new RayHit();
    expect(rayCastPolygon(box, identity, ray(-5, 1.1, 10, 0), hit)).toBe(false);
    expect(rayCastPolygon(box, identity, ray(-5, 0, 10, 0, 0.39), hit)).toBe(false);
    expect(rayCastPolygon(box, identity, ray(0, 0, 10, 0), hit)).toBe(false);
    expect(rayCastPolygon(box, identity, ray(-5, 0, -10, 0), hit)).toBe(false);
    expect(rayCastPolygon(box, identity, ray(-5, 2, 10, 0), hit)).toBe(false);
  });

  it('hits a rounded box on a pushed-out face and on a corner arc', () => {
    const rounded = makeBox(1, 1, 0, 0, 0, 0.5, 's');
    const hit = new RayHit();
    expect(rayCastPolygon(rounded, identity, ray(-5, 0.2, 10, 0), hit)).toBe(true);
    expect(hit.x).toBeCloseTo(-1.5, 12);
    expect(hit.normalX).toBeCloseTo(-1, 12);
    // At height 1.25 the ray meets the arc of the corner (-1, 1).
    expect(rayCastPolygon(rounded, identity, ray(-5, 1.25, 10, 0), hit)).toBe(true);
    const dx = -Math.sqrt(0.25 - 0.0625);
    expect(hit.x).toBeCloseTo(-1 + dx, 12);
    expect(hit.fraction).toBeCloseTo((5 - 1 + dx) / 10, 12);
    expect(hit.normalX).toBeCloseTo(dx / 0.5, 12);
    expect(hit.normalY).toBeCloseTo(0.5, 12);
    expect(rayCastPolygon(rounded, identity, ray(-5, 1.51, 10, 0), hit)).toBe(false);
    expect(rayCastPolygon(rounded, identity, ray(-1.4, 0, -10, 0), hit)).toBe(false);
    expect(rayCastPolygon(rounded, identity, ray(-1.4, 0, 10, 0), hit)).toBe(false);
  });
});

describe('createEmptyPolygon', () => {
  it('gives every polygon storage of its own, across slabs, with neighbours side by side', () => {
    // Polygons are cut from shared slabs (so a pass over many bodies reads their numbers in
    // order); no two may share a number.
    const polygons = Array.from({ length: 600 }, () => createEmptyPolygon());
    polygons.forEach((p, i) => {
      expect(p.vertices.length).toBe(2 * MAX_POLYGON_VERTICES);
      expect(p.normals.length).toBe(2 * MAX_POLYGON_VERTICES);
      p.vertices.fill(i);
      p.normals.fill(-i);
    });
    polygons.forEach((p, i) => {
      expect(p.vertices.every((v) => v === i)).toBe(true);
      expect(p.normals.every((v) => v === -i)).toBe(true);
    });
    let neighbours = 0;
    for (let i = 1; i < polygons.length; i++) {
      const a = polygons[i - 1]!;
      const b = polygons[i]!;
      if (b.vertices.buffer !== a.vertices.buffer) continue;
      expect(b.vertices.byteOffset).toBe(a.normals.byteOffset + a.normals.byteLength);
      neighbours++;
    }
    expect(neighbours).toBeGreaterThan(590);
  });
});
