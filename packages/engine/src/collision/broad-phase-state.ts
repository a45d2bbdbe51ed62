import { NULL_KEY, type BroadPhase, type BroadPhaseState } from './broad-phase.ts';
import { exportTreeState, importTreeState } from './dynamic-tree-state.ts';

// The broad phase as plain data, for world snapshots. Functions rather than methods, so an app
// that never takes a snapshot does not ship them.

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
