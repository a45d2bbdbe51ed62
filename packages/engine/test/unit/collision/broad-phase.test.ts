import { describe, expect, it } from 'vitest';
import { BroadPhase } from '../../../src/collision/broad-phase.ts';
import type { ProxyType } from '../../../src/collision/broad-phase.ts';
import { FILTER_ROW } from '../../../src/collision/pair-filter.ts';
import { PairSet } from '../../../src/collision/pair-set.ts';
import { AABB_MARGIN } from '../../../src/core/constants.ts';
import { AABB, aabbOverlaps } from '../../../src/geometry/aabb.ts';
import { RayInput } from '../../../src/geometry/ray.ts';
import { makeRandom } from './random-boxes.ts';

function randomBox(random: () => number, extent: number, maxSize: number): AABB {
  const x = (random() * 2 - 1) * extent;
  const y = (random() * 2 - 1) * extent;
  return new AABB().set(x, y, x + 0.05 + random() * maxSize, y + 0.05 + random() * maxSize);
}

/** Filter rows for shape ids below `count`: category 1, every mask bit, no group, no sensor. */
function openFilters(count: number): Int32Array {
  const filters = new Int32Array(count * FILTER_ROW);
  for (let id = 0; id < count; id++) {
    filters[id * FILTER_ROW] = 1;
    filters[id * FILTER_ROW + 1] = -1;
  }
  return filters;
}

/** Rows for the few shape ids the small tests below use. */
const OPEN = openFilters(16);

interface Proxy {
  key: number;
  type: ProxyType;
  shapeId: number;
}

/**
 * Runs a seeded random scene of static, kinematic and dynamic proxies through several rounds of
 * create, move and destroy, checks every updatePairs against brute force (less the pairs in
 * `known` and those `forbidden` says the `filters` rows forbid, which it must not report), and
 * returns the reported pairs in order.
 */
function runScene(
  seed: number,
  known = new PairSet(),
  filters = openFilters(4096),
  forbidden: (a: number, b: number) => boolean = () => false,
): string[] {
  const random = makeRandom(seed);
  const broadPhase = new BroadPhase();
  const live = new Map<number, Proxy>();
  let nextShapeId = 0;
  const log: string[] = [];
  const fatA = new AABB();
  const fatB = new AABB();

  const create = (type: ProxyType, force: boolean): Proxy => {
    const proxy = {
      key: broadPhase.createProxy(randomBox(random, 20, 2), type, nextShapeId, force),
      type,
      shapeId: nextShapeId++,
    };
    live.set(proxy.shapeId, proxy);
    return proxy;
  };

  for (let i = 0; i < 60; i++) {
    create(0, false);
  }
  for (let i = 0; i < 15; i++) {
    create(1, false);
  }
  for (let i = 0; i < 120; i++) {
    create(2, false);
  }

  for (let round = 0; round < 12; round++) {
    const moved = new Set<number>();
    if (round === 0) {
      for (const proxy of live.values()) {
        if (proxy.type !== 0) {
          moved.add(proxy.shapeId);
        }
      }
    }
    const shapes = [...live.values()];
    for (const proxy of shapes) {
      const roll = random();
      if (roll < 0.3) {
        if (broadPhase.moveProxy(proxy.key, randomBox(random, 20, 2))) {
          moved.add(proxy.shapeId);
        }
      } else if (roll < 0.33) {
        broadPhase.destroyProxy(proxy.key);
        live.delete(proxy.shapeId);
        moved.delete(proxy.shapeId);
      }
    }
    for (let i = 0; i < 5; i++) {
      const type = (i % 3) as ProxyType;
      const proxy = create(type, i === 3);
      if (type !== 0 || i === 3) {
        moved.add(proxy.shapeId);
      }
    }

    const expected = new Set<string>();
    const all = [...live.values()];
    for (let i = 0; i < all.length; i++) {
      for (let j = i + 1; j < all.length; j++) {
        const a = all[i]!;
        const b = all[j]!;
        if (!moved.has(a.shapeId) && !moved.has(b.shapeId)) {
          continue;
        }
        if (a.type !== 2 && b.type !== 2) {
          continue;
        }
        broadPhase.getFatAABB(a.key, fatA);
        broadPhase.getFatAABB(b.key, fatB);
        if (
          aabbOverlaps(fatA, fatB) &&
          !known.has(a.shapeId, b.shapeId) &&
          !forbidden(a.shapeId, b.shapeId)
        ) {
          expected.add(`${Math.min(a.shapeId, b.shapeId)},${Math.max(a.shapeId, b.shapeId)}`);
        }
      }
    }

    const reported: string[] = [];
    broadPhase.updatePairs(
      (shapeIdA, shapeIdB) => {
        expect(shapeIdA).toBeLessThan(shapeIdB);
        const a = live.get(shapeIdA)!;
        const b = live.get(shapeIdB)!;
        expect(a.type === 0 && b.type === 0).toBe(false);
        reported.push(`${shapeIdA},${shapeIdB}`);
      },
      known,
      filters,
    );
    expect(new Set(reported).size).toBe(reported.length);
    expect([...reported].sort()).toEqual([...expected].sort());
    expect(broadPhase.movedProxyCount).toBe(0);
    log.push(...reported, '|');
  }
  expect(broadPhase.proxyCount).toBe(live.size);
  return log;
}

