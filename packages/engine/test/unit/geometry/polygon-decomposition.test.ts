import { describe, expect, it } from 'vitest';
import { catchError } from './helpers.ts';
import { MAX_POLYGON_VERTICES } from '../../../src/core/constants.ts';
import { MassData } from '../../../src/geometry/mass-data.ts';
import type { Polygon } from '../../../src/geometry/polygon.ts';
import { computePolygonMass } from '../../../src/geometry/polygon-mass.ts';
import { makePolygonParts } from '../../../src/geometry/polygon-decomposition.ts';

function points(...coordinates: number[]): { x: number; y: number }[] {
  const list: { x: number; y: number }[] = [];
  for (let i = 0; i < coordinates.length; i += 2) {
    list.push({ x: coordinates[i]!, y: coordinates[i + 1]! });
  }
  return list;
}

/** Shoelace area of an outline (either winding gives |area|). */
function outlineArea(list: { x: number; y: number }[]): number {
  let sum = 0;
  for (let i = 0; i < list.length; i++) {
    const a = list[i]!;
    const b = list[(i + 1) % list.length]!;
    sum += a.x * b.y - a.y * b.x;
  }
  return Math.abs(sum / 2);
}

function isConvex(part: Polygon): boolean {
  for (let i = 0; i < part.count; i++) {
    const j = (i + 1) % part.count;
    const k = (i + 2) % part.count;
    const v = part.vertices;
    const turn =
      (v[2 * j]! - v[2 * i]!) * (v[2 * k + 1]! - v[2 * j + 1]!) -
      (v[2 * j + 1]! - v[2 * i + 1]!) * (v[2 * k]! - v[2 * j]!);
    if (turn <= 0) return false;
  }
  return true;
}

function totalArea(parts: Polygon[]): number {
  return parts.reduce((sum, part) => sum + computePolygonMass(part, 1, new MassData()).mass, 0);
}

describe('makePolygonParts', () => {
  it('keeps a convex outline of up to 8 corners as one part, rounding included', () => {
    const parts = makePolygonParts(points(0, 0, 1, 0, 1, 1, 0, 1), 0.1, 's');
    expect(parts.length).toBe(1);
    expect(parts[0]!.radius).toBe(0.1);
  });

  it('splits an L into two convex parts that tile it', () => {
    const l = points(0, 0, 2, 0, 2, 1, 1, 1, 1, 3, 0, 3);
    const parts = makePolygonParts(l, 0, 's');
    expect(parts.length).toBe(2);
    expect(parts.every(isConvex)).toBe(true);
    expect(totalArea(parts)).toBeCloseTo(outlineArea(l), 12);
  });

  it('splits either winding the same way in area', () => {
    const u = points(0, 0, 3, 0, 3, 2, 2, 2, 2, 1, 1, 1, 1, 2, 0, 2);
    const reversed = u.slice().reverse();
    expect(totalArea(makePolygonParts(u, 0, 's'))).toBeCloseTo(outlineArea(u), 12);
    expect(totalArea(makePolygonParts(reversed, 0, 's'))).toBeCloseTo(outlineArea(u), 12);
  });

  it('splits a convex outline of more than 8 corners into parts of at most 8', () => {
    const ring: { x: number; y: number }[] = [];
    for (let i = 0; i < 40; i++) {
      const angle = (2 * Math.PI * i) / 40;
      ring.push({ x: Math.cos(angle), y: Math.sin(angle) });
    }
    const parts = makePolygonParts(ring, 0, 's');
    expect(parts.every((part) => part.count <= MAX_POLYGON_VERTICES && isConvex(part))).toBe(true);
    expect(parts.length).toBeLessThanOrEqual(8);
    expect(totalArea(parts)).toBeCloseTo(outlineArea(ring), 12);
  });

  it('splits a star (many reflex corners) into convex parts tiling it', () => {
    const star: { x: number; y: number }[] = [];
    for (let i = 0; i < 24; i++) {
      const angle = (2 * Math.PI * i) / 24;
      const r = i % 2 === 0 ? 2 : 0.7;
      star.push({ x: r * Math.cos(angle), y: r * Math.sin(angle) });
    }
    const parts = makePolygonParts(star, 0, 's');
    expect(parts.every(isConvex)).toBe(true);
    expect(totalArea(parts)).toBeCloseTo(outlineArea(star), 12);
  });

  it('splits a comb of 126 teeth (254 points)', () => {
    // A base, then back along the teeth.
    const outline = [
      { x: 0, y: -1 },
      { x: 126, y: -1 },
    ];
    for (let i = 125; i >= 0; i--) outline.push({ x: i + 1, y: 0 }, { x: i + 0.5, y: 2 });
    expect(outline.length).toBe(254);
    const parts = makePolygonParts(outline, 0, 's');
    expect(parts.every(isConvex)).toBe(true);
    expect(totalArea(parts)).toBeCloseTo(outlineArea(outline), 9);
  });

  it('rejects what is not a simple polygon, naming the field', () => {
    const bowtie = catchError(() => makePolygonParts(points(0, 0, 2, 2, 2, 0, 0, 2), 0, 's'));
    expect(bowtie.field).toBe('s.vertices');
    expect(bowtie.message).toMatch(/self-intersecting/);
    // A figure eight that touches itself at one repeated point.
    const pinched = catchError(() =>
      makePolygonParts(points(0, 0, 1, 1, 2, 0, 2, 2, 1, 1, 0, 2), 0, 's'),
    );
    expect(pinched.field).toBe('s.vertices');
    expect(pinched.message).toMatch(/same point/);
    expect(catchError(() => makePolygonParts(points(0, 0, 1, 1, 2, 2), 0, 's')).message).toMatch(
      /one line/,
    );
    const tooMany = Array.from({ length: 257 }, (_, i) => ({ x: Math.cos(i), y: Math.sin(i) }));
    expect(catchError(() => makePolygonParts(tooMany, 0, 's')).message).toMatch(/at most 256/);
  });

  it('refuses to round an outline it splits', () => {
    const l = points(0, 0, 2, 0, 2, 1, 1, 1, 1, 3, 0, 3);
    const error = catchError(() => makePolygonParts(l, 0.1, 'shapes[0]'));
    expect(error.field).toBe('shapes[0].radius');
    expect(error.message).toMatch(/concave/);
  });
});
