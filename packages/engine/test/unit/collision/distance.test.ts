import { describe, expect, it } from 'vitest';
import {
  DistanceOutput,
  DistanceProxy,
  setProxyFromCapsule,
  setProxyFromCircle,
  setProxyFromPolygon,
  setProxyFromSegment,
  shapeDistance,
} from '../../../src/collision/distance.ts';
import { makeCapsule } from '../../../src/geometry/capsule.ts';
import { createEmptyPolygon } from '../../../src/geometry/polygon.ts';
import type { Polygon } from '../../../src/geometry/polygon.ts';
import { Transform } from '../../../src/math/transform.ts';
import { makeRandom } from './random-boxes.ts';

/** A convex polygon from counter-clockwise points (normals are not used by distance queries). */
function polygonFrom(points: readonly number[], radius = 0): Polygon {
  const polygon = createEmptyPolygon();
  polygon.count = points.length / 2;
  polygon.vertices.set(points);
  polygon.radius = radius;
  return polygon;
}

function box(halfWidth: number, halfHeight: number, radius = 0): Polygon {
  return polygonFrom(
    [
      -halfWidth,
      -halfHeight,
      halfWidth,
      -halfHeight,
      halfWidth,
      halfHeight,
      -halfWidth,
      halfHeight,
    ],
    radius,
  );
}

/** Distance between segments p1-p2 and q1-q2 (Ericson, Real-Time Collision Detection 5.1.9). */
function segmentSegmentDistance(
  p1x: number,
  p1y: number,
  p2x: number,
  p2y: number,
  q1x: number,
  q1y: number,
  q2x: number,
  q2y: number,
): number {
  const pointSegment = (px: number, py: number, ax: number, ay: number, bx: number, by: number) => {
    const ex = bx - ax;
    const ey = by - ay;
    const t = Math.min(1, Math.max(0, ((px - ax) * ex + (py - ay) * ey) / (ex * ex + ey * ey)));
    return Math.hypot(px - ax - t * ex, py - ay - t * ey);
  };
  return Math.min(
    pointSegment(p1x, p1y, q1x, q1y, q2x, q2y),
    pointSegment(p2x, p2y, q1x, q1y, q2x, q2y),
    pointSegment(q1x, q1y, p1x, p1y, p2x, p2y),
    pointSegment(q2x, q2y, p1x, p1y, p2x, p2y),
  );
}

function worldVertices(proxy: DistanceProxy, xf: Transform): number[] {
  const out: number[] = [];
  for (let i = 0; i < proxy.count; i++) {
    const x = proxy.vertices[2 * i]!;
    const y = proxy.vertices[2 * i + 1]!;
    out.push(xf.c * x - xf.s * y + xf.x, xf.s * x + xf.c * y + xf.y);
  }
  return out;
}

