import { releaseFrom } from '../core/release.ts';
import { PairSet } from '../collision/pair-set.ts';
import { AABB_MARGIN, LINEAR_SLOP, SPECULATIVE_DISTANCE } from '../core/constants.ts';
import type { Body } from './body.ts';
import type { BodyStore } from './body-memory.ts';
import { canCollide, initContactSlot, shouldSwap } from './contact.ts';
import type { ContactEdges } from './contact-edges.ts';
import {
  CACHE,
  CONTACT_STRIDE,
  ContactData,
  HAS_CACHE,
  NORMAL_X,
  NORMAL_Y,
  P_MAX_NORMAL_IMPULSE,
  P_SEPARATION,
  P_STEP_NORMAL_IMPULSE,
  P_STEP_TANGENT_IMPULSE,
  P_X,
  P_Y,
  POINT_COUNT,
  POINT_STRIDE,
  POINTS,
} from './contact-data.ts';
import type { Islands } from './island.ts';
import { jointPreventsCollision } from './joints/joint.ts';
import type { Shape } from './shape.ts';
import type { ShapeTable } from './shape-table.ts';
import {
  BODIES,
  CONTACT_DATA,
  NARROW_PHASE_SCRATCH,
  SHAPE_GEOMETRY,
  type SolverMemory,
} from './solver-memory.ts';

// Manifolds are reused while B moved less than this relative to A (m). Motion along the normal is
// measured exactly on reuse; only sliding along the surface can leave a contact point behind its
// true place, by at most this much: half the slop, below anything the solver resolves.
const REUSE_TOLERANCE = 0.5 * LINEAR_SLOP;
const REUSE_TOLERANCE_SQUARED = REUSE_TOLERANCE * REUSE_TOLERANCE;

// A contact whose fat boxes parted lives on while its shapes' tight boxes are no farther apart
// than this (m) along either axis. Fat boxes reach AABB_MARGIN past their shapes, so shapes within two margins
// can meet again by re-fattening alone; a turning box's own box also swells and shrinks from step
// to step. Counted in tumbler's first 150 steps: keeping to two margins, 62,000 of the 124,000
// contacts made were pairs ended the step before, at tight gaps of 0.21-0.29 m; keeping to four,
// 358 of 36,000. Per step over 300 steps (npm run bench:churn): 1,106 made before, 152 after.
const KEEP_GAP = 4 * AABB_MARGIN;

// Pairs reserved per shape before a step finds its pairs: a box in a stack or a pile touches
// about three others (large_pyramid: 14,950 contacts for 5,050 boxes). More still fit: the set
// then grows by doubling.
const PAIRS_PER_SHAPE = 3;

/**
 * Owns the contacts: creates one when the broad phase reports a new pair of overlapping fat boxes,
 * updates every active one in the narrow phase, and destroys it when the boxes part and the shapes
 * are more than KEEP_GAP apart. A contact is a slot of flat memory, nothing else: its numbers,
 * bodies, shapes and pair kind in {@link ContactData}, its place in its bodies' contact lists in
 * {@link ContactEdges}. Making one fills a slot and links two edges; ending one unlinks them and
 * moves the last slot into its place: no object is made, pooled or rewired.
 */
export class ContactManager {
  /** Contacts alive: slots 0 to count - 1, in creation order (removal moves the last one in). */
  count = 0;
  /** The contacts' numbers, bodies, shapes and pair kinds, by slot. */
  readonly slots: ContactData;
  /**
   * Shape pairs that started touching during the last narrow phase (the first `beganCount`), by
   * shape id: A at 2 i, B at 2 i + 1 ({@link beganShapeA}, {@link beganShapeB}). Sized with the
   * contacts, so a pile's first step (15,000 begins) grows no array one begin at a time.
   */
  beganIds: Int32Array = new Int32Array(64);
  beganCount = 0;
  /** Shape pairs that stopped touching during the last narrow phase (or were destroyed touching). */
  readonly endedA: Shape[] = [];
  readonly endedB: Shape[] = [];
  endedCount = 0;
  /** Contacts made and destroyed since the world was created (the bench's churn counters). */
  made = 0;
  destroyed = 0;
  private readonly pairs = new PairSet();
  /**
   * Pairs accepted by addPair, not yet contacts (the first `pendingCount`, already ordered), by
   * shape id: A at 2 n, B at 2 n + 1. Reserved with the pair set before the broad phase reports
   * (reservePairs), so a world's first step does not grow it pair by pair.
   */
  private pendingIds = new Int32Array(64);
  private pendingCount = 0;

