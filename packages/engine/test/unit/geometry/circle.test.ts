import { describe, expect, it } from 'vitest';
import { catchError, ray } from './helpers.ts';
import { AABB } from '../../../src/geometry/aabb.ts';
import {
  circleContainsPoint,
  computeCircleAABB,
  computeCircleMass,
  makeCircle,
  rayCastCircle,
  type Circle,
} from '../../../src/geometry/circle.ts';
import { MassData } from '../../../src/geometry/mass-data.ts';
import { RayHit } from '../../../src/geometry/ray.ts';
import { Transform } from '../../../src/math/transform.ts';

describe('makeCircle', () => {
  it('builds a circle from valid numbers', () => {
    const circle = makeCircle(1, -2, 0.5, 'shapes[0]');
    expect(circle).toEqual({ kind: 'circle', centerX: 1, centerY: -2, radius: 0.5 });
  });

  it('rejects a negative radius naming the field', () => {
    const error = catchError(() => makeCircle(0, 0, -1, 'shapes[0]'));
    expect(error.field).toBe('shapes[0].radius');
    expect(error.message).toBe('shapes[0].radius: must be greater than zero, got -1.');
  });

  it('rejects a zero radius', () => {
    expect(catchError(() => makeCircle(0, 0, 0, 'c')).field).toBe('c.radius');
  });

  it('rejects a non-finite centre', () => {
    const x = catchError(() => makeCircle(Number.NaN, 0, 1, 'shapes[2]'));
    expect(x.field).toBe('shapes[2].centerX');
    expect(x.message).toMatch(/must be a finite number, got NaN/);
    const y = catchError(() => makeCircle(0, Infinity, 1, 'shapes[2]'));
    expect(y.field).toBe('shapes[2].centerY');
  });
});

describe('computeCircleMass', () => {
  it('matches pi r^2 density and m r^2 / 2 about the centre', () => {
    const circle = makeCircle(0.3, -0.7, 0.25, 's');
    const mass = computeCircleMass(circle, 2.5, new MassData());
    const expectedMass = 2.5 * Math.PI * 0.25 * 0.25;
    expect(Math.abs(mass.mass - expectedMass) / expectedMass).toBeLessThan(1e-12);
    const expectedInertia = (expectedMass * 0.25 * 0.25) / 2;
    expect(Math.abs(mass.rotationalInertia - expectedInertia) / expectedInertia).toBeLessThan(
      1e-12,
    );
    expect(mass.centerX).toBe(0.3);
    expect(mass.centerY).toBe(-0.7);
  });
});

describe('computeCircleAABB', () => {
  it('bounds the centre placed by a rotated transform', () => {
    const circle = makeCircle(1, 0, 0.5, 's');
    const aabb = computeCircleAABB(circle, new Transform().set(2, 3, Math.PI / 2), new AABB());
    expect(aabb.minX).toBeCloseTo(1.5, 12);
    expect(aabb.maxX).toBeCloseTo(2.5, 12);
    expect(aabb.minY).toBeCloseTo(3.5, 12);
    expect(aabb.maxY).toBeCloseTo(4.5, 12);
  });
});

describe('circleContainsPoint', () => {
  const circle: Circle = makeCircle(1, 0, 0.5, 's');
  const xf = new Transform().set(0, 0, Math.PI);

  it('contains points inside and on the boundary of the placed circle', () => {
    expect(circleContainsPoint(circle, xf, -1, 0)).toBe(true);
    expect(circleContainsPoint(circle, xf, -1, 0.5)).toBe(true);
  });

  it('excludes points outside', () => {
    expect(circleContainsPoint(circle, xf, 1, 0)).toBe(false);
    expect(circleContainsPoint(circle, xf, -1, 0.51)).toBe(false);
  });
});

describe('rayCastCircle', () => {
  const circle = makeCircle(0, 0, 1, 's');
  const identity = new Transform();

  it('hits head-on at the analytic fraction with the outward normal', () => {
    const hit = new RayHit();
    expect(rayCastCircle(circle, identity, ray(-5, 0, 10, 0), hit)).toBe(true);
    expect(hit.fraction).toBeCloseTo(0.4, 14);
    expect(hit.x).toBeCloseTo(-1, 14);
    expect(hit.y).toBeCloseTo(0, 14);
    expect(hit.normalX).toBeCloseTo(-1, 14);
    expect(hit.normalY).toBeCloseTo(0, 14);
  });

  it('hits off-centre where the chord says', () => {
    const hit = new RayHit();
    expect(rayCastCircle(circle, identity, ray(-5, 0.6, 10, 0), hit)).toBe(true);
    expect(hit.x).toBeCloseTo(-0.8, 12);
    expect(hit.fraction).toBeCloseTo(0.42, 12);
    expect(hit.normalX).toBeCloseTo(-0.8, 12);
    expect(hit.normalY).toBeCloseTo(0.6, 12);
  });

  it('hits a circle placed by a transform', () => {
    const hit = new RayHit();
    const xf = new Transform().set(10, 5, 1.2);
    const placed = makeCircle(0, 0, 2, 's');
    expect(rayCastCircle(placed, xf, ray(10, 0, 0, 10), hit)).toBe(true);
    expect(hit.fraction).toBeCloseTo(0.3, 12);
    expect(hit.normalY).toBeCloseTo(-1, 12);
  });

  it('misses beside, short of, behind, and from inside', () => {
    const hit = new RayHit();
    expect(rayCastCircle(circle, identity, ray(-5, 1.01, 10, 0), hit)).toBe(false);
    expect(rayCastCircle(circle, identity, ray(-5, 0, 10, 0, 0.39), hit)).toBe(false);
    expect(rayCastCircle(circle, identity, ray(-5, 0, -10, 0), hit)).toBe(false);
    expect(rayCastCircle(circle, identity, ray(0.2, 0, 10, 0), hit)).toBe(false);
    expect(rayCastCircle(circle, identity, ray(-5, 0, 0, 0), hit)).toBe(false);
  });
});
