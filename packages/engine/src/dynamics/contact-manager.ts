import { releaseFrom } from '../core/release.ts';
import { PairSet } from '../collision/pair-set.ts';
import type { Body } from './body.ts';
import { canCollide, initContactSlot, shouldSwap } from './contact.ts';
import type { ContactEdges } from './contact-edges.ts';
import { CONTACT_STRIDE, ContactData, POINT_COUNT } from './contact-data.ts';
import { GATE_BEGIN, GATE_DESTROY } from './contact-gates.ts';
import { GATE_ACTION } from './narrow-phase-scratch.ts';
import type { Islands } from './island.ts';
import { jointPreventsCollision } from './joints/joint.ts';
import type { Shape } from './shape.ts';
import {
  BODIES,
  CONTACT_BODIES,
  CONTACT_DATA,
  CONTACT_KINDS,
  CONTACT_SHAPES,
  NARROW_PHASE_SCRATCH,
  SHAPE_BOXES,
  SHAPE_GEOMETRY,
  type SolverMemory,
} from './solver-memory.ts';

// Pairs reserved per shape before a step finds its pairs, and contacts foreseen per shape of a
// body that can move (foreseenContacts): a box in a stack or a pile touches about three others
// (large_pyramid: 14,950 contacts for 5,050 boxes). More still fit: the rooms then grow by
// doubling.
const PAIRS_PER_SHAPE = 3;

/**
 * The contacts a world foresees for a step, from its `movingShapes` shapes on bodies that are not
 * static (two static shapes never make a contact): the rule the solver memory is reserved by as
 * bodies join (Solver.reserveForeseen), so that a world's first step, which makes every contact
 * of its resting piles at once, finds the room made.
 */
export function foreseenContacts(movingShapes: number): number {
  return PAIRS_PER_SHAPE * movingShapes;
}

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
  /** The pairs of shape ids that have a contact (or will, once createPending has run). */
  readonly pairs: PairSet = new PairSet();
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

  constructor(
    private readonly islands: Islands,
    private readonly memory: SolverMemory,
    /** Each body's contact list (shared with the island search). */
    readonly edges: ContactEdges,
    /** The world's bodies by world index, and its shapes by id: what a slot's numbers name. */
    private readonly bodies: readonly Body[],
    private readonly shapes: readonly (Shape | null)[],
  ) {
    this.slots = new ContactData(memory);
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
   * Broad-phase callback: a pair of overlapping fat boxes, by shape id, that the filters allow
   * and that has no contact. Most pairs found are neither (a moved box overlaps what it overlapped
   * before; in a ragdoll rain, bones of one ragdoll): the broad phase turns those away itself,
   * from the filter rows (collision/pair-filter.ts) and then {@link pairs}
   * (BroadPhase.updatePairs), before any call. A pair with a contact always passes the filters:
   * a filter change destroys the contacts it forbids.
   */
  addPair(shapeIdA: number, shapeIdB: number, shapesById: readonly (Shape | null)[]): void {
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
    this.edges.reserve(PAIRS_PER_SHAPE * shapeIds);
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
   * The gates and the manifolds run in the kernel (wasm/contact-gates.ts), from the bodies' own
   * numbers (body-memory.ts) and the shapes' boxes and geometry rows (shape-table.ts,
   * shape-geometry.ts), so most contacts are settled without loading an object: in a tumbling
   * pile three contacts in four are pairs of fat boxes whose shapes are nowhere near touching,
   * and in a resting stack nearly all reuse their manifold. Box2D v3 streams its contact sims in
   * arrays for the same reason ("b2CollideTask").
   */
  collide(dt: number): void {
    this.beganCount = 0;
    this.endedCount = 0;
    // At most one begin per contact: room for them all before the loop.
    if (2 * this.count > this.beganIds.length) {
      this.beganIds = grownInt32(this.beganIds, 2 * this.count);
    }
    const began = this.beganIds;
    // The gates and the manifolds are the kernel's (wasm/contact-gates.ts), over the slots in the
    // solver memory, which does not move during the narrow phase (bodies and shapes join between
    // steps). It stops at each slot whose outcome needs objects: a contact to end, a touch that
    // began or ended; that work is done here, in slot order, and the pass resumes.
    const memory = this.memory;
    const kernel = memory.kernel;
    const offsets = memory.offsets;
    const scratch = memory.narrowPhase;
    const slotBodies = this.slots.bodies;
    const slotShapes = this.slots.shapes;
    let i = 0;
    for (;;) {
      i = kernel.collideContacts(
        offsets[CONTACT_DATA]!,
        offsets[CONTACT_BODIES]!,
        offsets[CONTACT_SHAPES]!,
        offsets[CONTACT_KINDS]!,
        offsets[BODIES]!,
        offsets[SHAPE_BOXES]!,
        offsets[SHAPE_GEOMETRY]!,
        offsets[NARROW_PHASE_SCRATCH]!,
        i,
        this.count,
        dt,
      );
      if (i >= this.count) break;
      const action = scratch[GATE_ACTION];
      if (action === GATE_DESTROY) {
        this.destroy(i, false);
        continue; // the last contact now sits at index i
      }
      if (action === GATE_BEGIN) {
        const n = this.beganCount++;
        began[2 * n] = slotShapes[2 * i]!;
        began[2 * n + 1] = slotShapes[2 * i + 1]!;
        this.wake(this.bodies[slotBodies[2 * i]!]!);
        this.wake(this.bodies[slotBodies[2 * i + 1]!]!);
      } else {
        this.recordEnd(i);
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