describe('shapeDistance', () => {
  const output = new DistanceOutput();

  it('gives the gap between two circles, with surface points and normal', () => {
    const a = setProxyFromCircle(new DistanceProxy(), {
      kind: 'circle',
      centerX: 0.5,
      centerY: 0,
      radius: 1,
    });
    const b = setProxyFromCircle(new DistanceProxy(), {
      kind: 'circle',
      centerX: 0,
      centerY: 0,
      radius: 0.5,
    });
    // A's centre is at (0, 0.5) after a quarter turn about an origin at (0, 0); B is at (3, 4.5).
    const xfA = new Transform().set(0, 0, Math.PI / 2);
    const xfB = new Transform().set(3, 4.5, 0);
    const distance = shapeDistance(a, xfA, b, xfB, output);
    expect(distance).toBeCloseTo(5 - 1.5, 12);
    expect(output.distance).toBe(distance);
    expect(output.normalX).toBeCloseTo(0.6, 12);
    expect(output.normalY).toBeCloseTo(0.8, 12);
    expect(output.pointAX).toBeCloseTo(0.6, 12);
    expect(output.pointAY).toBeCloseTo(0.5 + 0.8, 12);
    expect(output.pointBX).toBeCloseTo(3 - 0.3, 12);
    expect(output.pointBY).toBeCloseTo(4.5 - 0.4, 12);
  });

  it('reports 0 for overlapping circles, with a common point between them', () => {
    const a = setProxyFromCircle(new DistanceProxy(), {
      kind: 'circle',
      centerX: 0,
      centerY: 0,
      radius: 1,
    });
    const b = setProxyFromCircle(new DistanceProxy(), {
      kind: 'circle',
      centerX: 0,
      centerY: 0,
      radius: 1,
    });
    const distance = shapeDistance(a, new Transform(), b, new Transform().set(1.5, 0, 0), output);
    expect(distance).toBe(0);
    expect(output.pointAX).toBeCloseTo(0.75, 12);
    expect(output.pointBX).toBe(output.pointAX);
  });

  it('gives face, rotated-corner and corner-corner distances between boxes', () => {
    const a = setProxyFromPolygon(new DistanceProxy(), box(1, 1));
    const b = setProxyFromPolygon(new DistanceProxy(), box(0.5, 0.5));
    const xfA = new Transform();

    expect(shapeDistance(a, xfA, b, new Transform().set(4, 0.3, 0), output)).toBeCloseTo(2.5, 12);
    expect(output.normalX).toBeCloseTo(1, 12);
    expect(output.normalY).toBeCloseTo(0, 12);
    expect(output.pointAX).toBeCloseTo(1, 12);
    expect(output.pointBX).toBeCloseTo(3.5, 12);

    expect(shapeDistance(a, xfA, b, new Transform().set(4, 0, Math.PI / 4), output)).toBeCloseTo(
      3 - 0.5 * Math.SQRT2,
      12,
    );

    expect(shapeDistance(a, xfA, b, new Transform().set(3, 3, 0), output)).toBeCloseTo(
      1.5 * Math.SQRT2,
      12,
    );
    expect(output.pointAX).toBeCloseTo(1, 12);
    expect(output.pointAY).toBeCloseTo(1, 12);
    expect(output.pointBX).toBeCloseTo(2.5, 12);
    expect(output.pointBY).toBeCloseTo(2.5, 12);
  });

  it('reports 0 for overlapping boxes', () => {
    const a = setProxyFromPolygon(new DistanceProxy(), box(1, 1));
    const b = setProxyFromPolygon(new DistanceProxy(), box(0.5, 0.5));
    expect(shapeDistance(a, new Transform(), b, new Transform().set(1.2, 0.4, 0.3), output)).toBe(
      0,
    );
    expect(output.normalX).toBe(0);
    expect(output.normalY).toBe(0);
  });

  it('gives the distance from a sharp or rounded polygon to a segment', () => {
    const segment = setProxyFromSegment(new DistanceProxy(), {
      kind: 'segment',
      x1: 3,
      y1: 0,
      x2: 0,
      y2: 3,
      oneSided: false,
    });
    const sharp = setProxyFromPolygon(new DistanceProxy(), box(1, 1));
    const rounded = setProxyFromPolygon(new DistanceProxy(), box(1, 1, 0.1));
    const identity = new Transform();
    // The corner (1, 1) is closest to the line x + y = 3.
    expect(shapeDistance(sharp, identity, segment, identity, output)).toBeCloseTo(
      1 / Math.SQRT2,
      12,
    );
    expect(output.pointBX).toBeCloseTo(1.5, 12);
    expect(output.pointBY).toBeCloseTo(1.5, 12);
    expect(shapeDistance(rounded, identity, segment, identity, output)).toBeCloseTo(
      1 / Math.SQRT2 - 0.1,
      12,
    );
    // A horizontal segment below the box: the face at y = -1 is closest.
    const floor = setProxyFromSegment(new DistanceProxy(), {
      kind: 'segment',
      x1: -5,
      y1: -2.25,
      x2: 5,
      y2: -2.25,
      oneSided: false,
    });
    expect(
      shapeDistance(floor, identity, sharp, new Transform().set(0.3, 0, 0), output),
    ).toBeCloseTo(1.25, 12);
    expect(output.normalY).toBeCloseTo(1, 12);
  });

  it('matches brute-force edge distances for random separated convex polygons', () => {
    const random = makeRandom(31337);
    const a = new DistanceProxy();
    const b = new DistanceProxy();
    let maxIterations = 0;
    for (let trial = 0; trial < 300; trial++) {
      const proxies = [a, b];
      for (const proxy of proxies) {
        // Points on a circle at increasing angles form a convex, counter-clockwise polygon.
        const count = 3 + Math.floor(random() * 6);
        const radius = 0.2 + random() * 2;
        const points: number[] = [];
        const start = random() * 2 * Math.PI;
        const angles = Array.from({ length: count }, () => random() * 2 * Math.PI).sort(
          (p, q) => p - q,
        );
        for (const angle of angles) {
          points.push(radius * Math.cos(start + angle), radius * Math.sin(start + angle));
        }
        setProxyFromPolygon(proxy, polygonFrom(points));
      }
      const xfA = new Transform().set(random() * 4 - 2, random() * 4 - 2, random() * 6);
      const direction = random() * 2 * Math.PI;
      const gap = 4.5 + random() * 3;
      const xfB = new Transform().set(
        xfA.x + gap * Math.cos(direction),
        xfA.y + gap * Math.sin(direction),
        random() * 6,
      );
      const va = worldVertices(a, xfA);
      const vb = worldVertices(b, xfB);
      let expected = Infinity;
      for (let i = 0; i < a.count; i++) {
        const i2 = (i + 1) % a.count;
        for (let j = 0; j < b.count; j++) {
          const j2 = (j + 1) % b.count;
          expected = Math.min(
            expected,
            segmentSegmentDistance(
              va[2 * i]!,
              va[2 * i + 1]!,
              va[2 * i2]!,
              va[2 * i2 + 1]!,
              vb[2 * j]!,
              vb[2 * j + 1]!,
              vb[2 * j2]!,
              vb[2 * j2 + 1]!,
            ),
          );
        }
      }
      const distance = shapeDistance(a, xfA, b, xfB, output);
      expect(distance).toBeCloseTo(expected, 9);
      expect(
        Math.hypot(output.pointBX - output.pointAX, output.pointBY - output.pointAY),
      ).toBeCloseTo(expected, 9);
      maxIterations = Math.max(maxIterations, output.iterations);
    }
    expect(maxIterations).toBeLessThanOrEqual(20);
    expect(maxIterations).toBeGreaterThan(1);
  });
});

describe('capsule proxies', () => {
  it('measure a capsule as its segment swollen by its radius', () => {
    const capsule = new DistanceProxy();
    setProxyFromCapsule(capsule, makeCapsule(-1, 0, 1, 0, 0.25, 'c'));
    expect([capsule.count, capsule.radius]).toEqual([2, 0.25]);
    const ball = new DistanceProxy();
    setProxyFromCircle(ball, { kind: 'circle', centerX: 0, centerY: 0, radius: 0.5 });
    const out = new DistanceOutput();
    // Beside the middle: 1.5 - 0.25 - 0.5; beyond the end, turned: |(2.5, 0) - (1, 0)| - 0.75.
    expect(
      shapeDistance(capsule, new Transform(), ball, new Transform().set(0.3, 1.5, 0), out),
    ).toBeCloseTo(0.75, 12);
    expect(
      shapeDistance(
        capsule,
        new Transform().set(0, 0, Math.PI / 2),
        ball,
        new Transform().set(0, 2.5, 0),
        out,
      ),
    ).toBeCloseTo(0.75, 12);
    expect(out.normalY).toBeCloseTo(1, 12);
  });
});
