import { AABB_MARGIN } from '../core/constants.ts';
import { AABB } from '../geometry/aabb.ts';
import type { RayInput } from '../geometry/ray.ts';
import { DynamicTree } from './dynamic-tree.ts';
import { filterRowsAllow } from './pair-filter.ts';
import type { PairSet } from './pair-set.ts';
import type { TreeQueryCallback } from './dynamic-tree.ts';
import { rayCastTree, type TreeRayCastCallback } from './dynamic-tree-ray-cast.ts';
import type { TreeState } from './dynamic-tree-state.ts';

// The broad phase finds candidate shape pairs from fattened boxes, one DynamicTree per body
// type as in Box2D v3: static shapes never need to find each other, so a moved dynamic proxy
// queries all three trees while a moved static or kinematic proxy queries only the dynamic
// tree, and the large static tree is never searched on behalf of static or kinematic shapes.
//
// Fat boxes (tight box + AABB_MARGIN) let a shape move a little without touching the tree;
// only shapes that leave their fat box are reinserted and buffered as moved, and only moved
// proxies look for new pairs.

/** A broad phase's state as plain data: the static, kinematic and dynamic trees, and moved keys. */
export interface BroadPhaseState {
  readonly trees: readonly [TreeState, TreeState, TreeState];
  readonly moved: readonly number[];
}

/** Body type of a proxy: 0 static, 1 kinematic, 2 dynamic. */
export type ProxyType = 0 | 1 | 2;

/** Receives a new candidate pair of shapes, shapeIdA < shapeIdB. */
export type PairCallback = (shapeIdA: number, shapeIdB: number) => void;

const STATIC = 0;
const DYNAMIC = 2;
export const NULL_KEY = -1;

/** Packs a tree proxy id and a proxy type into a proxy key. */
function makeProxyKey(proxyId: number, type: number): number {
  return (proxyId << 2) | type;
}

/**
 * Broad phase over three dynamic AABB trees (static, kinematic, dynamic). Proxies are named by
 * proxy keys, `(treeProxyId << 2) | type`, non-negative int32s. Boxes are in metres, world frame.
 * Not re-entrant: do not create, destroy or move proxies from inside its callbacks.
 */
export class BroadPhase {
  /** @internal */
  readonly trees: readonly [DynamicTree, DynamicTree, DynamicTree] = [
    new DynamicTree(),
    new DynamicTree(),
    new DynamicTree(),
  ];
  /** Proxy keys buffered as moved since the last updatePairs; NULL_KEY marks a destroyed one. */
  /** @internal */
  moveBuffer = new Int32Array(64);
  /** @internal */
  moveCount = 0;
  /** Index in moveBuffer per proxy key, or -1 when the proxy is not buffered. */
  /** @internal */
  movedIndex = new Int32Array(64).fill(-1);

  // State of the current query or rayCast, read by the pre-bound tree callbacks below so that no
  // closure is created per call.
  private currentType = 0;
  private userQuery: TreeQueryCallback | null = null;
  private userRayCast: TreeRayCastCallback | null = null;
  private isQueryStopped = false;
  /**
   * While true, moved kinematic and dynamic proxies keep their place in their tree, which only
   * grows to hold them (DynamicTree.enlargeProxy), until {@link rebuildMoved}: a step moves many
   * proxies at once, and one rebuild costs less than reinserting each. Nothing may be inserted
   * into or removed from those trees meanwhile.
   */
  deferring = false;
  private readonly scratchBox = new AABB();

  private readonly forwardQueryCallback: TreeQueryCallback = (proxyId, shapeId) => {
    const proceed = this.userQuery!(makeProxyKey(proxyId, this.currentType), shapeId);
    if (!proceed) {
      this.isQueryStopped = true;
    }
    return proceed;
  };
  private readonly forwardRayCastCallback: TreeRayCastCallback = (input, proxyId, shapeId) =>
    this.userRayCast!(input, makeProxyKey(proxyId, this.currentType), shapeId);

  /** Number of live proxies in all three trees. */
  get proxyCount(): number {
    return this.trees[0].proxyCount + this.trees[1].proxyCount + this.trees[2].proxyCount;
  }

  /** Number of proxies buffered as moved and not yet processed by updatePairs. */
  get movedProxyCount(): number {
    return this.moveCount;
  }

  /**
   * Adds a proxy for shape `shapeId` (an int32 the callbacks get back) with the shape's tight
   * box `aabb` (m, world frame) and returns its proxy key. Kinematic and dynamic boxes are
   * fattened by AABB_MARGIN; static ones are stored tight, since they rarely move. The proxy is
   * buffered as moved, so the next updatePairs finds its pairs, unless it is static and
   * `forcePairCreation` is false (a static shape added at start-up is found by the dynamic
   * shapes' own queries).
   */
  createProxy(aabb: AABB, type: ProxyType, shapeId: number, forcePairCreation: boolean): number {
    const stored = type === STATIC ? aabb : this.fatten(aabb);
    const proxyKey = makeProxyKey(this.trees[type].createProxy(stored, shapeId), type);
    if (type !== STATIC || forcePairCreation) {
      this.bufferMove(proxyKey);
    }
    return proxyKey;
  }

