import { describe, expect, it } from 'vitest';
import { catchError, ray } from './helpers.ts';
import { AABB } from '../../../src/geometry/aabb.ts';
import { RayHit } from '../../../src/geometry/ray.ts';
import { computeSegmentAABB, makeSegment, rayCastSegment } from '../../../src/geometry/segment.ts';
import { Transform } from '../../../src/math/transform.ts';

describe('makeSegment', () => {
  it('builds a segment and keeps its sidedness', () => {
    expect(makeSegment(0, 0, 2, 1, true, 'walls[0]')).toEqual({
      kind: 'segment',
      x1: 0,
      y1: 0,
      x2: 2,
      y2: 1,
      oneSided: true,
    });
    expect(makeSegment(0, 0, 2, 1, false, 'w').oneSided).toBe(false);
  });

  it('rejects coincident end points, saying they must differ', () => {
    const error = catchError(() => makeSegment(1, 1, 1.001, 1, false, 'walls[3]'));
    expect(error.field).toBe('walls[3]');
    expect(error.message).toMatch(/^walls\[3\]: the wall's two points must differ/);
  });

  it('rejects non-finite coordinates naming each one', () => {
    expect(catchError(() => makeSegment(Number.NaN, 0, 1, 0, false, 'w')).field).toBe('w.x1');
    expect(catchError(() => makeSegment(0, Infinity, 1, 0, false, 'w')).field).toBe('w.y1');
    expect(catchError(() => makeSegment(0, 0, -Infinity, 0, false, 'w')).field).toBe('w.x2');
    expect(catchError(() => makeSegment(0, 0, 1, Number.NaN, false, 'w')).field).toBe('w.y2');
  });
});

describe('computeSegmentAABB', () => {
  it('bounds the rotated end points', () => {
    const segment = makeSegment(-1, 0, 1, 0, false, 'w');
    const aabb = computeSegmentAABB(segment, new Transform().set(3, 4, Math.PI / 4), new AABB());
    const h = Math.SQRT1_2;
    expect(aabb.minX).toBeCloseTo(3 - h, 12);
    expect(aabb.maxX).toBeCloseTo(3 + h, 12);
    expect(aabb.minY).toBeCloseTo(4 - h, 12);
    expect(aabb.maxY).toBeCloseTo(4 + h, 12);
  });
});

describe('rayCastSegment', () => {
  const segment = makeSegment(-1, 0, 1, 0, true, 'w');
  const identity = new Transform();

  it('hits from either side with the normal facing the origin', () => {
    const hit = new RayHit();
    expect(rayCastSegment(segment, identity, ray(0.5, 2, 0, -4), hit)).toBe(true);
    expect(hit.fraction).toBeCloseTo(0.5, 14);
    expect(hit.x).toBeCloseTo(0.5, 14);
    expect(hit.y).toBeCloseTo(0, 14);
    expect(hit.normalX).toBeCloseTo(0, 14);
    expect(hit.normalY).toBeCloseTo(1, 14);
    expect(rayCastSegment(segment, identity, ray(0.5, -1, 0, 4), hit)).toBe(true);
    expect(hit.fraction).toBeCloseTo(0.25, 14);
    expect(hit.normalY).toBeCloseTo(-1, 14);
  });

  it('hits a rotated, translated segment at the analytic point', () => {
    const hit = new RayHit();
    const xf = new Transform().set(5, 5, Math.PI / 2);
    // The segment now runs from (5, 4) to (5, 6).
    expect(rayCastSegment(segment, xf, ray(0, 5.5, 10, 0), hit)).toBe(true);
    expect(hit.fraction).toBeCloseTo(0.5, 12);
    expect(hit.y).toBeCloseTo(5.5, 12);
    expect(hit.normalX).toBeCloseTo(-1, 12);
    expect(hit.normalY).toBeCloseTo(0, 12);
  });

  it('misses beyond the ends, short of the line, and parallel to it', () => {
    const hit = new RayHit();
    expect(rayCastSegment(segment, identity, ray(1.01, 2, 0, -4), hit)).toBe(false);
    expect(rayCastSegment(segment, identity, ray(0, 2, 0, -4, 0.49), hit)).toBe(false);
    expect(rayCastSegment(segment, identity, ray(-5, 0, 10, 0), hit)).toBe(false);
    expect(rayCastSegment(segment, identity, ray(0, 2, 0, 4), hit)).toBe(false);
  });
});
