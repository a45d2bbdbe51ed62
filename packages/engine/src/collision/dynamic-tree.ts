import type { AABB } from '../geometry/aabb.ts';

// A dynamic bounding-volume hierarchy of axis-aligned boxes: the idea of Box2D's b2DynamicTree
// (Erin Catto), written from the published algorithms rather than from its code.
//
// - Leaves hold the boxes the caller gives (the broad phase fattens them), internal nodes the
//   union of their two children. Node data lives in typed arrays indexed by node id; freed
//   nodes form a singly linked free list through `parent`, so steady-state use allocates nothing.
// - Insertion picks the sibling that minimises the surface-area-heuristic cost of the tree (the
//   sum of internal-node perimeters: in 2D the perimeter plays the role of surface area), found
//   by branch and bound (Bittner, Hapala and Havran 2015, "Fast insertion-based optimization of
//   bounding volume hierarchies"; Box2D v3's b2FindBestSibling applies the same bound).
// - On the way back up from an insertion or removal, each ancestor is balanced: when one child is
//   more than one level taller than the other, the taller one is promoted (Box2D v2's b2Balance).
//   Sorted insertion (a row of boxes, a pyramid's floor) therefore still yields a height of
//   O(log n). The perimeter-reducing rotations of Kopta et al. 2012 (Box2D v3's b2RotateNodes)
//   were measured and dropped: with the per-step rebuild below they changed no scene's time.
// - Proxies that move within a step are not reinserted: enlargeProxy sets the leaf's new box and
//   grows its ancestors to hold it, flagging the path, and rebuild then rebuilds the flagged part
//   top-down once per step, splitting at the middle of the boxes' centres along the wider axis
//   (Box2D v3's b2DynamicTree_EnlargeProxy and partial b2DynamicTree_Rebuild, median split). A
//   falling pile moves most of its proxies every step, and one rebuild over them costs less than
//   as many removals and insertions with their rotations.

/** The link of a node that has no parent, child or next free node. */
export const NULL_NODE = -1;
const INITIAL_CAPACITY = 16;
const INITIAL_STACK = 64;

/**
 * Called for each leaf whose box overlaps the query box. `proxyId` is the leaf, `userData` what
 * was stored with it. Return false to stop the query.
 */
export type TreeQueryCallback = (proxyId: number, userData: number) => boolean;

/**
 * Half the perimeter of the union of node box `o` (an offset into `boxes`) and a box (m). The tree
 * compares half-perimeters throughout: halving every cost orders the candidates exactly the same.
 */
function unionPerimeter(
  boxes: Float64Array,
  o: number,
  minX: number,
  minY: number,
  maxX: number,
  maxY: number,
): number {
  const wx = Math.max(boxes[o + 2]!, maxX) - Math.min(boxes[o]!, minX);
  const wy = Math.max(boxes[o + 3]!, maxY) - Math.min(boxes[o + 1]!, minY);
  return wx + wy;
}

/**
 * A dynamic AABB tree for broad-phase queries and ray casts. Proxy ids are node ids: stable
 * while the proxy lives, reused after it is destroyed. Boxes are in world coordinates (m).
 * The tree must not be modified from inside a query or ray-cast callback.
 */
export class DynamicTree {
  /** minX, minY, maxX, maxY per node (m). */
  /** @internal */
  boxes: Float64Array;
  /** @internal */
  child1: Int32Array;
  /** @internal */
  child2: Int32Array;
  /** Parent of a live node; next free node of a freed one. */
  /** @internal */
  parent: Int32Array;
  /** 0 for a leaf, 1 + the taller child's height for an internal node, -1 for a free node. */
  /** @internal */
  heights: Int32Array;
  /** @internal */
  userData: Int32Array;
  /** 1 on the ancestors of a leaf enlargeProxy moved, until rebuild; 0 elsewhere. */
  /** @internal */
  flags: Uint8Array;
  /** rebuild's items: the leaves and unchanged subtrees under the flagged nodes. */
  private items: Int32Array = new Int32Array(INITIAL_STACK);
  /** The proxies the last {@link overlapping} found, in its order (grown as needed). */
  /** @internal */
  hits: Int32Array = new Int32Array(INITIAL_STACK);
  /** @internal */
  capacity = 0;
  /** @internal */
  freeList = NULL_NODE;
  /** @internal */
  root = NULL_NODE;
  /** @internal */
  leafCount = 0;
  /** Traversal stack shared by query and rayCastTree; `stackTop` lets a callback query again. */
  /** @internal */
  stack: Int32Array;
  /** @internal */
  stackTop = 0;