  /** Contacts there will be once createPending has run. */
  get countWithPending(): number {
    return this.count + this.pendingCount;
  }
  /** The bodies' numbers (body-memory.ts), which the narrow phase's gates read in place. */
  private readonly bodyStore: BodyStore;

  constructor(
    private readonly islands: Islands,
    private readonly memory: SolverMemory,
    private readonly table: ShapeTable,
    /** Each body's contact list (shared with the island search). */
    readonly edges: ContactEdges,
    /** The world's bodies by world index, and its shapes by id: what a slot's numbers name. */
    private readonly bodies: readonly Body[],
    private readonly shapes: readonly (Shape | null)[],
  ) {
    this.slots = new ContactData(memory);
    this.bodyStore = memory.bodyStore;
  }

  /** Body A of the contact in `slot`. */
  bodyA(slot: number): Body {
    return this.bodies[this.slots.bodies[2 * slot]!]!;
  }

  /** Body B of the contact in `slot`. */
  bodyB(slot: number): Body {
    return this.bodies[this.slots.bodies[2 * slot + 1]!]!;
  }

  /** Shape A of the contact in `slot`. */
  shapeA(slot: number): Shape {
    return this.shapes[this.slots.shapes[2 * slot]!]!;
  }

  /** Shape B of the contact in `slot`. */
  shapeB(slot: number): Shape {
    return this.shapes[this.slots.shapes[2 * slot + 1]!]!;
  }

  /** Shape A of the `i`-th begin of the last narrow phase. */
  beganShapeA(i: number): Shape {
    return this.shapes[this.beganIds[2 * i]!]!;
  }

  /** Shape B of the `i`-th begin of the last narrow phase. */
  beganShapeB(i: number): Shape {
    return this.shapes[this.beganIds[2 * i + 1]!]!;
  }

  /** Whether the contact in `slot` touches: its slot holds manifold points (contact.ts). */
  touching(slot: number): boolean {
    return this.slots.data[slot * CONTACT_STRIDE + POINT_COUNT] !== 0;
  }

  /**
   * Broad-phase callback: a pair of overlapping fat boxes, by shape id. Most pairs reported
   * already have a contact (a moved box overlaps what it overlapped before): one hash lookup
   * settles those before any shape or body is read.
   */
  addPair(shapeIdA: number, shapeIdB: number, shapesById: readonly (Shape | null)[]): void {
    // Sensors never make contacts, and filters may forbid the pair (filtersCollide in filter.ts,
    // from the shape table: offsets in shape-table.ts). Checked first, from numbers: in a ragdoll
    // rain nine reports in ten are pairs the filters forbid (bones of one ragdoll, feet), and they
    // are reported again whenever a box moves. A pair with a contact always passes: a filter
    // change destroys the contacts it forbids.
    const f = this.table.filters;
    const fa = shapeIdA * 4;
    const fb = shapeIdB * 4;
    if (f[fa + 3] !== 0 || f[fb + 3] !== 0) return;
    const group = f[fa + 2]!;
    if (group === f[fb + 2] && group !== 0) {
      if (group < 0) return;
    } else if ((f[fa]! & f[fb + 1]!) === 0 || (f[fb]! & f[fa + 1]!) === 0) {
      return;
    }
    if (this.pairs.has(shapeIdA, shapeIdB)) return;
    const shapeA = shapesById[shapeIdA]!;
    const shapeB = shapesById[shapeIdB]!;
    const bodyA = shapeA.body;
    const bodyB = shapeB.body;
    if (bodyA === bodyB) return;
    // Only pairs where something can be pushed matter.
    if (bodyA.type !== 'dynamic' && bodyB.type !== 'dynamic') return;
    if (!canCollide(shapeA, shapeB)) return;
    if (jointPreventsCollision(bodyA, bodyB)) return;
    this.pairs.add(shapeA.id, shapeB.id);
    // Created in createPending, once the broad phase has reported every pair: the slots then
    // grow once for all of them (a pile's first step finds 15,000 pairs).
    const n = this.pendingCount++;
    if (2 * n + 2 > this.pendingIds.length)
      this.pendingIds = grownInt32(this.pendingIds, 2 * n + 2);
    const swap = shouldSwap(shapeA, shapeB);
    this.pendingIds[2 * n] = swap ? shapeIdB : shapeIdA;
    this.pendingIds[2 * n + 1] = swap ? shapeIdA : shapeIdB;
  }

