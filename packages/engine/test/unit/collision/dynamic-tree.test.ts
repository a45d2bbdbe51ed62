import { describe, expect, it } from 'vitest';
import { DynamicTree } from '../../../src/collision/dynamic-tree.ts';
import { checkTreeState, exportTreeState } from '../../../src/collision/dynamic-tree-state.ts';
import { AABB, aabbOverlaps } from '../../../src/geometry/aabb.ts';
import { makeRandom, randomBox } from './random-boxes.ts';

/**
 * Every structural invariant of a tree: links, reachability and the free list (checkTreeState),
 * then each internal node's height and enclosing box, and every free node marked free.
 */
function validate(tree: DynamicTree): void {
  const state = exportTreeState(tree);
  expect(checkTreeState(state)).toBeNull();
  for (let node = 0; node < state.capacity; node++) {
    const a = state.child1[node]!;
    const b = state.child2[node]!;
    if (state.heights[node]! <= 0 || a === -1) continue;
    expect(state.heights[node]).toBe(1 + Math.max(state.heights[a]!, state.heights[b]!));
    for (const child of [a, b]) {
      for (let k = 0; k < 2; k++) {
        expect(state.boxes[4 * node + k]!).toBeLessThanOrEqual(state.boxes[4 * child + k]!);
        expect(state.boxes[4 * node + 2 + k]!).toBeGreaterThanOrEqual(
          state.boxes[4 * child + 2 + k]!,
        );
      }
    }
  }
  for (let node = state.freeList; node !== -1; node = state.parent[node]!) {
    expect(state.heights[node]).toBe(-1);
  }
}

/** The tree's height: 0 for a single leaf or none. */
function height(tree: DynamicTree): number {
  const state = exportTreeState(tree);
  return state.root === -1 ? 0 : state.heights[state.root]!;
}

/** Sum of the internal nodes' perimeters over the root's: the SAH quality (lower is better). */
function areaRatio(tree: DynamicTree): number {
  const state = exportTreeState(tree);
  const perimeter = (node: number): number =>
    2 *
    (state.boxes[4 * node + 2]! -
      state.boxes[4 * node]! +
      (state.boxes[4 * node + 3]! - state.boxes[4 * node + 1]!));
  let total = 0;
  for (let node = 0; node < state.capacity; node++) {
    if (state.heights[node]! > 0) total += perimeter(node);
  }
  return total / perimeter(state.root);
}

/**
 * Ten random box queries, each answered with exactly the proxies brute force over `live` finds,
 * and `overlapping` listing them in the query's order.
 */
function expectQueriesMatchBruteForce(
  tree: DynamicTree,
  live: ReadonlyMap<number, AABB>,
  random: () => number,
): void {
  for (let q = 0; q < 10; q++) {
    const query = randomBox(random, 50, 20);
    const found: number[] = [];
    tree.query(query, (proxyId) => {
      found.push(proxyId);
      return true;
    });
    const expected = [...live].filter(([, box]) => aabbOverlaps(box, query)).map(([id]) => id);
    // overlapping (the broad phase's pair search) lists the same proxies in the query's order.
    const count = tree.overlapping(
      Float64Array.of(query.minX, query.minY, query.maxX, query.maxY),
      0,
    );
    expect([...tree.hits.subarray(0, count)]).toEqual(found);
    expect(found.sort((a, b) => a - b)).toEqual(expected.sort((a, b) => a - b));
    // overlapsAny (continuous collision's early out) agrees with the full query.
    expect(tree.overlapsAny(query)).toBe(expected.length > 0);
  }
}

