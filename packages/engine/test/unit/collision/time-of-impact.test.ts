import { describe, expect, it } from 'vitest';
import {
  DistanceOutput,
  DistanceProxy,
  setProxyFromCircle,
  setProxyFromPolygon,
  setProxyFromSegment,
  shapeDistance,
} from '../../../src/collision/distance.ts';
import {
  getSweepTransform,
  Sweep,
  timeOfImpact,
  TimeOfImpactOutput,
} from '../../../src/collision/time-of-impact.ts';
import { LINEAR_SLOP } from '../../../src/core/constants.ts';
import { createEmptyPolygon } from '../../../src/geometry/polygon.ts';
import type { Polygon } from '../../../src/geometry/polygon.ts';
import { Transform } from '../../../src/math/transform.ts';
import { makeRandom } from './random-boxes.ts';

const STEP = 1 / 60;

function box(halfWidth: number, halfHeight: number): Polygon {
  const polygon = createEmptyPolygon();
  polygon.count = 4;
  polygon.vertices.set([
    -halfWidth,
    -halfHeight,
    halfWidth,
    -halfHeight,
    halfWidth,
    halfHeight,
    -halfWidth,
    halfHeight,
  ]);
  return polygon;
}

function circleProxy(radius: number): DistanceProxy {
  return setProxyFromCircle(new DistanceProxy(), {
    kind: 'circle',
    centerX: 0,
    centerY: 0,
    radius,
  });
}

function wallProxy(x1: number, y1: number, x2: number, y2: number): DistanceProxy {
  return setProxyFromSegment(new DistanceProxy(), {
    kind: 'segment',
    x1,
    y1,
    x2,
    y2,
    oneSided: false,
  });
}

function sweep(x1: number, y1: number, a1: number, x2: number, y2: number, a2: number): Sweep {
  const s = new Sweep();
  s.c1X = x1;
  s.c1Y = y1;
  s.a1 = a1;
  s.c2X = x2;
  s.c2Y = y2;
  s.a2 = a2;
  return s;
}

function staticSweep(x: number, y: number): Sweep {
  return sweep(x, y, 0, x, y, 0);
}

/** Distance between the shapes' surfaces (radii included, m) at fraction t; 0 if they overlap. */
function surfaceDistanceAt(
  proxyA: DistanceProxy,
  sweepA: Sweep,
  proxyB: DistanceProxy,
  sweepB: Sweep,
  t: number,
): number {
  const xfA = getSweepTransform(sweepA, t, new Transform());
  const xfB = getSweepTransform(sweepB, t, new Transform());
  return shapeDistance(proxyA, xfA, proxyB, xfB, new DistanceOutput());
}

describe('getSweepTransform', () => {
  it('interpolates the centre and angle and puts the origin at centre - R(angle) localCenter', () => {
    const s = sweep(0, 0, 0, 2, 4, Math.PI);
    s.localCenterX = 1;
    s.localCenterY = 0;
    const xf = getSweepTransform(s, 0.5, new Transform());
    expect(xf.c).toBeCloseTo(0, 12);
    expect(xf.s).toBeCloseTo(1, 12);
    // The centre is at (1, 2); the local centre (1, 0) turned a quarter is (0, 1).
    expect(xf.x).toBeCloseTo(1, 12);
    expect(xf.y).toBeCloseTo(1, 12);
  });
});

