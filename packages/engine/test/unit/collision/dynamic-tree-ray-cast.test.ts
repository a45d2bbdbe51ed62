import { describe, expect, it } from 'vitest';
import { DynamicTree } from '../../../src/collision/dynamic-tree.ts';
import { rayCastTree } from '../../../src/collision/dynamic-tree-ray-cast.ts';
import { AABB } from '../../../src/geometry/aabb.ts';
import { RayInput } from '../../../src/geometry/ray.ts';
import { makeRandom, randomBox } from './random-boxes.ts';

/** Entry fraction of the ray into the box by the slab method, or Infinity if it misses. */
function rayBoxFraction(input: RayInput, box: AABB): number {
  let tMin = 0;
  let tMax = input.maxFraction;
  const origin = [input.originX, input.originY];
  const direction = [input.translationX, input.translationY];
  const lower = [box.minX, box.minY];
  const upper = [box.maxX, box.maxY];
  for (let axis = 0; axis < 2; axis++) {
    const p = origin[axis]!;
    const d = direction[axis]!;
    if (d === 0) {
      if (p < lower[axis]! || p > upper[axis]!) {
        return Infinity;
      }
      continue;
    }
    let t1 = (lower[axis]! - p) / d;
    let t2 = (upper[axis]! - p) / d;
    if (t1 > t2) {
      [t1, t2] = [t2, t1];
    }
    tMin = Math.max(tMin, t1);
    tMax = Math.min(tMax, t2);
    if (tMin > tMax) {
      return Infinity;
    }
  }
  return tMin;
}

describe('rayCastTree', () => {
  it('finds the same first ray hit as brute force', () => {
    const random = makeRandom(777);
    const tree = new DynamicTree();
    const boxes = new Map<number, AABB>();
    for (let i = 0; i < 300; i++) {
      const box = randomBox(random, 40, 3);
      boxes.set(tree.createProxy(box, i), box);
    }
    const input = new RayInput();
    let hits = 0;
    for (let r = 0; r < 200; r++) {
      const angle = random() * 2 * Math.PI;
      input.originX = (random() * 2 - 1) * 60;
      input.originY = (random() * 2 - 1) * 60;
      input.translationX = 100 * Math.cos(angle);
      input.translationY = 100 * Math.sin(angle);
      input.maxFraction = 1;

      let expectedFraction = Infinity;
      for (const box of boxes.values()) {
        expectedFraction = Math.min(expectedFraction, rayBoxFraction(input, box));
      }

      let bestFraction = Infinity;
      rayCastTree(tree, input, (rayInput, proxyId) => {
        const fraction = rayBoxFraction(rayInput, boxes.get(proxyId)!);
        if (fraction === Infinity) {
          return -1;
        }
        bestFraction = fraction;
        return fraction;
      });
      if (expectedFraction === Infinity) {
        expect(bestFraction).toBe(Infinity);
        expect(input.maxFraction).toBe(1);
      } else {
        hits++;
        expect(bestFraction).toBeCloseTo(expectedFraction, 12);
        expect(input.maxFraction).toBeCloseTo(expectedFraction, 12);
      }
    }
    expect(hits).toBeGreaterThan(50);
  });

  it('stops a ray cast when the callback returns 0', () => {
    const tree = new DynamicTree();
    for (let i = 0; i < 10; i++) {
      tree.createProxy(new AABB().set(i * 2, -1, i * 2 + 1, 1), i);
    }
    const input = new RayInput();
    input.originX = -5;
    input.translationX = 40;
    let calls = 0;
    rayCastTree(tree, input, () => {
      calls++;
      return 0;
    });
    expect(calls).toBe(1);
    expect(input.maxFraction).toBe(0);
  });
});