  constructor(initialCapacity: number = INITIAL_CAPACITY) {
    const capacity = Math.max(2, initialCapacity | 0);
    this.capacity = 0;
    this.boxes = new Float64Array(0);
    this.child1 = new Int32Array(0);
    this.child2 = new Int32Array(0);
    this.parent = new Int32Array(0);
    this.heights = new Int32Array(0);
    this.userData = new Int32Array(0);
    this.flags = new Uint8Array(0);
    this.stack = new Int32Array(INITIAL_STACK);
    this.grow(capacity);
  }

  /** Number of live proxies (leaves). */
  get proxyCount(): number {
    return this.leafCount;
  }

  /**
   * Inserts a leaf holding `aabb` (m, world frame) exactly as given and returns its proxy id.
   * `userData` is an int32 the caller gets back in callbacks (the broad phase stores shape ids).
   */
  createProxy(aabb: AABB, userData: number): number {
    const leaf = this.allocateNode();
    const boxes = this.boxes;
    boxes[4 * leaf] = aabb.minX;
    boxes[4 * leaf + 1] = aabb.minY;
    boxes[4 * leaf + 2] = aabb.maxX;
    boxes[4 * leaf + 3] = aabb.maxY;
    this.userData[leaf] = userData;
    this.heights[leaf] = 0;
    this.insertLeaf(leaf);
    this.leafCount++;
    return leaf;
  }

  /** Removes a proxy; its id may be returned by a later createProxy. */
  destroyProxy(proxyId: number): void {
    this.removeLeaf(proxyId);
    this.freeNode(proxyId);
    this.leafCount--;
  }

  /** Replaces a proxy's box (m, world frame) and reinserts it where it now belongs. */
  moveProxy(proxyId: number, aabb: AABB): void {
    this.removeLeaf(proxyId);
    const boxes = this.boxes;
    boxes[4 * proxyId] = aabb.minX;
    boxes[4 * proxyId + 1] = aabb.minY;
    boxes[4 * proxyId + 2] = aabb.maxX;
    boxes[4 * proxyId + 3] = aabb.maxY;
    this.insertLeaf(proxyId);
  }

  /**
   * Gives a proxy a new box (m, world frame) without moving it in the tree: its ancestors grow to
   * hold the box, and the path up is flagged for {@link rebuild}. Queries stay exact meanwhile
   * (every node still holds its leaves); only the tree's quality waits for the rebuild. Only
   * enlargements may happen between this and the rebuild (no insertion or removal).
   */
  enlargeProxy(proxyId: number, aabb: AABB): void {
    const boxes = this.boxes;
    const flags = this.flags;
    const minX = aabb.minX;
    const minY = aabb.minY;
    const maxX = aabb.maxX;
    const maxY = aabb.maxY;
    const o = 4 * proxyId;
    boxes[o] = minX;
    boxes[o + 1] = minY;
    boxes[o + 2] = maxX;
    boxes[o + 3] = maxY;
    let growing = true;
    let node = this.parent[proxyId]!;
    while (node !== NULL_NODE) {
      if (growing) {
        const p = 4 * node;
        growing = false;
        if (minX < boxes[p]!) {
          boxes[p] = minX;
          growing = true;
        }
        if (minY < boxes[p + 1]!) {
          boxes[p + 1] = minY;
          growing = true;
        }
        if (maxX > boxes[p + 2]!) {
          boxes[p + 2] = maxX;
          growing = true;
        }
        if (maxY > boxes[p + 3]!) {
          boxes[p + 3] = maxY;
          growing = true;
        }
      }
      flags[node] = 1;
      node = this.parent[node]!;
    }
  }

