import { describe, expect, it } from 'vitest';
import { ray } from './helpers.ts';
import { AABB } from '../../../src/geometry/aabb.ts';
import { makeBox } from '../../../src/geometry/polygon.ts';
import {
  computePolygonAABB,
  polygonContainsPoint,
  rayCastPolygon,
} from '../../../src/geometry/polygon-queries.ts';
import { RayHit } from '../../../src/geometry/ray.ts';
import { Transform } from '../../../src/math/transform.ts';

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
