import { NULL_NODE, type DynamicTree } from './dynamic-tree.ts';

// A tree as plain data, for world snapshots. Functions rather than methods, so an app that never
// takes a snapshot does not ship them.

/** A tree's state as plain arrays: per node 4 box numbers (m) and 5 integers. */
export interface TreeState {
  readonly capacity: number;
  readonly root: number;
  readonly freeList: number;
  readonly leafCount: number;
  readonly boxes: readonly number[];
  readonly child1: readonly number[];
  readonly child2: readonly number[];
  readonly parent: readonly number[];
  readonly heights: readonly number[];
  readonly userData: readonly number[];
}

/**
 * Checks that a tree state is well formed (lengths, links in range, parents matching children,
 * every live node reached once from the root, the free list covering the rest), so a corrupt
 * snapshot cannot make queries loop or read out of range. Returns what is wrong, or null.
 */
export function checkTreeState(state: TreeState): string | null {
  const n = state.capacity;
  if (!Number.isInteger(n) || n < 2 || n > 1 << 26) return 'capacity must be a whole number >= 2';
  if (state.boxes.length !== 4 * n) return `boxes must hold ${4 * n} numbers`;
  for (const key of ['child1', 'child2', 'parent', 'heights', 'userData'] as const) {
    const list = state[key];
    if (list.length !== n) return `${key} must hold ${n} integers`;
    for (const v of list)
      if (!Number.isInteger(v) || v < -1 || v > 0x7fffffff) return `${key} holds ${v}`;
  }
  const inRange = (node: number): boolean => node >= 0 && node < n;
  const seen = new Uint8Array(n);
  let leaves = 0;
  if (state.root !== NULL_NODE) {
    if (!inRange(state.root) || state.parent[state.root] !== NULL_NODE)
      return 'root is not a live node';
    const stack = [state.root];
    while (stack.length > 0) {
      const node = stack.pop()!;
      if (seen[node] === 1) return `node ${node} is reached twice`;
      seen[node] = 1;
      const a = state.child1[node]!;
      const b = state.child2[node]!;
      if (a === NULL_NODE) {
        if (b !== NULL_NODE || state.heights[node] !== 0) return `leaf ${node} is malformed`;
        leaves++;
        continue;
      }
      if (!inRange(a) || !inRange(b) || state.parent[a] !== node || state.parent[b] !== node) {
        return `node ${node} has bad children`;
      }
      stack.push(a, b);
    }
  } else if (state.leafCount !== 0) {
    return 'an empty tree has no leaves';
  }
  if (leaves !== state.leafCount)
    return `leafCount is ${state.leafCount} but ${leaves} leaves hang from the root`;
  let free = state.freeList;
  let freeCount = 0;
  while (free !== NULL_NODE) {
    if (!inRange(free) || seen[free] !== 0) return `free list reaches node ${free}`;
    seen[free] = 2;
    freeCount++;
    free = state.parent[free]!;
  }
  const live = seen.reduce((sum, v) => sum + (v === 1 ? 1 : 0), 0);
  if (live + freeCount !== n) return 'some nodes are neither in the tree nor free';
  return null;
}

/** A tree's whole state as plain arrays; {@link importTreeState} restores it. */
export function exportTreeState(tree: DynamicTree): TreeState {
  const n = tree.capacity;
  return {
    capacity: n,
    root: tree.root,
    freeList: tree.freeList,
    leafCount: tree.leafCount,
    boxes: Array.from(tree.boxes.subarray(0, 4 * n)),
    child1: Array.from(tree.child1.subarray(0, n)),
    child2: Array.from(tree.child2.subarray(0, n)),
    parent: Array.from(tree.parent.subarray(0, n)),
    heights: Array.from(tree.heights.subarray(0, n)),
    userData: Array.from(tree.userData.subarray(0, n)),
  };
}

/** Replaces a tree's state with one that checkTreeState accepted. */
export function importTreeState(tree: DynamicTree, state: TreeState): void {
  tree.capacity = state.capacity;
  tree.root = state.root;
  tree.freeList = state.freeList;
  tree.leafCount = state.leafCount;
  tree.boxes = Float64Array.from(state.boxes);
  tree.child1 = Int32Array.from(state.child1);
  tree.child2 = Int32Array.from(state.child2);
  tree.parent = Int32Array.from(state.parent);
  tree.heights = Int32Array.from(state.heights);
  tree.userData = Int32Array.from(state.userData);
  tree.flags = new Uint8Array(state.capacity);
  tree.stackTop = 0;
}