  /**
   * Rebuilds every flagged node (see enlargeProxy) top-down over the leaves and unflagged
   * subtrees below them, and clears the flags. Does nothing when no proxy was enlarged.
   */
  rebuild(): void {
    const root = this.root;
    if (root === NULL_NODE || this.flags[root] === 0) return;
    // Two methods, not one: V8 compiled the gathering loop on the fly (on-stack replacement)
    // before the code after it had run, and then threw that compiled code away at the call
    // below on every step (compounds: 331 times in 400 steps).
    this.root = this.build(0, this.gatherRebuildItems(root), 0);
    this.parent[this.root] = NULL_NODE;
  }

  /** Frees the flagged nodes under `root` and lists the subtrees below them in items; returns their count. */
  private gatherRebuildItems(root: number): number {
    const flags = this.flags;
    let items = this.items;
    let count = 0;
    let stack = this.stack;
    let top = 0;
    stack[top++] = root;
    while (top > 0) {
      const node = stack[--top]!;
      if (flags[node] === 0 || this.heights[node] === 0) {
        if (count === items.length) items = this.items = growInt32(items, 2 * count);
        items[count++] = node;
        continue;
      }
      if (top + 2 > stack.length) {
        this.growStack();
        stack = this.stack;
      }
      stack[top++] = this.child1[node]!;
      stack[top++] = this.child2[node]!;
      // Its place is taken by one of the nodes the build allocates.
      this.freeNode(node);
    }
    return count;
  }

  /** Builds a subtree over items[start..end) and returns its root. */
  private build(start: number, end: number, depth: number): number {
    const items = this.items;
    if (end - start === 1) return items[start]!;
    let split = start + ((end - start) >> 1);
    // Past a depth no real scene reaches, halves by count: the depth stays logarithmic.
    if (depth < 64) {
      const boxes = this.boxes;
      // Bounds of the items' centres, doubled (min + max), which orders them the same.
      let loX = Infinity;
      let loY = Infinity;
      let hiX = -Infinity;
      let hiY = -Infinity;
      for (let k = start; k < end; k++) {
        const o = 4 * items[k]!;
        const cx = boxes[o]! + boxes[o + 2]!;
        const cy = boxes[o + 1]! + boxes[o + 3]!;
        if (cx < loX) loX = cx;
        if (cx > hiX) hiX = cx;
        if (cy < loY) loY = cy;
        if (cy > hiY) hiY = cy;
      }
      const alongX = hiX - loX >= hiY - loY;
      const pivot = alongX ? 0.5 * (loX + hiX) : 0.5 * (loY + hiY);
      const axis = alongX ? 0 : 1;
      let i = start;
      let j = end - 1;
      while (i <= j) {
        const o = 4 * items[i]! + axis;
        if (boxes[o]! + boxes[o + 2]! < pivot) {
          i++;
        } else {
          const t = items[i]!;
          items[i] = items[j]!;
          items[j] = t;
          j--;
        }
      }
      // All centres on one side (coincident boxes): halve by count.
      if (i > start && i < end) split = i;
    }
    const node = this.allocateNode();
    const left = this.build(start, split, depth + 1);
    const right = this.build(split, end, depth + 1);
    this.child1[node] = left;
    this.child2[node] = right;
    this.parent[left] = node;
    this.parent[right] = node;
    this.refit(node);
    return node;
  }

  /** The int32 stored with the proxy at creation. */
  getUserData(proxyId: number): number {
    return this.userData[proxyId]!;
  }

  /** Copies the proxy's stored box (m, world frame) into `out` and returns `out`. */
  getFatAABB(proxyId: number, out: AABB): AABB {
    const boxes = this.boxes;
    out.minX = boxes[4 * proxyId]!;
    out.minY = boxes[4 * proxyId + 1]!;
    out.maxX = boxes[4 * proxyId + 2]!;
    out.maxY = boxes[4 * proxyId + 3]!;
    return out;
  }

