import { describe, expect, it } from 'vitest';
import { DynamicTree } from '../../../src/collision/dynamic-tree.ts';
import {
  checkTreeState,
  exportTreeState,
  importTreeState,
} from '../../../src/collision/dynamic-tree-state.ts';
import { AABB } from '../../../src/geometry/aabb.ts';

function filled(): DynamicTree {
  const tree = new DynamicTree();
  for (let i = 0; i < 40; i++) {
    const x = (i * 7) % 13;
    const y = (i * 5) % 11;
    tree.createProxy(new AABB().set(x, y, x + 1, y + 1), i);
  }
  tree.destroyProxy(3);
  tree.destroyProxy(17);
  return tree;
}

function hits(tree: DynamicTree, box: AABB): number[] {
  const found: number[] = [];
  tree.query(box, (_id, data) => {
    found.push(data);
    return true;
  });
  return found;
}

describe('DynamicTree state export', () => {
  it('round-trips: the imported tree answers queries in the same order and grows the same way', () => {
    const original = filled();
    const copy = new DynamicTree();
    const state = exportTreeState(original);
    expect(checkTreeState(state)).toBeNull();
    importTreeState(copy, JSON.parse(JSON.stringify(state)));
    const box = new AABB().set(2, 2, 8, 6);
    expect(hits(copy, box)).toEqual(hits(original, box));
    const a = original.createProxy(new AABB().set(3, 3, 4, 4), 99);
    const b = copy.createProxy(new AABB().set(3, 3, 4, 4), 99);
    expect(b).toBe(a);
    expect(exportTreeState(copy)).toEqual(exportTreeState(original));
  });

  it('finds broken states: cycles, bad links, wrong counts', () => {
    const state = exportTreeState(filled());
    expect(checkTreeState({ ...state, leafCount: state.leafCount + 1 })).toMatch(/leafCount/);
    const child1 = state.child1.slice();
    const internal = child1.findIndex((c) => c >= 0);
    child1[internal] = internal; // a node that is its own child
    expect(checkTreeState({ ...state, child1 })).not.toBeNull();
    expect(checkTreeState({ ...state, boxes: state.boxes.slice(1) })).toMatch(/boxes/);
    expect(checkTreeState({ ...state, freeList: state.root })).not.toBeNull();
  });
});