  /** Removes a proxy and drops it from the move buffer. Its key may be reused. */
  destroyProxy(proxyKey: number): void {
    this.unbufferMove(proxyKey);
    this.trees[proxyKey & 3]!.destroyProxy(proxyKey >> 2);
  }

  /**
   * Updates a proxy with its shape's new tight box `aabb` (m, world frame). If the box still
   * lies inside the stored fat box nothing changes and this returns false; otherwise the fat
   * box becomes `aabb` plus AABB_MARGIN (static proxies: `aabb` itself), the proxy is buffered
   * as moved and this returns true.
   */
  moveProxy(proxyKey: number, aabb: AABB): boolean {
    const type = proxyKey & 3;
    const tree = this.trees[type]!;
    const proxyId = proxyKey >> 2;
    if (
      tree.getMinX(proxyId) <= aabb.minX &&
      tree.getMinY(proxyId) <= aabb.minY &&
      aabb.maxX <= tree.getMaxX(proxyId) &&
      aabb.maxY <= tree.getMaxY(proxyId)
    ) {
      return false;
    }
    const box = type === STATIC ? aabb : this.fatten(aabb);
    if (this.deferring && type !== STATIC) tree.enlargeProxy(proxyId, box);
    else tree.moveProxy(proxyId, box);
    this.bufferMove(proxyKey);
    return true;
  }

  /** Rebuilds what moved since `deferring` was set, and clears it. */
  rebuildMoved(): void {
    this.deferring = false;
    this.trees[1].rebuild();
    this.trees[2].rebuild();
  }

  /**
   * Marks a proxy as moved so that the next updatePairs looks for its pairs, for example after
   * a body wakes up or changes its filter. Buffering twice has no further effect.
   */
  bufferMove(proxyKey: number): void {
    if (proxyKey >= this.movedIndex.length) {
      let length = this.movedIndex.length;
      while (length <= proxyKey) {
        length *= 2;
      }
      const grown = new Int32Array(length).fill(-1);
      grown.set(this.movedIndex);
      this.movedIndex = grown;
    }
    if (this.movedIndex[proxyKey] !== -1) {
      return;
    }
    if (this.moveCount === this.moveBuffer.length) {
      const grown = new Int32Array(2 * this.moveBuffer.length);
      grown.set(this.moveBuffer);
      this.moveBuffer = grown;
    }
    this.movedIndex[proxyKey] = this.moveCount;
    this.moveBuffer[this.moveCount++] = proxyKey;
  }

  /** Copies the proxy's stored (fat) box (m, world frame) into `out` and returns `out`. */
  getFatAABB(proxyKey: number, out: AABB): AABB {
    return this.trees[proxyKey & 3]!.getFatAABB(proxyKey >> 2, out);
  }

  /** The shape id given at creation. */
  getShapeId(proxyKey: number): number {
    return this.trees[proxyKey & 3]!.getUserData(proxyKey >> 2);
  }

  /** The proxy's body type, as given at creation. */
  getType(proxyKey: number): ProxyType {
    return (proxyKey & 3) as ProxyType;
  }

  /**
   * Reports every pair of overlapping fat boxes that involves a proxy moved since the last
   * call and at least one dynamic proxy, exactly once, as (smaller shape id, larger shape id);
   * then empties the move buffer. The order follows the move buffer, then each tree's
   * traversal, so it is the same for the same sequence of calls. Not reported: pairs the shapes'
   * rows of `filters` forbid (pair-filter.ts: sensors, filter bits and groups), checked first,
   * from numbers, and then pairs of shape ids in `known` (those that already have a contact;
   * Box2D v3 looks its pair set up in the same place): most pairs found are one or the other.
   */
  updatePairs(onPair: PairCallback, known: PairSet, filters: Int32Array): void {
    this.queryMovedProxies(onPair, known, filters);
    this.clearMoveBuffer();
  }

  // The loops live in methods of their own, with nothing after them: V8 compiles a long loop on
  // stack replacement before the code after it has run, and that code then lacked type feedback
  // and deoptimised on every step.
  private queryMovedProxies(onPair: PairCallback, known: PairSet, filters: Int32Array): void {
    const trees = this.trees;
    for (let i = 0; i < this.moveCount; i++) {
      const proxyKey = this.moveBuffer[i]!;
      if (proxyKey === NULL_KEY) {
        continue;
      }
      const type = proxyKey & 3;
      const tree = trees[type]!;
      // The query box is read where it lives (the moved proxy's row of its tree's boxes): four
      // doubles passed as arguments were boxed on the heap at each call (~16 KB a tumbler step).
      const boxes = tree.boxes;
      const at = 4 * (proxyKey >> 2);
      const shapeId = tree.getUserData(proxyKey >> 2);
      if (type === DYNAMIC) {
        this.reportPairs(onPair, known, filters, trees[0], 0, proxyKey, shapeId, boxes, at);
        this.reportPairs(onPair, known, filters, trees[1], 1, proxyKey, shapeId, boxes, at);
      }
      this.reportPairs(onPair, known, filters, trees[2], DYNAMIC, proxyKey, shapeId, boxes, at);
    }
  }

