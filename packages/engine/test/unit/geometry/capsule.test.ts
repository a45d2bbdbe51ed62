import { describe, expect, it } from 'vitest';
import { catchError, ray } from './helpers.ts';
import { AABB } from '../../../src/geometry/aabb.ts';
import {
  capsuleContainsPoint,
  computeCapsuleAABB,
  computeCapsuleMass,
  makeCapsule,
  rayCastCapsule,
} from '../../../src/geometry/capsule.ts';
import { MassData } from '../../../src/geometry/mass-data.ts';
import { makeBox } from '../../../src/geometry/polygon.ts';
import { computePolygonMass } from '../../../src/geometry/polygon-mass.ts';
import { RayHit } from '../../../src/geometry/ray.ts';
import { Transform } from '../../../src/math/transform.ts';

describe('makeCapsule', () => {
  it('keeps the centres and radius', () => {
    const capsule = makeCapsule(-1, 0, 1, 0, 0.25, 's');
    expect([capsule.kind, capsule.x1, capsule.y2, capsule.radius]).toEqual([
      'capsule',
      -1,
      0,
      0.25,
    ]);
  });

  it('names the bad field', () => {
    expect(catchError(() => makeCapsule(NaN, 0, 1, 0, 1, 's')).field).toBe('s.center1.x');
    expect(catchError(() => makeCapsule(0, 0, 1, Infinity, 1, 's')).field).toBe('s.center2.y');
    expect(catchError(() => makeCapsule(0, 0, 1, 0, 0, 's')).field).toBe('s.radius');
    expect(catchError(() => makeCapsule(0, 0, 1, 0, -1, 's')).field).toBe('s.radius');
    const same = catchError(() => makeCapsule(1, 1, 1, 1.001, 0.5, 'shapes[2]'));
    expect(same.field).toBe('shapes[2]');
    expect(same.message).toMatch(/circle/);
  });
});

describe('computeCapsuleMass', () => {
  it('matches a rectangle plus a disc in area, with the centre at the midpoint', () => {
    const L = 2;
    const r = 0.5;
    const mass = computeCapsuleMass(makeCapsule(1, 1, 1 + L, 1, r, 's'), 3, new MassData());
    expect(mass.mass).toBeCloseTo(3 * (2 * r * L + Math.PI * r * r), 12);
    expect(mass.centerX).toBeCloseTo(2, 14);
    expect(mass.centerY).toBeCloseTo(1, 14);
  });

  it('equals the exact rounded-polygon inertia of a thin rounded box with the same outline', () => {
    // A capsule is a box of half height h -> 0 rounded by r: the rounded-polygon formula, exact
    // for any h, converges to the capsule's as h shrinks (linearly in h).
    const L = 1.5;
    const r = 0.3;
    const capsule = computeCapsuleMass(makeCapsule(-L / 2, 0, L / 2, 0, r, 's'), 1, new MassData());
    const h = 1e-7;
    const rounded = computePolygonMass(makeBox(L / 2, h, 0, 0, 0, r, 'b'), 1, new MassData());
    expect(Math.abs(capsule.rotationalInertia - rounded.rotationalInertia)).toBeLessThan(1e-6);
    expect(Math.abs(capsule.mass - rounded.mass)).toBeLessThan(1e-6);
  });

  it('turns with the capsule: the inertia does not depend on its direction', () => {
    const a = computeCapsuleMass(makeCapsule(0, 0, 2, 0, 0.4, 's'), 1, new MassData());
    const b = computeCapsuleMass(
      makeCapsule(0, 0, Math.SQRT2, Math.SQRT2, 0.4, 's'),
      1,
      new MassData(),
    );
    expect(b.rotationalInertia).toBeCloseTo(a.rotationalInertia, 12);
  });
});

describe('capsule bounds and point test', () => {
  const capsule = makeCapsule(-1, 0, 1, 0, 0.5, 's');
  const turned = new Transform().set(10, 5, Math.PI / 2);

  it('bounds the capsule placed by the transform, radius included', () => {
    const box = computeCapsuleAABB(capsule, turned, new AABB());
    expect(box.minX).toBeCloseTo(9.5, 12);
    expect(box.maxX).toBeCloseTo(10.5, 12);
    expect(box.minY).toBeCloseTo(3.5, 12);
    expect(box.maxY).toBeCloseTo(6.5, 12);
  });

  it('contains points within the radius of the core, and not the corners of its box', () => {
    expect(capsuleContainsPoint(capsule, turned, 10, 6.49)).toBe(true);
    expect(capsuleContainsPoint(capsule, turned, 10.49, 5)).toBe(true);
    expect(capsuleContainsPoint(capsule, turned, 10.45, 6.45)).toBe(false);
    expect(capsuleContainsPoint(capsule, turned, 10.51, 5)).toBe(false);
  });
});

describe('rayCastCapsule', () => {
  const capsule = makeCapsule(-1, 0, 1, 0, 0.5, 's');
  const identity = new Transform();

  it('hits a side with its normal', () => {
    const hit = new RayHit();
    expect(rayCastCapsule(capsule, identity, ray(0.3, 3, 0, -5), hit)).toBe(true);
    expect(hit.fraction).toBeCloseTo(2.5 / 5, 12);
    expect(hit.x).toBeCloseTo(0.3, 14);
    expect(hit.y).toBeCloseTo(0.5, 14);
    expect(hit.normalX).toBeCloseTo(0, 14);
    expect(hit.normalY).toBeCloseTo(1, 14);
  });

  it('hits a rounded end where the circle is', () => {
    const hit = new RayHit();
    expect(rayCastCapsule(capsule, identity, ray(4, 0.3, -4, 0), hit)).toBe(true);
    // Circle around (1, 0) of radius 0.5 at height 0.3: x = 1 + 0.4.
    expect(hit.x).toBeCloseTo(1.4, 12);
    expect(hit.normalX).toBeCloseTo(0.8, 12);
    expect(hit.normalY).toBeCloseTo(0.6, 12);
  });

  it('misses past the ends, from inside, and beyond maxFraction', () => {
    const hit = new RayHit();
    expect(rayCastCapsule(capsule, identity, ray(1.55, 3, 0, -5), hit)).toBe(false);
    expect(rayCastCapsule(capsule, identity, ray(0, 0, 5, 0), hit)).toBe(false);
    expect(rayCastCapsule(capsule, identity, ray(0, 3, 0, -5, 0.4), hit)).toBe(false);
  });

  it('works in a turned and shifted frame', () => {
    const hit = new RayHit();
    const placed = new Transform().set(3, 3, Math.PI / 2);
    expect(rayCastCapsule(capsule, placed, ray(0, 3, 10, 0), hit)).toBe(true);
    expect(hit.x).toBeCloseTo(2.5, 12);
    expect(hit.normalX).toBeCloseTo(-1, 12);
  });
});