  /** Lower x bound of the proxy's stored box (m). */
  getMinX(proxyId: number): number {
    return this.boxes[4 * proxyId]!;
  }

  /** Lower y bound of the proxy's stored box (m). */
  getMinY(proxyId: number): number {
    return this.boxes[4 * proxyId + 1]!;
  }

  /** Upper x bound of the proxy's stored box (m). */
  getMaxX(proxyId: number): number {
    return this.boxes[4 * proxyId + 2]!;
  }

  /** Upper y bound of the proxy's stored box (m). */
  getMaxY(proxyId: number): number {
    return this.boxes[4 * proxyId + 3]!;
  }

  /**
   * True if `aabb` overlaps the box of any proxy: a query that stops at the first one. Its own
   * loop rather than query() with a callback: a third callback at query's call site made the
   * pair search slower (rain, 7 alternating runs: 14.59 -> 14.93 ms a step).
   */
  overlapsAny(aabb: AABB): boolean {
    if (this.root === NULL_NODE) return false;
    const minX = aabb.minX;
    const minY = aabb.minY;
    const maxX = aabb.maxX;
    const maxY = aabb.maxY;
    const boxes = this.boxes;
    const base = this.stackTop;
    let top = base;
    this.stack[top++] = this.root;
    while (top > base) {
      const node = this.stack[--top]!;
      const o = 4 * node;
      if (
        boxes[o]! > maxX ||
        minX > boxes[o + 2]! ||
        boxes[o + 1]! > maxY ||
        minY > boxes[o + 3]!
      ) {
        continue;
      }
      const first = this.child1[node]!;
      if (first === NULL_NODE) return true;
      if (top + 2 > this.stack.length) this.growStack();
      this.stack[top++] = this.child2[node]!;
      this.stack[top++] = first;
    }
    return false;
  }

  /**
   * Calls `callback` for every proxy whose box overlaps `aabb` (m, world frame; touching
   * counts), in a deterministic depth-first order, until it returns false.
   */
  query(aabb: AABB, callback: TreeQueryCallback): void {
    if (this.root === NULL_NODE) {
      return;
    }
    const minX = aabb.minX;
    const minY = aabb.minY;
    const maxX = aabb.maxX;
    const maxY = aabb.maxY;
    const base = this.stackTop;
    let top = base;
    this.stack[top++] = this.root;
    while (top > base) {
      const node = this.stack[--top]!;
      const boxes = this.boxes;
      const o = 4 * node;
      if (
        boxes[o]! > maxX ||
        minX > boxes[o + 2]! ||
        boxes[o + 1]! > maxY ||
        minY > boxes[o + 3]!
      ) {
        continue;
      }
      const first = this.child1[node]!;
      if (first === NULL_NODE) {
        this.stackTop = top;
        const proceed = callback(node, this.userData[node]!);
        this.stackTop = base;
        if (!proceed) {
          return;
        }
      } else {
        if (top + 2 > this.stack.length) {
          this.growStack();
        }
        this.stack[top++] = this.child2[node]!;
        this.stack[top++] = first;
      }
    }
  }

