import { NULL_KEY, type BroadPhase, type BroadPhaseState } from './broad-phase.ts';
import type { DynamicTree, TreeState } from './dynamic-tree.ts';

// The broad phase as plain data, for world snapshots. Functions rather than methods, so an app
// that never takes a snapshot does not ship them.

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

/** The trees and the move buffer as plain data. */
export function exportBroadPhaseState(broadPhase: BroadPhase): BroadPhaseState {
  const trees = broadPhase.trees;
  return {
    trees: [exportTreeState(trees[0]), exportTreeState(trees[1]), exportTreeState(trees[2])],
    moved: Array.from(broadPhase.moveBuffer.subarray(0, broadPhase.moveCount)),
  };
}

/** Replaces every tree and the move buffer; the trees' states must have passed checkTreeState. */
export function importBroadPhaseState(broadPhase: BroadPhase, state: BroadPhaseState): void {
  for (let type = 0; type < 3; type++) importTreeState(broadPhase.trees[type]!, state.trees[type]!);
  broadPhase.moveBuffer = new Int32Array(Math.max(64, state.moved.length));
  broadPhase.movedIndex = new Int32Array(64).fill(-1);
  broadPhase.moveCount = 0;
  for (const key of state.moved) {
    if (key === NULL_KEY) {
      broadPhase.moveBuffer[broadPhase.moveCount++] = NULL_KEY;
      continue;
    }
    broadPhase.bufferMove(key);
  }
}