  /**
   * Makes room in the pair set for PAIRS_PER_SHAPE pairs per shape id in use, before the broad
   * phase reports pairs: a world's first step then adds them all without growing the set.
   */
  reservePairs(shapeIds: number): void {
    this.pairs.reserve(PAIRS_PER_SHAPE * shapeIds);
    const pending = 2 * PAIRS_PER_SHAPE * shapeIds;
    if (pending > this.pendingIds.length) this.pendingIds = grownInt32(this.pendingIds, pending);
  }

  /** Creates the contacts of the pairs addPair accepted since the last call, in that order. */
  createPending(): void {
    const count = this.pendingCount;
    if (count === 0) return;
    this.slots.reserve(this.count + count);
    this.edges.reserve(this.count + count);
    const data = this.slots.data;
    // The batch's slots cleared in one call, not one per contact: 15,000 calls in a pile's first
    // step, made before V8 has optimised this loop.
    data.fill(0, this.count * CONTACT_STRIDE, (this.count + count) * CONTACT_STRIDE);
    const ids = this.pendingIds;
    const shapes = this.shapes;
    for (let n = 0; n < count; n++) {
      const slot = this.count++;
      this.fillSlot(slot, shapes[ids[2 * n]!]!, shapes[ids[2 * n + 1]!]!, data);
      this.edges.link(slot);
    }
    this.made += count;
    this.pendingCount = 0;
  }

