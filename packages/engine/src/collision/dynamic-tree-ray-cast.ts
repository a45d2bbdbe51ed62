import type { RayInput } from '../geometry/ray.ts';
import { NULL_NODE, type DynamicTree } from './dynamic-tree.ts';

/**
 * Called for each leaf whose box the ray may hit. `input.maxFraction` holds the current clip
 * (a fraction of `input.translation`, no unit). Return the fraction at which the proxy's shape
 * was hit to clip the ray there, 0 to stop the cast, -1 to ignore this proxy and continue, or
 * `input.maxFraction` to continue unclipped.
 */
export type TreeRayCastCallback = (input: RayInput, proxyId: number, userData: number) => number;

/**
 * Casts the ray from `input.origin` along `input.translation` (m, world frame), clipped at
 * `input.maxFraction`, and calls `callback` for each proxy of `tree` whose box the clipped ray
 * crosses. The callback's return value clips the ray (see TreeRayCastCallback), and
 * `input.maxFraction` is updated to the clip so later callbacks and callers see it.
 */
export function rayCastTree(
  tree: DynamicTree,
  input: RayInput,
  callback: TreeRayCastCallback,
): void {
  if (tree.root === NULL_NODE) {
    return;
  }
  const px = input.originX;
  const py = input.originY;
  const dx = input.translationX;
  const dy = input.translationY;
  // A box is skipped if it is off the ray's line (separating axis along the ray's normal)
  // or outside the box of the clipped segment (separating axes x and y): the segment-vs-box
  // separating-axis test of Gino van den Bergen, "Collision Detection in Interactive 3D
  // Environments" (2003), as Box2D uses it.
  const length = Math.sqrt(dx * dx + dy * dy);
  const nx = length > 0 ? -dy / length : 0;
  const ny = length > 0 ? dx / length : 0;
  const absNx = Math.abs(nx);
  const absNy = Math.abs(ny);
  let maxFraction = input.maxFraction;
  let endX = px + maxFraction * dx;
  let endY = py + maxFraction * dy;
  let segMinX = px < endX ? px : endX;
  let segMinY = py < endY ? py : endY;
  let segMaxX = px > endX ? px : endX;
  let segMaxY = py > endY ? py : endY;

  const base = tree.stackTop;
  let top = base;
  tree.stack[top++] = tree.root;
  while (top > base) {
    const node = tree.stack[--top]!;
    const boxes = tree.boxes;
    const o = 4 * node;
    const bMinX = boxes[o]!;
    const bMinY = boxes[o + 1]!;
    const bMaxX = boxes[o + 2]!;
    const bMaxY = boxes[o + 3]!;
    if (bMinX > segMaxX || segMinX > bMaxX || bMinY > segMaxY || segMinY > bMaxY) {
      continue;
    }
    const cx = 0.5 * (bMinX + bMaxX);
    const cy = 0.5 * (bMinY + bMaxY);
    const hx = 0.5 * (bMaxX - bMinX);
    const hy = 0.5 * (bMaxY - bMinY);
    if (Math.abs(nx * (px - cx) + ny * (py - cy)) > absNx * hx + absNy * hy) {
      continue;
    }
    const first = tree.child1[node]!;
    if (first === NULL_NODE) {
      input.maxFraction = maxFraction;
      tree.stackTop = top;
      const value = callback(input, node, tree.userData[node]!);
      tree.stackTop = base;
      if (value === 0) {
        input.maxFraction = 0;
        return;
      }
      if (value > 0 && value <= maxFraction) {
        maxFraction = value;
        endX = px + maxFraction * dx;
        endY = py + maxFraction * dy;
        segMinX = px < endX ? px : endX;
        segMinY = py < endY ? py : endY;
        segMaxX = px > endX ? px : endX;
        segMaxY = py > endY ? py : endY;
      }
      input.maxFraction = maxFraction;
    } else {
      if (top + 2 > tree.stack.length) {
        tree.growStack();
      }
      tree.stack[top++] = tree.child2[node]!;
      tree.stack[top++] = first;
    }
  }
}