  /**
   * Reports the pairs of moved proxy `queryKey` (shape `queryShapeId`, fat box at `at` in `boxes`) with the
   * proxies of `tree` (type `type`) its box overlaps, in the tree's query order: the list
   * DynamicTree.overlapping makes, read here with no callback per leaf.
   */
  private reportPairs(
    onPair: PairCallback,
    known: PairSet,
    filters: Int32Array,
    tree: DynamicTree,
    type: number,
    queryKey: number,
    queryShapeId: number,
    boxes: Float64Array,
    at: number,
  ): void {
    const count = tree.overlapping(boxes, at);
    if (count === 0) return;
    const hits = tree.hits;
    const userData = tree.userData;
    const movedIndex = this.movedIndex;
    for (let k = 0; k < count; k++) {
      const proxyId = hits[k]!;
      const proxyKey = makeProxyKey(proxyId, type);
      if (proxyKey === queryKey) continue;
      // When both proxies moved, both queries find the pair; only the one with the larger key
      // reports it (Box2D's rule), which keeps each pair to one report.
      if (proxyKey > queryKey && proxyKey < movedIndex.length && movedIndex[proxyKey] !== -1) {
        continue;
      }
      const shapeId = userData[proxyId]!;
      const low = shapeId < queryShapeId ? shapeId : queryShapeId;
      const high = shapeId < queryShapeId ? queryShapeId : shapeId;
      if (filterRowsAllow(filters, low, high) && !known.hasOrdered(low, high)) onPair(low, high);
    }
  }

  private clearMoveBuffer(): void {
    for (let i = 0; i < this.moveCount; i++) {
      const proxyKey = this.moveBuffer[i]!;
      if (proxyKey !== NULL_KEY) {
        this.movedIndex[proxyKey] = -1;
      }
    }
    this.moveCount = 0;
  }

  /** True if `aabb` (m, world frame) overlaps the fat box of any static proxy. */
  overlapsStatic(aabb: AABB): boolean {
    return this.trees[STATIC].overlapsAny(aabb);
  }

  /**
   * Calls `callback(proxyKey, shapeId)` for every proxy in the three trees whose fat box
   * overlaps `aabb` (m, world frame), static tree first, until it returns false. With
   * `staticOnly`, only the static tree is searched (a non-bullet's sweep: Box2D v3's order).
   */
  query(aabb: AABB, callback: TreeQueryCallback, staticOnly = false): void {
    const savedCallback = this.userQuery;
    const savedType = this.currentType;
    const savedStopped = this.isQueryStopped;
    this.userQuery = callback;
    this.isQueryStopped = false;
    const types = staticOnly ? 1 : 3;
    for (let type = 0; type < types && !this.isQueryStopped; type++) {
      this.currentType = type;
      this.trees[type]!.query(aabb, this.forwardQueryCallback);
    }
    this.userQuery = savedCallback;
    this.currentType = savedType;
    this.isQueryStopped = savedStopped;
  }

  /**
   * Casts a ray through the three trees, calling `callback(input, proxyKey, shapeId)` for
   * every proxy whose fat box the ray may cross (see TreeRayCastCallback). A clip made in one
   * tree also clips the ray in the trees searched after it; returning 0 stops the whole cast.
   */
  rayCast(input: RayInput, callback: TreeRayCastCallback): void {
    const savedCallback = this.userRayCast;
    const savedType = this.currentType;
    this.userRayCast = callback;
    for (let type = 0; type < 3; type++) {
      this.currentType = type;
      rayCastTree(this.trees[type]!, input, this.forwardRayCastCallback);
      if (input.maxFraction === 0) {
        break;
      }
    }
    this.userRayCast = savedCallback;
    this.currentType = savedType;
  }

  private unbufferMove(proxyKey: number): void {
    if (proxyKey >= this.movedIndex.length) {
      return;
    }
    const index = this.movedIndex[proxyKey]!;
    if (index !== -1) {
      this.moveBuffer[index] = NULL_KEY;
      this.movedIndex[proxyKey] = -1;
    }
  }

  /** Writes `aabb` grown by AABB_MARGIN on every side into the scratch box and returns it. */
  private fatten(aabb: AABB): AABB {
    const fat = this.scratchBox;
    fat.minX = aabb.minX - AABB_MARGIN;
    fat.minY = aabb.minY - AABB_MARGIN;
    fat.maxX = aabb.maxX + AABB_MARGIN;
    fat.maxY = aabb.maxY + AABB_MARGIN;
    return fat;
  }
}