  /**
   * Narrow phase over every contact with an awake body: drop the ones whose fat boxes parted,
   * update the manifolds of the rest, record which started or stopped touching, and wake a
   * sleeping body that something started touching.
   *
   * Gates first, from the bodies' own numbers (body-memory.ts) and the flat copy of the shapes'
   * boxes (shape-table.ts), so most contacts are settled without loading their Contact, Body, Shape or
   * Transform objects: in a tumbling pile three contacts in four are pairs of fat boxes whose
   * shapes are nowhere near touching, and in a resting stack nearly all reuse their manifold.
   * Box2D v3 streams its contact sims in arrays for the same reason ("b2CollideTask").
   */
  collide(dt: number): void {
    this.beganCount = 0;
    this.endedCount = 0;
    // At most one begin per contact: room for them all before the loop.
    if (2 * this.count > this.beganIds.length) {
      this.beganIds = grownInt32(this.beganIds, 2 * this.count);
    }
    const began = this.beganIds;
    // The world's body memory does not move during the narrow phase (bodies join between steps).
    const pose = this.bodyStore.data;
    const boxes = this.table.data;
    const data = this.slots.data;
    const slotBodies = this.slots.bodies;
    const slotShapes = this.slots.shapes;
    const kinds = this.slots.kinds;
    // The narrow phase in full is the kernel's (wasm/update-manifold.ts), over the same memory.
    const memory = this.memory;
    const kernel = memory.kernel;
    const dataAt = memory.offsets[CONTACT_DATA]!;
    const bodiesAt = memory.offsets[BODIES]!;
    const geometryAt = memory.offsets[SHAPE_GEOMETRY]!;
    const scratchAt = memory.offsets[NARROW_PHASE_SCRATCH]!;
    let i = 0;
    while (i < this.count) {
      // Offsets: body-memory.ts (stride 40: pose 0-3, velocity 4-6, origin reach 7, max extent 8,
      // awake 9) and shape-table.ts (stride 8; fat box from 4). Literals: the loop is hot.
      const pa = slotBodies[2 * i]! * 40;
      const pb = slotBodies[2 * i + 1]! * 40;
      if (pose[pa + 9] === 0 && pose[pb + 9] === 0) {
        i++;
        continue;
      }
      const sa = slotShapes[2 * i]! * 8;
      const sb = slotShapes[2 * i + 1]! * 8;
      // aabbOverlaps of the fat boxes, written out. Parted fat boxes end the contact only once the
      // shapes' tight boxes are also apart by more than KEEP_GAP: a box re-fattened around its new
      // place often parts from a neighbour's stale fat box, and the neighbour's own re-fattening
      // joins them again a step or two later (in a tumbling pile two contacts in three made were
      // ended the step before). Keeping such a pair costs the box test below; ending and making it
      // again costs the pair set, both bodies' contact lists and a new slot. A kept pair stays
      // correct: its shapes are still tested every step, and the broad phase's report of its
      // fat boxes meeting again finds it in the pair set.
      if (
        !(
          boxes[sa + 4]! <= boxes[sb + 6]! &&
          boxes[sb + 4]! <= boxes[sa + 6]! &&
          boxes[sa + 5]! <= boxes[sb + 7]! &&
          boxes[sb + 5]! <= boxes[sa + 7]!
        ) &&
        (boxes[sa]! - KEEP_GAP > boxes[sb + 2]! ||
          boxes[sb]! - KEEP_GAP > boxes[sa + 2]! ||
          boxes[sa + 1]! - KEEP_GAP > boxes[sb + 3]! ||
          boxes[sb + 1]! - KEEP_GAP > boxes[sa + 3]!)
      ) {
        this.destroy(i, false);
        continue; // the last contact now sits at index i
      }
      const base = i * CONTACT_STRIDE;
      // Bound on how much the gap can close this step: relative speed plus rotation at the rim.
      const dvx = pose[pb + 4]! - pose[pa + 4]!;
      const dvy = pose[pb + 5]! - pose[pa + 5]!;
      // Rotation at the rim: |angular velocity| times the farthest point from the centre of mass.
      const spinA = Math.abs(pose[pa + 6]!) * pose[pa + 8]!;
      const spinB = Math.abs(pose[pb + 6]!) * pose[pb + 8]!;
      const reach = dt * (Math.sqrt(dvx * dvx + dvy * dvy) + spinA + spinB);
      const margin = SPECULATIVE_DISTANCE + reach;
      // Most pairs whose fat boxes overlap are nowhere near touching: their tight boxes settle it.
      if (
        boxes[sa]! - margin > boxes[sb + 2]! ||
        boxes[sb]! - margin > boxes[sa + 2]! ||
        boxes[sa + 1]! - margin > boxes[sb + 3]! ||
        boxes[sb + 1]! - margin > boxes[sa + 3]!
      ) {
        // A contact touches exactly when its slot holds points (contact.ts keeps them together).
        if (data[base + POINT_COUNT] !== 0) this.recordEnd(i);
        data[base + POINT_COUNT] = 0;
        data[base + HAS_CACHE] = 0;
        i++;
        continue;
      }
      // B's pose in A's frame.
      const cA = pose[pa + 2]!;
      const sA = pose[pa + 3]!;
      const cB = pose[pb + 2]!;
      const sB = pose[pb + 3]!;
      const relC = cA * cB + sA * sB;
      const relS = cA * sB - sA * cB;
      const ox = pose[pb]! - pose[pa]!;
      const oy = pose[pb + 1]! - pose[pa + 1]!;
      const relX = cA * ox + sA * oy;
      const relY = -sA * ox + cA * oy;
      // Reuse: B moved relative to A by less than REUSE_TOLERANCE at any of its points since the
      // manifold was computed in full, so the same features touch and only the separations need
      // updating. Resting stacks (most contacts of a settled scene) skip the separating-axis test
      // and the clipping this way (the manifold reuse of Parry/Rapier).
      const k = base + CACHE;
      const dx = relX - data[k]!;
      const dy = relY - data[k + 1]!;
      // |sin| of the rotation since then, times the farthest point of B from its own origin.
      const turn = Math.abs(relS * data[k + 2]! - relC * data[k + 3]!) * pose[pb + 7]!;
      if (
        data[base + HAS_CACHE] === 1 &&
        dx * dx + dy * dy + turn * turn < REUSE_TOLERANCE_SQUARED
      ) {
        // Move the cached surface points with their bodies and measure the gap along the normal.
        const xA = pose[pa]!;
        const yA = pose[pa + 1]!;
        const xB = pose[pb]!;
        const yB = pose[pb + 1]!;
        const nx = cA * data[k + 12]! - sA * data[k + 13]!;
        const ny = sA * data[k + 12]! + cA * data[k + 13]!;
        data[base + NORMAL_X] = nx;
        data[base + NORMAL_Y] = ny;
        const count = data[base + POINT_COUNT]!;
        for (let j = 0; j < count; j++) {
          const q = k + 4 + 4 * j;
          const ax = cA * data[q]! - sA * data[q + 1]! + xA;
          const ay = sA * data[q]! + cA * data[q + 1]! + yA;
          const bx = cB * data[q + 2]! - sB * data[q + 3]! + xB;
          const by = sB * data[q + 2]! + cB * data[q + 3]! + yB;
          const p = base + POINTS + j * POINT_STRIDE;
          data[p + P_SEPARATION] = (bx - ax) * nx + (by - ay) * ny;
          data[p + P_X] = 0.5 * (ax + bx);
          data[p + P_Y] = 0.5 * (ay + by);
        }
        for (let j = 0; j < 2; j++) {
          const p = base + POINTS + j * POINT_STRIDE;
          data[p + P_MAX_NORMAL_IMPULSE] = 0;
          data[p + P_STEP_NORMAL_IMPULSE] = 0;
          data[p + P_STEP_TANGENT_IMPULSE] = 0;
        }
        i++;
        continue;
      }
      const wasTouching = data[base + POINT_COUNT] !== 0;
      const touching =
        kernel.updateManifold(
          dataAt,
          bodiesAt,
          geometryAt,
          scratchAt,
          i,
          kinds[i]!,
          sa >> 3,
          sb >> 3,
          slotBodies[2 * i]!,
          slotBodies[2 * i + 1]!,
          dt,
          margin,
          reach,
          relX,
          relY,
          relC,
          relS,
        ) > 0;
      if (touching !== wasTouching) {
        if (touching) {
          const n = this.beganCount++;
          began[2 * n] = sa >> 3;
          began[2 * n + 1] = sb >> 3;
          this.wake(this.bodies[slotBodies[2 * i]!]!);
          this.wake(this.bodies[slotBodies[2 * i + 1]!]!);
        } else {
          this.recordEnd(i);
        }
      }
      i++;
    }
  }