describe('timeOfImpact', () => {
  const output = new TimeOfImpactOutput();

  it('catches a 0.1 m circle at 100 m/s crossing a thin static wall, stopping at the target', () => {
    const circle = circleProxy(0.1);
    const wall = wallProxy(1, -1, 1, 1);
    const travel = 100 * STEP;
    const moving = sweep(0, 0.3, 0, travel, 0.3, 0);
    timeOfImpact(circle, moving, wall, staticSweep(0, 0), 1, output);
    expect(output.state).toBe('hit');
    // The centre stops where the core distance is the target 0.1 - LINEAR_SLOP.
    const expected = (1 - (0.1 - LINEAR_SLOP)) / travel;
    expect(Math.abs(output.fraction - expected) * travel).toBeLessThanOrEqual(0.25 * LINEAR_SLOP);
    // At the end of the step the circle would be far through the wall.
    expect(travel).toBeGreaterThan(1.6);
  });

  it('finds the same hit with the wall as shape A and the circle as shape B', () => {
    const travel = 100 * STEP;
    timeOfImpact(
      wallProxy(1, -1, 1, 1),
      staticSweep(0, 0),
      circleProxy(0.1),
      sweep(0, 0, 0, travel, 0, 0),
      1,
      output,
    );
    expect(output.state).toBe('hit');
    expect(output.fraction * travel).toBeCloseTo(1 - 0.1 + LINEAR_SLOP, 3);
  });

  it('stops a circle at the face of a static box', () => {
    const boxProxy = setProxyFromPolygon(new DistanceProxy(), box(0.5, 0.5));
    const circle = circleProxy(0.25);
    const moving = sweep(0, 0.2, 0, 5, 0.2, 0);
    timeOfImpact(boxProxy, staticSweep(3, 0), circle, moving, 1, output);
    expect(output.state).toBe('hit');
    const expected = (2.5 - (0.25 - LINEAR_SLOP)) / 5;
    expect(Math.abs(output.fraction - expected) * 5).toBeLessThanOrEqual(0.25 * LINEAR_SLOP);
    const gap = surfaceDistanceAt(boxProxy, staticSweep(3, 0), circle, moving, output.fraction);
    expect(gap).toBe(0);
  });

  it('catches a spinning 0.2 m box at 100 m/s crossing a thin wall, never overlapping deeply', () => {
    const boxProxy = setProxyFromPolygon(new DistanceProxy(), box(0.1, 0.1));
    const wall = wallProxy(1, -1, 1, 1);
    const travel = 100 * STEP;
    const angle = 40 * STEP * 2 * Math.PI * 0.25;
    const moving = sweep(0, 0.05, 0.1, travel, 0.05, 0.1 + angle);
    timeOfImpact(boxProxy, moving, wall, staticSweep(0, 0), 1, output);
    expect(output.state).toBe('hit');

    // Reference: the first time the box's rightmost corner comes within LINEAR_SLOP of x = 1,
    // by dense sampling then bisection.
    const rightmost = (t: number): number => {
      const a = 0.1 + t * angle;
      const cx = t * travel;
      let best = -Infinity;
      for (const [x, y] of [
        [-0.1, -0.1],
        [0.1, -0.1],
        [0.1, 0.1],
        [-0.1, 0.1],
      ] as const) {
        best = Math.max(best, cx + Math.cos(a) * x - Math.sin(a) * y);
      }
      return best;
    };
    const gapAt = (t: number) => 1 - rightmost(t) - LINEAR_SLOP;
    let lo = 0;
    let hi = 1;
    for (let i = 1; i <= 10000; i++) {
      if (gapAt(i / 10000) <= 0) {
        lo = (i - 1) / 10000;
        hi = i / 10000;
        break;
      }
    }
    for (let i = 0; i < 60; i++) {
      const mid = 0.5 * (lo + hi);
      if (gapAt(mid) > 0) {
        lo = mid;
      } else {
        hi = mid;
      }
    }
    expect(Math.abs(output.fraction - lo) * travel).toBeLessThanOrEqual(LINEAR_SLOP);
    const gap = 1 - rightmost(output.fraction);
    expect(gap).toBeGreaterThanOrEqual(LINEAR_SLOP - 0.25 * LINEAR_SLOP);
    expect(gap).toBeLessThanOrEqual(LINEAR_SLOP + 0.25 * LINEAR_SLOP);
  });

  it('finds when a rotating rod sweeps onto a point-like circle (pure rotation)', () => {
    // A rod of half-length 1 turning about its centre from 0 to a quarter turn; the circle
    // centre is at (0, 0.8). The core distance is 0.8 cos(angle), which reaches the target
    // 0.05 - LINEAR_SLOP at angle = acos(target / 0.8).
    const rod = wallProxy(-1, 0, 1, 0);
    const circle = circleProxy(0.05);
    const turn = Math.PI / 2;
    timeOfImpact(rod, sweep(0, 0, 0, 0, 0, turn), circle, staticSweep(0, 0.8), 1, output);
    expect(output.state).toBe('hit');
    const expected = Math.acos((0.05 - LINEAR_SLOP) / 0.8) / turn;
    const distanceAtHit = 0.8 * Math.cos(output.fraction * turn);
    expect(Math.abs(distanceAtHit - (0.05 - LINEAR_SLOP))).toBeLessThanOrEqual(0.25 * LINEAR_SLOP);
    expect(output.fraction).toBeCloseTo(expected, 2);
  });

  it('finds the meeting time of two circles moving towards each other', () => {
    const a = circleProxy(0.5);
    const b = circleProxy(0.5);
    timeOfImpact(a, sweep(-3, 0, 0, 1, 0, 0), b, sweep(3, 0, 0, -1, 0, 0), 1, output);
    expect(output.state).toBe('hit');
    // The centres close at 8 m per step from 6 m apart to the target 1 - LINEAR_SLOP.
    const expected = (6 - (1 - LINEAR_SLOP)) / 8;
    expect(Math.abs(output.fraction - expected) * 8).toBeLessThanOrEqual(0.25 * LINEAR_SLOP);
  });

  it('reports separated, at maxFraction, for a circle that passes beside the wall', () => {
    const circle = circleProxy(0.1);
    const wall = wallProxy(1, -1, 1, 1);
    timeOfImpact(circle, sweep(0, 1.5, 0, 2, 1.5, 0), wall, staticSweep(0, 0), 1, output);
    expect(output.state).toBe('separated');
    expect(output.fraction).toBe(1);

    timeOfImpact(circle, sweep(0, 0, 0, -5, 0, 0), wall, staticSweep(0, 0), 1, output);
    expect(output.state).toBe('separated');
    expect(output.fraction).toBe(1);
  });

  it('reports separated when the hit lies beyond maxFraction', () => {
    const circle = circleProxy(0.1);
    const wall = wallProxy(1, -1, 1, 1);
    // The hit would be at about 0.9 of the step.
    timeOfImpact(circle, sweep(0, 0, 0, 1, 0, 0), wall, staticSweep(0, 0), 0.5, output);
    expect(output.state).toBe('separated');
    expect(output.fraction).toBe(0.5);
  });

  it('reports overlapped at 0 when the cores already overlap', () => {
    const a = setProxyFromPolygon(new DistanceProxy(), box(0.5, 0.5));
    const b = setProxyFromPolygon(new DistanceProxy(), box(0.5, 0.5));
    timeOfImpact(a, staticSweep(0, 0), b, sweep(0.3, 0.2, 0.4, 5, 0, 0), 1, output);
    expect(output.state).toBe('overlapped');
    expect(output.fraction).toBe(0);
  });

  it('reports a hit at 0 when only the radii overlap at the start', () => {
    timeOfImpact(
      circleProxy(0.5),
      staticSweep(0, 0),
      circleProxy(0.5),
      sweep(0.9, 0, 0, 3, 0, 0),
      1,
      output,
    );
    expect(output.state).toBe('hit');
    expect(output.fraction).toBe(0);
  });

  it('never reports a time after the first contact for random fast spinning boxes', () => {
    const random = makeRandom(4242);
    const a = setProxyFromPolygon(new DistanceProxy(), box(0.1, 0.1));
    const b = setProxyFromPolygon(new DistanceProxy(), box(0.5, 0.05));
    const target = LINEAR_SLOP;
    const states = new Map<string, number>();
    for (let trial = 0; trial < 200; trial++) {
      const sweepA = sweep(
        random() * 4 - 2,
        random() * 4 - 2,
        random() * 6,
        random() * 4 - 2,
        random() * 4 - 2,
        random() * 6 + (random() - 0.5) * 4,
      );
      sweepA.localCenterX = (random() - 0.5) * 0.1;
      const sweepB = sweep(0, 0, random(), 0, 0, random() * 2);
      timeOfImpact(a, sweepA, b, sweepB, 1, output);
      states.set(output.state, (states.get(output.state) ?? 0) + 1);
      expect(output.state).not.toBe('unknown');
      if (output.state === 'overlapped') {
        continue;
      }
      // Before the reported fraction, the shapes never came closer than the target.
      const end = output.fraction;
      for (let i = 0; i < 200; i++) {
        const t = (end * i) / 200;
        expect(surfaceDistanceAt(a, sweepA, b, sweepB, t)).toBeGreaterThan(
          target - 0.25 * LINEAR_SLOP,
        );
      }
      if (output.state === 'hit') {
        const gap = surfaceDistanceAt(a, sweepA, b, sweepB, output.fraction);
        expect(Math.abs(gap - target)).toBeLessThanOrEqual(0.25 * LINEAR_SLOP);
      }
    }
    expect(states.get('hit') ?? 0).toBeGreaterThan(20);
    expect(states.get('failed') ?? 0).toBe(0);
  });
});