  /**
   * Lists in {@link hits} every proxy whose box overlaps the box at double `at` of `box` (min x,
   * min y, max x, max y; m, world frame; touching counts), in {@link query}'s order, and returns
   * their count. No callback: the broad phase's pair search reads the list (issue #30: in tumbler
   * the query with its callback chain was 14 % of a step). The box comes as an array and an
   * offset, not four numbers: doubles passed to a call V8 does not inline are boxed on the heap. A child is tested before it is pushed, which visits the same leaves in the same
   * depth-first order with fewer stack moves.
   */
  overlapping(box: Float64Array, at: number): number {
    const root = this.root;
    if (root === NULL_NODE) return 0;
    const minX = box[at]!;
    const minY = box[at + 1]!;
    const maxX = box[at + 2]!;
    const maxY = box[at + 3]!;
    const boxes = this.boxes;
    const child1 = this.child1;
    const child2 = this.child2;
    let o = 4 * root;
    if (boxes[o]! > maxX || minX > boxes[o + 2]! || boxes[o + 1]! > maxY || minY > boxes[o + 3]!) {
      return 0;
    }
    let hits = this.hits;
    let count = 0;
    let stack = this.stack;
    const base = this.stackTop;
    let top = base;
    stack[top++] = root;
    while (top > base) {
      const node = stack[--top]!;
      const a = child1[node]!;
      if (a === NULL_NODE) {
        if (count === hits.length) hits = this.hits = growInt32(hits, 2 * count);
        hits[count++] = node;
        continue;
      }
      if (top + 2 > stack.length) {
        this.growStack();
        stack = this.stack;
      }
      const b = child2[node]!;
      o = 4 * b;
      if (!(
        boxes[o]! > maxX ||
        minX > boxes[o + 2]! ||
        boxes[o + 1]! > maxY ||
        minY > boxes[o + 3]!
      )) {
        stack[top++] = b;
      }
      o = 4 * a;
      if (!(
        boxes[o]! > maxX ||
        minX > boxes[o + 2]! ||
        boxes[o + 1]! > maxY ||
        minY > boxes[o + 3]!
      )) {
        stack[top++] = a;
      }
    }
    return count;
  }

  /** Half the node box's perimeter (see unionPerimeter). */
  private perimeter(node: number): number {
    const o = 4 * node;
    const boxes = this.boxes;
    return boxes[o + 2]! - boxes[o]! + (boxes[o + 3]! - boxes[o + 1]!);
  }

  private grow(newCapacity: number): void {
    const old = this.capacity;
    const boxes = new Float64Array(4 * newCapacity);
    boxes.set(this.boxes);
    this.boxes = boxes;
    this.child1 = growInt32(this.child1, newCapacity);
    this.child2 = growInt32(this.child2, newCapacity);
    this.parent = growInt32(this.parent, newCapacity);
    this.heights = growInt32(this.heights, newCapacity);
    this.userData = growInt32(this.userData, newCapacity);
    // No flag is pending when the tree grows: nothing is inserted between enlargeProxy and rebuild.
    this.flags = new Uint8Array(newCapacity);
    // Thread the new nodes onto the free list in ascending order, ahead of any older free nodes.
    for (let node = old; node < newCapacity; node++) {
      this.parent[node] = node + 1 < newCapacity ? node + 1 : this.freeList;
      this.heights[node] = -1;
      this.child1[node] = NULL_NODE;
      this.child2[node] = NULL_NODE;
    }
    this.freeList = old;
    this.capacity = newCapacity;
  }

  /** @internal */
  growStack(): void {
    const stack = new Int32Array(2 * this.stack.length);
    stack.set(this.stack);
    this.stack = stack;
  }

  private allocateNode(): number {
    if (this.freeList === NULL_NODE) {
      this.grow(2 * this.capacity);
    }
    const node = this.freeList;
    this.freeList = this.parent[node]!;
    this.parent[node] = NULL_NODE;
    this.child1[node] = NULL_NODE;
    this.child2[node] = NULL_NODE;
    this.heights[node] = 0;
    this.userData[node] = -1;
    return node;
  }

  private freeNode(node: number): void {
    this.flags[node] = 0;
    this.parent[node] = this.freeList;
    this.heights[node] = -1;
    this.child1[node] = NULL_NODE;
    this.child2[node] = NULL_NODE;
    this.freeList = node;
  }