  /** Wakes a sleeping body's island during the narrow phase (the gates read the flag in place). */
  private wake(body: Body): void {
    if (body.awake) return;
    this.islands.wake(body);
  }

  /** Destroys every contact of a body (it is being removed), waking what touched it. */
  destroyContactsOf(body: Body): void {
    const edges = this.edges;
    for (let key = edges.first(body.worldIndex); key >= 0; key = edges.first(body.worldIndex)) {
      this.destroy(key >> 1, true);
    }
  }

  /** The body at world index `index` left the world (its contacts are already destroyed). */
  bodyRemoved(index: number): void {
    this.slots.bodyRemoved(index, this.count);
  }

  /** Destroys every contact of a shape (it is being removed). */
  destroyContactsOfShape(shape: Shape): void {
    this.destroyContactsWhere(shape.body, shape.id, -1, false);
  }

  /** Destroys the contacts of a shape that its filter now forbids, waking their bodies. */
  destroyForbiddenContactsOf(shape: Shape): void {
    this.destroyContactsWhere(shape.body, shape.id, -1, true);
  }

  /** Destroys the contacts between two bodies (a joint now keeps them from colliding). */
  destroyContactsBetween(bodyA: Body, bodyB: Body): void {
    this.destroyContactsWhere(bodyA, -1, bodyB.worldIndex, false);
  }