/** The two shape ids of a logged pair "a,b". */
function pairOf(entry: string): [number, number] {
  const [a, b] = entry.split(',').map(Number);
  return [a!, b!];
}

describe('BroadPhase', () => {
  it('reports exactly the overlapping fat-box pairs among moved proxies, once each', () => {
    const log = runScene(99);
    expect(log.length).toBeGreaterThan(100);
  });

  it('reports pairs in the same order for two identical runs', () => {
    expect(runScene(5)).toEqual(runScene(5));
  });

  it('does not report the known pairs (those with a contact), and reports the rest in order', () => {
    const all = runScene(11);
    const known = new PairSet();
    const pairs = all.filter((entry) => entry !== '|');
    for (let i = 0; i < pairs.length; i += 2) {
      const [a, b] = pairs[i]!.split(',').map(Number);
      known.add(a!, b!);
    }
    expect(known.size).toBeGreaterThan(50);
    const rest = runScene(11, known);
    expect(rest).toEqual(all.filter((entry) => entry === '|' || !known.has(...pairOf(entry))));
    expect(rest.length).toBeLessThan(all.length);
  });

  it('does not report the pairs the filter rows forbid (sensors, groups), and reports the rest in order', () => {
    const all = runScene(13);
    // Shape ids divisible by 4 are sensors; those divisible by 3 share group -1 (never together).
    const filters = openFilters(4096);
    for (let id = 0; id < 4096; id++) {
      if (id % 4 === 0) filters[id * FILTER_ROW + 3] = 1;
      if (id % 3 === 0) filters[id * FILTER_ROW + 2] = -1;
    }
    const forbidden = (a: number, b: number): boolean =>
      a % 4 === 0 || b % 4 === 0 || (a % 3 === 0 && b % 3 === 0);
    const rest = runScene(13, new PairSet(), filters, forbidden);
    expect(rest).toEqual(all.filter((entry) => entry === '|' || !forbidden(...pairOf(entry))));
    expect(rest.length).toBeLessThan(all.length - 50);
  });

  it('never pairs static with static, even when forced', () => {
    const broadPhase = new BroadPhase();
    const box = new AABB().set(0, 0, 1, 1);
    broadPhase.createProxy(box, 0, 1, true);
    broadPhase.createProxy(box, 0, 2, true);
    broadPhase.createProxy(box, 1, 3, false);
    let count = 0;
    broadPhase.updatePairs(
      () => {
        count++;
      },
      new PairSet(),
      OPEN,
    );
    expect(count).toBe(0);
    broadPhase.createProxy(box, 2, 4, false);
    const pairs: string[] = [];
    broadPhase.updatePairs(
      (a, b) => {
        pairs.push(`${a},${b}`);
      },
      new PairSet(),
      OPEN,
    );
    expect(pairs.sort()).toEqual(['1,4', '2,4', '3,4']);
  });

  it('fattens non-static boxes by the margin, keeps static boxes tight, and skips small moves', () => {
    const broadPhase = new BroadPhase();
    const tight = new AABB().set(0, 0, 1, 1);
    const dynamicKey = broadPhase.createProxy(tight, 2, 7, false);
    const staticKey = broadPhase.createProxy(tight, 0, 8, false);
    const out = new AABB();
    broadPhase.getFatAABB(dynamicKey, out);
    expect([out.minX, out.minY, out.maxX, out.maxY]).toEqual([
      -AABB_MARGIN,
      -AABB_MARGIN,
      1 + AABB_MARGIN,
      1 + AABB_MARGIN,
    ]);
    broadPhase.getFatAABB(staticKey, out);
    expect([out.minX, out.minY, out.maxX, out.maxY]).toEqual([0, 0, 1, 1]);
    expect(broadPhase.getShapeId(dynamicKey)).toBe(7);
    expect(broadPhase.getShapeId(staticKey)).toBe(8);
    expect(broadPhase.getType(dynamicKey)).toBe(2);
    expect(broadPhase.getType(staticKey)).toBe(0);
    broadPhase.updatePairs(() => undefined, new PairSet(), OPEN);

    const half = AABB_MARGIN / 2;
    expect(broadPhase.moveProxy(dynamicKey, new AABB().set(half, half, 1 + half, 1 + half))).toBe(
      false,
    );
    expect(broadPhase.movedProxyCount).toBe(0);
    const far = 2 * AABB_MARGIN;
    expect(broadPhase.moveProxy(dynamicKey, new AABB().set(far, 0, 1 + far, 1))).toBe(true);
    expect(broadPhase.movedProxyCount).toBe(1);
    broadPhase.getFatAABB(dynamicKey, out);
    expect(out.minX).toBeCloseTo(far - AABB_MARGIN, 12);
    expect(out.maxX).toBeCloseTo(1 + far + AABB_MARGIN, 12);
  });

  it('forgets a destroyed proxy that was buffered as moved', () => {
    const broadPhase = new BroadPhase();
    const box = new AABB().set(0, 0, 1, 1);
    broadPhase.createProxy(box, 0, 1, false);
    const doomed = broadPhase.createProxy(box, 2, 2, false);
    broadPhase.destroyProxy(doomed);
    let count = 0;
    broadPhase.updatePairs(
      () => {
        count++;
      },
      new PairSet(),
      OPEN,
    );
    expect(count).toBe(0);
    expect(broadPhase.proxyCount).toBe(1);
  });

  it('queries and ray-casts all three trees, passing proxy keys and shape ids', () => {
    const broadPhase = new BroadPhase();
    const keys = [
      broadPhase.createProxy(new AABB().set(0, 0, 1, 1), 0, 10, false),
      broadPhase.createProxy(new AABB().set(3, 0, 4, 1), 1, 11, false),
      broadPhase.createProxy(new AABB().set(6, 0, 7, 1), 2, 12, false),
    ];
    const seen: number[] = [];
    broadPhase.query(new AABB().set(-1, -1, 10, 2), (proxyKey, shapeId) => {
      expect(broadPhase.getShapeId(proxyKey)).toBe(shapeId);
      seen.push(shapeId);
      return true;
    });
    expect(seen.sort()).toEqual([10, 11, 12]);

    let calls = 0;
    broadPhase.query(new AABB().set(-1, -1, 10, 2), () => {
      calls++;
      return false;
    });
    expect(calls).toBe(1);

    // A ray from the right: the dynamic box (searched last) is the first hit, and clipping in
    // earlier trees must not hide it; a clip at the dynamic box must hold at the end.
    const input = new RayInput();
    input.originX = 10;
    input.originY = 0.5;
    input.translationX = -20;
    const hit: number[] = [];
    broadPhase.rayCast(input, (rayInput, proxyKey, shapeId) => {
      expect(keys).toContain(proxyKey);
      const entry = broadPhase.getFatAABB(proxyKey, new AABB()).maxX;
      const fraction = (rayInput.originX - entry) / -rayInput.translationX;
      hit.push(shapeId);
      return fraction;
    });
    expect(hit).toContain(12);
    expect(input.maxFraction).toBeCloseTo((10 - (7 + AABB_MARGIN)) / 20, 12);
  });
});
