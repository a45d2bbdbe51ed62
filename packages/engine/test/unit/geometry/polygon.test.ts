import { describe, expect, it } from 'vitest';
import { catchError, points } from './helpers.ts';
import { MAX_POLYGON_VERTICES } from '../../../src/core/constants.ts';
import {
  createEmptyPolygon,
  makeBox,
  makePolygon,
  type Polygon,
} from '../../../src/geometry/polygon.ts';

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