  /**
   * Destroys the contacts of `body` with shape id `shape` on one side (-1: any) and the body at
   * world index `other` on the other (-1: any); with `forbidden`, only those whose filters forbid
   * the pair, waking their bodies. After each end the walk starts again from the list's head: the
   * end moved the last slot, and with it the keys of its edges.
   */
  private destroyContactsWhere(body: Body, shape: number, other: number, forbidden: boolean): void {
    const edges = this.edges;
    const shapes = this.slots.shapes;
    let key = edges.first(body.worldIndex);
    while (key >= 0) {
      const slot = key >> 1;
      if (
        (shape < 0 || shapes[2 * slot] === shape || shapes[2 * slot + 1] === shape) &&
        (other < 0 || edges.other(key) === other) &&
        (!forbidden || !this.shapeA(slot).collidesWith(this.shapeB(slot)))
      ) {
        this.destroy(slot, shape >= 0);
        key = edges.first(body.worldIndex);
      } else {
        key = edges.next[key]!;
      }
    }
  }

  /** Wakes every body in contact with `body` (a static body was moved by hand). */
  wakeContactsOf(body: Body): void {
    const edges = this.edges;
    for (let key = edges.first(body.worldIndex); key >= 0; key = edges.next[key]!) {
      this.islands.wake(this.bodies[edges.other(key)]!);
    }
  }

  /**
   * Recreates a contact from a snapshot: shapes already ordered, in the next slot, which it
   * returns. The caller fills the slot's numbers and links its edges into the bodies' lists.
   */
  restoreContact(shapeA: Shape, shapeB: Shape): number {
    this.pairs.add(shapeA.id, shapeB.id);
    const slot = this.count;
    this.slots.reserve(slot + 1);
    this.edges.reserve(slot + 1);
    const data = this.slots.data;
    data.fill(0, slot * CONTACT_STRIDE, (slot + 1) * CONTACT_STRIDE);
    this.fillSlot(slot, shapeA, shapeB, data);
    this.count++;
    return slot;
  }

  /**
   * Ends the contact in `slot`: reports its end if it touched (waking its bodies with
   * `wakeBodies`), unlinks its edges and moves the last contact into its slot.
   */
  private destroy(slot: number, wakeBodies: boolean): void {
    if (this.touching(slot)) {
      this.recordEnd(slot);
      if (wakeBodies) {
        this.islands.wake(this.bodyA(slot));
        this.islands.wake(this.bodyB(slot));
      }
    }
    const shapes = this.slots.shapes;
    this.pairs.remove(shapes[2 * slot]!, shapes[2 * slot + 1]!);
    this.edges.unlink(slot);
    const last = --this.count;
    if (last !== slot) {
      this.edges.move(last, slot);
      this.slots.move(last, slot);
    }
    this.destroyed++;
  }

  /**
   * Drops the references the per-step lists still hold past their counts (a removed body's
   * shapes): overwritten with null in place. The ends not yet reported stay.
   */
  releaseReferences(): void {
    this.beganCount = 0;
    releaseFrom(this.endedA, this.endedCount);
    releaseFrom(this.endedB, this.endedCount);
  }

  /** Frees the per-step lists' room after the world shrank a lot. */
  shrink(): void {
    this.beganIds = new Int32Array(64);
    this.beganCount = 0;
    this.endedA.length = this.endedCount;
    this.endedB.length = this.endedCount;
    const kept = this.pendingIds.subarray(0, 2 * this.pendingCount);
    this.pendingIds = grownInt32(new Int32Array(64), kept.length);
    this.pendingIds.set(kept);
  }

  /** Sets up the cleared `slot` for the pair of shapes a and b (ordered): numbers, bodies, shapes, kind. */
  private fillSlot(slot: number, a: Shape, b: Shape, data: Float64Array): void {
    const kind = initContactSlot(slot, a, b, data);
    this.slots.setPair(slot, a.body.worldIndex, b.body.worldIndex, a.id, b.id, kind);
  }

  private recordEnd(slot: number): void {
    const n = this.endedCount++;
    this.endedA[n] = this.shapeA(slot);
    this.endedB[n] = this.shapeB(slot);
  }
}

/** A copy of `array` with room for at least `needed` elements (doubling), its contents kept. */
function grownInt32(array: Int32Array, needed: number): Int32Array<ArrayBuffer> {
  let size = Math.max(array.length, 1);
  while (size < needed) size *= 2;
  const grown = new Int32Array(size);
  grown.set(array);
  return grown;
}