  /**
   * Branch-and-bound search for the sibling that minimises the cost of inserting `leaf` L
   * (Bittner et al. 2015, section 3). Making node X the sibling of L costs
   *   cost(X) = perimeter(X ∪ L) + Σ over ancestors P of X of [perimeter(P ∪ L) - perimeter(P)]
   * (the new parent plus the growth of every ancestor). Every node below an internal node C
   * pays C's growth and at least perimeter(L) for its own new parent, so the subtree of C is
   * searched only while cost(C) - perimeter(C) + perimeter(L) can beat the best cost found.
   * The search follows one path, into the child with the lower bound, instead of the paper's
   * priority queue: the same trade Box2D v3 makes, giving nearly the same trees with no queue.
   */
  private findBestSibling(leaf: number): number {
    const boxes = this.boxes;
    const lo = 4 * leaf;
    const lMinX = boxes[lo]!;
    const lMinY = boxes[lo + 1]!;
    const lMaxX = boxes[lo + 2]!;
    const lMaxY = boxes[lo + 3]!;
    const leafPerimeter = lMaxX - lMinX + (lMaxY - lMinY);
    const leafCenterX = lMinX + lMaxX;
    const leafCenterY = lMinY + lMaxY;

    let node = this.root;
    const o = 4 * node;
    let nodePerimeter = this.perimeter(node);
    let direct = unionPerimeter(boxes, o, lMinX, lMinY, lMaxX, lMaxY);
    let inherited = 0;
    let best = node;
    let bestCost = direct;

    while (this.child1[node] !== NULL_NODE) {
      // The cost of the current node as sibling is inherited + direct, already compared when
      // the node was reached. Going below it, every descendant also pays the growth of this node.
      inherited += direct - nodePerimeter;

      const a = this.child1[node]!;
      const b = this.child2[node]!;
      const ao = 4 * a;
      const bo = 4 * b;
      const directA = unionPerimeter(boxes, ao, lMinX, lMinY, lMaxX, lMaxY);
      const directB = unionPerimeter(boxes, bo, lMinX, lMinY, lMaxX, lMaxY);
      const costA = inherited + directA;
      const costB = inherited + directB;
      if (costA < bestCost) {
        best = a;
        bestCost = costA;
      }
      if (costB < bestCost) {
        best = b;
        bestCost = costB;
      }
      const isLeafA = this.child1[a] === NULL_NODE;
      const isLeafB = this.child1[b] === NULL_NODE;
      // Below child C every candidate pays at least inherited + growth of C + perimeter(L).
      const perimeterA = isLeafA ? 0 : this.perimeter(a);
      const perimeterB = isLeafB ? 0 : this.perimeter(b);
      const lowerA = isLeafA ? Infinity : inherited + directA - perimeterA + leafPerimeter;
      const lowerB = isLeafB ? Infinity : inherited + directB - perimeterB + leafPerimeter;
      if (bestCost <= lowerA && bestCost <= lowerB) {
        break;
      }
      let goA: boolean;
      if (lowerA === lowerB) {
        // Tie (common when L lies inside both): descend towards the nearer centre.
        const ax = boxes[ao]! + boxes[ao + 2]! - leafCenterX;
        const ay = boxes[ao + 1]! + boxes[ao + 3]! - leafCenterY;
        const bx = boxes[bo]! + boxes[bo + 2]! - leafCenterX;
        const by = boxes[bo + 1]! + boxes[bo + 3]! - leafCenterY;
        goA = ax * ax + ay * ay <= bx * bx + by * by;
      } else {
        goA = lowerA < lowerB;
      }
      if (goA) {
        node = a;
        nodePerimeter = perimeterA;
        direct = directA;
      } else {
        node = b;
        nodePerimeter = perimeterB;
        direct = directB;
      }
    }
    return best;
  }

  private insertLeaf(leaf: number): void {
    if (this.root === NULL_NODE) {
      this.root = leaf;
      this.parent[leaf] = NULL_NODE;
      return;
    }
    const sibling = this.findBestSibling(leaf);
    const oldParent = this.parent[sibling]!;
    const newParent = this.allocateNode();
    this.parent[newParent] = oldParent;
    this.child1[newParent] = sibling;
    this.child2[newParent] = leaf;
    this.parent[sibling] = newParent;
    this.parent[leaf] = newParent;
    if (oldParent === NULL_NODE) {
      this.root = newParent;
    } else if (this.child1[oldParent] === sibling) {
      this.child1[oldParent] = newParent;
    } else {
      this.child2[oldParent] = newParent;
    }
    this.refitAndBalanceFrom(newParent);
  }

