import { describe, expect, it } from 'vitest';
import { atan2, cosSin } from '../../../src/math/trigonometry.ts';

// The reference is V8's Math.sin, cos and atan2 (fdlibm's algorithms, within 1 ulp of the exact
// values). The engine's own functions must stay as accurate, and be rotations.

/** The spacing of doubles at v (one unit in the last place). */
function ulp(v: number): number {
  const a = Math.abs(v);
  if (a < 2.2250738585072014e-308) return Number.MIN_VALUE;
  let u = Number.EPSILON; // ulp(1)
  let p = 1;
  while (p * 2 <= a) {
    p *= 2;
    u *= 2;
  }
  while (p > a) {
    p /= 2;
    u /= 2;
  }
  return u;
}

/** Dense sweeps: every 1e-5 rad of [-10, 10], a coarser one up to 2^20 pi/2, near k pi/4. */
function angles(): number[] {
  const list: number[] = [];
  for (let i = 0; i <= 2_000_000; i += 1) list.push(-10 + i * 1e-5);
  for (let i = 0; i <= 200_000; i++) list.push(-1.6e6 + i * 16.000123);
  for (let k = -2000; k <= 2000; k++) {
    const a = (k * Math.PI) / 4;
    list.push(a, a + 1e-9, a - 1e-12, a * (1 + Number.EPSILON));
  }
  for (let e = -60; e <= 0; e += 0.25) list.push(2 ** e, -(2 ** e));
  return list;
}

describe('cosSin: the engine sine and cosine, from + - * / only', () => {
  const out = new Float64Array(2);
  const list = angles();

  it('is within 1 ulp of Math.cos and Math.sin over a dense sweep', { timeout: 60_000 }, () => {
    let worstCos = 0;
    let worstSin = 0;
    for (const a of list) {
      cosSin(a, out);
      const c = Math.cos(a);
      const s = Math.sin(a);
      worstCos = Math.max(worstCos, Math.abs(out[0]! - c) / ulp(c));
      worstSin = Math.max(worstSin, Math.abs(out[1]! - s) / ulp(s));
    }
    expect(list.length).toBeGreaterThan(2_000_000);
    expect(worstCos).toBeLessThanOrEqual(1);
    expect(worstSin).toBeLessThanOrEqual(1);
  });

  it(
    'is a rotation: |c^2 + s^2 - 1| <= 2^-52 at every angle of the sweep',
    { timeout: 60_000 },
    () => {
      let worst = 0;
      for (const a of list) {
        cosSin(a, out);
        worst = Math.max(worst, Math.abs(out[0]! * out[0]! + out[1]! * out[1]! - 1));
      }
      expect(worst).toBeLessThanOrEqual(Number.EPSILON);
    },
  );

  it('is even in cosine and odd in sine, bit for bit', () => {
    for (let i = 0; i < 10_000; i++) {
      const a = i * 0.0137 + 1e-3;
      cosSin(a, out);
      const c = out[0]!;
      const s = out[1]!;
      cosSin(-a, out);
      expect(out[0]).toBe(c);
      expect(out[1]).toBe(-s);
    }
  });

  it('gives exact values at 0 and keeps the sign of a zero angle', () => {
    cosSin(0, out);
    expect([out[0], out[1]]).toEqual([1, 0]);
    cosSin(-0, out);
    expect(Object.is(out[1], -0)).toBe(true);
  });

  it('beyond 2^20 pi/2 rad stays within half an ulp of the angle, and a rotation', () => {
    let worst = 0;
    for (let i = 0; i <= 20_000; i++) {
      const a = 1.7e6 * Math.pow(1e12 / 1.7e6, i / 20_000);
      cosSin(a, out);
      const error = Math.max(Math.abs(out[0]! - Math.cos(a)), Math.abs(out[1]! - Math.sin(a)));
      // The angle itself is known to half an ulp: that much error in the angle is inherent.
      worst = Math.max(worst, error / ulp(a));
      expect(Math.abs(out[0]! * out[0]! + out[1]! * out[1]! - 1)).toBeLessThanOrEqual(
        Number.EPSILON,
      );
    }
    expect(worst).toBeLessThanOrEqual(0.5);
    for (const a of [1e15, 1e300, Number.MAX_VALUE, -Number.MAX_VALUE]) {
      cosSin(a, out);
      expect(Math.abs(out[0]! * out[0]! + out[1]! * out[1]! - 1)).toBeLessThanOrEqual(
        Number.EPSILON,
      );
    }
  });

  it('gives NaN for NaN and infinite angles', () => {
    for (const a of [NaN, Infinity, -Infinity]) {
      cosSin(a, out);
      expect([out[0], out[1]]).toEqual([NaN, NaN]);
    }
  });
});

describe('atan2: the engine arc tangent, from + - * / only', () => {
  it('is within 1 ulp of Math.atan2 for directions all round and lengths from 1e-9 to 1e9', () => {
    let worst = 0;
    let count = 0;
    for (let i = 0; i < 400_000; i++) {
      const t = (i / 400_000) * 2 * Math.PI - Math.PI;
      const length = Math.pow(10, ((i * 7919) % 181) / 10 - 9);
      const y = length * Math.sin(t);
      const x = length * Math.cos(t) * (1 + (i % 5));
      const expected = Math.atan2(y, x);
      worst = Math.max(worst, Math.abs(atan2(y, x) - expected) / ulp(expected));
      count++;
    }
    expect(count).toBe(400_000);
    expect(worst).toBeLessThanOrEqual(1);
  });

  it('follows Math.atan2 at signed zeros, infinities and extreme ratios', () => {
    const cases: [number, number][] = [
      [0, 0],
      [-0, 0],
      [0, -0],
      [-0, -0],
      [0, -1],
      [-0, -1],
      [0, 1],
      [1, 0],
      [-1, -0],
      [Infinity, 1],
      [-Infinity, -1],
      [1, Infinity],
      [1, -Infinity],
      [-1, -Infinity],
      [Infinity, Infinity],
      [-Infinity, -Infinity],
      [1e-300, -1e300],
      [-1e-300, -1e300],
      [1e300, 1e-300],
      [1e300, -1e-300],
    ];
    for (const [y, x] of cases) {
      expect(Object.is(atan2(y, x), Math.atan2(y, x)), `atan2(${y}, ${x})`).toBe(true);
    }
    expect(atan2(NaN, 1)).toBeNaN();
    expect(atan2(1, NaN)).toBeNaN();
  });
});