describe('DynamicTree', () => {
  it('keeps its invariants and answers queries like brute force under random insert, move and destroy', () => {
    const random = makeRandom(12345);
    const tree = new DynamicTree();
    const live = new Map<number, AABB>();
    const scratch = new AABB();

    for (let batch = 0; batch < 40; batch++) {
      for (let op = 0; op < 25; op++) {
        const roll = random();
        const ids = [...live.keys()];
        if (roll < 0.5 || ids.length < 10) {
          const box = randomBox(random, 50, 4);
          const id = tree.createProxy(box, 1000 + live.size);
          expect(live.has(id)).toBe(false);
          live.set(id, box);
        } else if (roll < 0.8) {
          const id = ids[Math.floor(random() * ids.length)]!;
          const box = randomBox(random, 50, 4);
          tree.moveProxy(id, box);
          live.set(id, box);
        } else {
          const id = ids[Math.floor(random() * ids.length)]!;
          tree.destroyProxy(id);
          live.delete(id);
        }
      }
      validate(tree);
      expect(tree.proxyCount).toBe(live.size);
      for (const [id, box] of live) {
        tree.getFatAABB(id, scratch);
        expect([scratch.minX, scratch.minY, scratch.maxX, scratch.maxY]).toEqual([
          box.minX,
          box.minY,
          box.maxX,
          box.maxY,
        ]);
      }

      expectQueriesMatchBruteForce(tree, live, random);
    }
    expect(live.size).toBeGreaterThan(200);
  });

  it('returns the user data stored with each proxy', () => {
    const tree = new DynamicTree();
    const a = tree.createProxy(new AABB().set(0, 0, 1, 1), 7);
    const b = tree.createProxy(new AABB().set(5, 5, 6, 6), 42);
    expect(tree.getUserData(a)).toBe(7);
    expect(tree.getUserData(b)).toBe(42);
    const seen: number[] = [];
    tree.query(new AABB().set(4, 4, 7, 7), (_proxyId, userData) => {
      seen.push(userData);
      return true;
    });
    expect(seen).toEqual([42]);
  });

  it('stops a query when the callback returns false', () => {
    const tree = new DynamicTree();
    for (let i = 0; i < 20; i++) {
      tree.createProxy(new AABB().set(i, 0, i + 0.5, 1), i);
    }
    let calls = 0;
    tree.query(new AABB().set(-1, -1, 30, 2), () => {
      calls++;
      return calls < 3;
    });
    expect(calls).toBe(3);
  });

  it('supports a query from inside a query callback', () => {
    const tree = new DynamicTree();
    for (let i = 0; i < 50; i++) {
      tree.createProxy(new AABB().set(i, 0, i + 0.9, 1), i);
    }
    let outer = 0;
    let inner = 0;
    tree.query(new AABB().set(-1, -1, 100, 2), () => {
      outer++;
      tree.query(new AABB().set(10.5, 0, 12.5, 1), () => {
        inner++;
        return true;
      });
      return true;
    });
    expect(outer).toBe(50);
    expect(inner).toBe(50 * 3);
  });

  it('stays O(log n) high for 1000 proxies inserted in sorted order', () => {
    const tree = new DynamicTree();
    for (let i = 0; i < 1000; i++) {
      tree.createProxy(new AABB().set(i, 0, i + 1, 1), i);
    }
    validate(tree);
    // A perfectly balanced tree of 1000 leaves has height 10.
    expect(height(tree)).toBeLessThanOrEqual(20);
    expect(areaRatio(tree)).toBeLessThan(20);
  });

  it('reuses destroyed proxy ids and keeps its capacity after churn', () => {
    const tree = new DynamicTree();
    const ids: number[] = [];
    for (let i = 0; i < 100; i++) {
      ids.push(tree.createProxy(new AABB().set(i, i, i + 1, i + 1), i));
    }
    const maxId = Math.max(...ids);
    for (let round = 0; round < 5; round++) {
      for (let i = 0; i < 100; i++) {
        tree.destroyProxy(ids[i]!);
      }
      expect(tree.proxyCount).toBe(0);
      expect(height(tree)).toBe(0);
      for (let i = 0; i < 100; i++) {
        ids[i] = tree.createProxy(new AABB().set(i, -i, i + 1, -i + 1), i);
      }
    }
    validate(tree);
    expect(Math.max(...ids)).toBeLessThanOrEqual(maxId);
  });

  it('answers queries like brute force between enlargements and after each rebuild, and rebuilds to a tree as good as insertion', () => {
    const random = makeRandom(777);
    const tree = new DynamicTree();
    const live = new Map<number, AABB>();
    for (let i = 0; i < 400; i++) {
      const box = randomBox(random, 50, 2);
      live.set(tree.createProxy(box, i), box);
    }
    const inserted = areaRatio(tree);
    const ids = [...live.keys()];
    for (let round = 0; round < 20; round++) {
      // A step: most proxies drift, a few jump across the world.
      for (const id of ids) {
        const old = live.get(id)!;
        const jump = random() < 0.05;
        const dx = jump ? (random() * 2 - 1) * 80 : (random() * 2 - 1) * 0.5;
        const dy = jump ? (random() * 2 - 1) * 80 : (random() * 2 - 1) * 0.5;
        if (random() < 0.6) {
          const box = new AABB().set(old.minX + dx, old.minY + dy, old.maxX + dx, old.maxY + dy);
          tree.enlargeProxy(id, box);
          live.set(id, box);
        }
      }
      // Exact queries while the tree only grew.
      expectQueriesMatchBruteForce(tree, live, random);
      tree.rebuild();
      validate(tree);
      expectQueriesMatchBruteForce(tree, live, random);
      expect(tree.proxyCount).toBe(live.size);
    }
    // The rebuilt tree is balanced and better than incremental insertion (SAH cost ratio; 20 vs 36).
    expect(height(tree)).toBeLessThanOrEqual(20);
    expect(areaRatio(tree)).toBeLessThan(inserted);
    // Every flag is cleared: a second rebuild leaves the tree as it is.
    const before = exportTreeState(tree);
    tree.rebuild();
    expect(exportTreeState(tree)).toEqual(before);
  });

  it('rebuilds a tree of one enlarged leaf, and of coincident boxes, without losing a proxy', () => {
    const tree = new DynamicTree();
    const only = tree.createProxy(new AABB().set(0, 0, 1, 1), 1);
    tree.enlargeProxy(only, new AABB().set(5, 5, 6, 6));
    tree.rebuild();
    validate(tree);
    expect(tree.getMinX(only)).toBe(5);
    const same: number[] = [only];
    for (let i = 0; i < 50; i++) same.push(tree.createProxy(new AABB().set(5, 5, 6, 6), i));
    for (const id of same) tree.enlargeProxy(id, new AABB().set(2, 2, 3, 3));
    tree.rebuild();
    validate(tree);
    let found = 0;
    tree.query(new AABB().set(2.5, 2.5, 2.6, 2.6), () => {
      found++;
      return true;
    });
    expect(found).toBe(51);
    expect(height(tree)).toBeLessThanOrEqual(8);
  });
});