  private removeLeaf(leaf: number): void {
    if (leaf === this.root) {
      this.root = NULL_NODE;
      return;
    }
    const oldParent = this.parent[leaf]!;
    const grandParent = this.parent[oldParent]!;
    const sibling =
      this.child1[oldParent] === leaf ? this.child2[oldParent]! : this.child1[oldParent]!;
    this.freeNode(oldParent);
    this.parent[leaf] = NULL_NODE;
    if (grandParent === NULL_NODE) {
      this.root = sibling;
      this.parent[sibling] = NULL_NODE;
      return;
    }
    if (this.child1[grandParent] === oldParent) {
      this.child1[grandParent] = sibling;
    } else {
      this.child2[grandParent] = sibling;
    }
    this.parent[sibling] = grandParent;
    this.refitAndBalanceFrom(grandParent);
  }

  /** Recomputes boxes and heights from `node` to the root, balancing each ancestor on the way. */
  private refitAndBalanceFrom(node: number): void {
    let index = node;
    while (index !== NULL_NODE) {
      this.refit(index);
      index = this.balance(index);
      index = this.parent[index]!;
    }
  }

  /** Sets an internal node's box to the union of its children and its height from theirs. */
  private refit(node: number): void {
    const a = this.child1[node]!;
    const b = this.child2[node]!;
    const boxes = this.boxes;
    const o = 4 * node;
    const ao = 4 * a;
    const bo = 4 * b;
    boxes[o] = Math.min(boxes[ao]!, boxes[bo]!);
    boxes[o + 1] = Math.min(boxes[ao + 1]!, boxes[bo + 1]!);
    boxes[o + 2] = Math.max(boxes[ao + 2]!, boxes[bo + 2]!);
    boxes[o + 3] = Math.max(boxes[ao + 3]!, boxes[bo + 3]!);
    const ha = this.heights[a]!;
    const hb = this.heights[b]!;
    this.heights[node] = 1 + (ha > hb ? ha : hb);
  }

  /**
   * Balances internal node `a` (already refitted) and returns the node now at its place: a child
   * more than one level taller than its sibling is promoted (Box2D v2's AVL-like balance).
   */
  private balance(a: number): number {
    const b = this.child1[a]!;
    const c = this.child2[a]!;
    const hb = this.heights[b]!;
    const hc = this.heights[c]!;
    if (hc - hb > 1) return this.promote(a, c, b);
    if (hb - hc > 1) return this.promote(a, b, c);
    return a;
  }

  /**
   * Promotes `tall`, a child of `a` at least two levels taller than its sibling `short`, to
   * `a`'s place; `a` keeps `short` and takes the shorter of `tall`'s children, `tall` keeps the
   * taller one. Returns `tall`.
   */
  private promote(a: number, tall: number, short: number): number {
    const f = this.child1[tall]!;
    const g = this.child2[tall]!;
    const aParent = this.parent[a]!;

    this.parent[tall] = aParent;
    if (aParent === NULL_NODE) {
      this.root = tall;
    } else if (this.child1[aParent] === a) {
      this.child1[aParent] = tall;
    } else {
      this.child2[aParent] = tall;
    }

    const keep = this.heights[f]! >= this.heights[g]! ? f : g;
    const give = keep === f ? g : f;
    this.child1[a] = short;
    this.child2[a] = give;
    this.parent[give] = a;
    this.child1[tall] = a;
    this.child2[tall] = keep;
    this.parent[a] = tall;
    this.refit(a);
    this.refit(tall);
    return tall;
  }
}

function growInt32(array: Int32Array, length: number): Int32Array {
  const grown = new Int32Array(length);
  grown.set(array);
  return grown;
}
