import { releaseFrom } from '../core/release.ts';
import { PairSet } from '../collision/pair-set.ts';
import { AABB_MARGIN, LINEAR_SLOP, SPECULATIVE_DISTANCE } from '../core/constants.ts';
import type { Body } from './body.ts';
import type { BodyStore } from './body-memory.ts';
import {
  canCollide,
  Contact,
  GATE_MARGIN,
  GATE_REACH,
  GATE_REL_C,
  GATE_REL_S,
  GATE_REL_X,
  GATE_REL_Y,
  gateTransformA,
  gateTransformB,
  narrowPhaseGate,
  shouldSwap,
  updateManifold,
} from './contact.ts';
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
import type { SolverMemory } from './solver-memory.ts';

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
 * are more than KEEP_GAP apart. Contacts are
 * pooled, so a scene that keeps its pairs allocates nothing.
 */
export class ContactManager {
  /** Every contact, in creation order (removal swaps the last one in). */
  readonly contacts: Contact[] = [];
  /** The contacts' numbers: slot i belongs to contacts[i]. */
  readonly slots: ContactData;
  /** Contacts that started touching during the last narrow phase (the first `beganCount`). */
  readonly began: Contact[] = [];
  beganCount = 0;
  /** Shape pairs that stopped touching during the last narrow phase (or were destroyed touching). */
  readonly endedA: Shape[] = [];
  readonly endedB: Shape[] = [];
  endedCount = 0;
  /** Contacts made and destroyed since the world was created (the bench's churn counters). */
  made = 0;
  destroyed = 0;
  private readonly pairs = new PairSet();
  private readonly pool: Contact[] = [];
  /** Pairs accepted by addPair, not yet contacts (the first `pendingCount`, already ordered). */
  private readonly pendingA: Shape[] = [];
  private readonly pendingB: Shape[] = [];
  private pendingCount = 0;

  /** Contacts there will be once createPending has run. */
  get countWithPending(): number {
    return this.contacts.length + this.pendingCount;
  }
  /** The bodies' numbers (body-memory.ts), which the narrow phase's gates read in place. */
  private readonly bodyStore: BodyStore;

  constructor(
    private readonly islands: Islands,
    memory: SolverMemory,
    private readonly table: ShapeTable,
  ) {
    this.slots = new ContactData(memory);
    this.bodyStore = memory.bodyStore;
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
    if (shouldSwap(shapeA, shapeB)) {
      this.pendingA[n] = shapeB;
      this.pendingB[n] = shapeA;
    } else {
      this.pendingA[n] = shapeA;
      this.pendingB[n] = shapeB;
    }
  }

  /**
   * Makes room in the pair set for PAIRS_PER_SHAPE pairs per shape id in use, before the broad
   * phase reports pairs: a world's first step then adds them all without growing the set.
   */
  reservePairs(shapeIds: number): void {
    this.pairs.reserve(PAIRS_PER_SHAPE * shapeIds);
  }

  /** Creates the contacts of the pairs addPair accepted since the last call, in that order. */
  createPending(): void {
    const count = this.pendingCount;
    if (count === 0) return;
    this.slots.reserve(this.contacts.length + count);
    const data = this.slots.data;
    for (let n = 0; n < count; n++) {
      const contact = this.pool.pop() ?? new Contact();
      contact.index = this.contacts.length;
      contact.init(this.pendingA[n]!, this.pendingB[n]!, data);
      this.setPair(contact);
      this.contacts.push(contact);
      contact.indexInA = contact.bodyA.contacts.length;
      contact.bodyA.contacts.push(contact);
      contact.indexInB = contact.bodyB.contacts.length;
      contact.bodyB.contacts.push(contact);
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
    // The world's body memory does not move during the narrow phase (bodies join between steps).
    const pose = this.bodyStore.data;
    const boxes = this.table.data;
    const contacts = this.contacts;
    const data = this.slots.data;
    const slotBodies = this.slots.bodies;
    const slotShapes = this.slots.shapes;
    const kinds = this.slots.kinds;
    const geometries = this.table.geometries;
    const gate = narrowPhaseGate;
    let i = 0;
    while (i < contacts.length) {
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
        this.destroy(contacts[i]!, false);
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
        if (data[base + POINT_COUNT] !== 0) {
          const contact = contacts[i]!;
          contact.touching = false;
          this.recordEnd(contact);
        }
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
      gate[GATE_MARGIN] = margin;
      gate[GATE_REACH] = reach;
      gate[GATE_REL_X] = relX;
      gate[GATE_REL_Y] = relY;
      gate[GATE_REL_C] = relC;
      gate[GATE_REL_S] = relS;
      const xfA = gateTransformA;
      xfA.x = pose[pa]!;
      xfA.y = pose[pa + 1]!;
      xfA.c = cA;
      xfA.s = sA;
      const xfB = gateTransformB;
      xfB.x = pose[pb]!;
      xfB.y = pose[pb + 1]!;
      xfB.c = cB;
      xfB.s = sB;
      const wasTouching = data[base + POINT_COUNT] !== 0;
      const touching =
        updateManifold(
          contacts,
          i,
          kinds[i]!,
          geometries[sa >> 3]!,
          geometries[sb >> 3]!,
          dt,
          data,
        ) > 0;
      if (touching !== wasTouching) {
        const contact = contacts[i]!;
        contact.touching = touching;
        if (touching) {
          this.began[this.beganCount++] = contact;
          this.wake(contact.bodyA);
          this.wake(contact.bodyB);
        } else {
          this.recordEnd(contact);
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
    while (body.contacts.length > 0) {
      this.destroy(body.contacts[body.contacts.length - 1]!, true);
    }
  }

  /** The body at world index `index` left the world (its contacts are already destroyed). */
  bodyRemoved(index: number): void {
    this.slots.bodyRemoved(index, this.contacts.length);
  }

  /** Destroys every contact of a shape (it is being removed). */
  destroyContactsOfShape(shape: Shape): void {
    const contacts = shape.body.contacts;
    for (let i = contacts.length - 1; i >= 0; i--) {
      const contact = contacts[i]!;
      if (contact.shapeA === shape || contact.shapeB === shape) this.destroy(contact, true);
    }
  }

  /** Destroys the contacts between two bodies (a joint now keeps them from colliding). */
  destroyContactsBetween(bodyA: Body, bodyB: Body): void {
    const contacts = bodyA.contacts;
    for (let i = contacts.length - 1; i >= 0; i--) {
      const contact = contacts[i]!;
      if (contact.other(bodyA) === bodyB) this.destroy(contact, false);
    }
  }

  /**
   * Recreates a contact from a snapshot: shapes already ordered, appended to the contact list.
   * The caller fills its slot of the contact data and the bodies' contact lists.
   */
  restoreContact(shapeA: Shape, shapeB: Shape): Contact {
    this.pairs.add(shapeA.id, shapeB.id);
    const contact = new Contact();
    contact.index = this.contacts.length;
    this.slots.reserve(contact.index + 1);
    contact.init(shapeA, shapeB, this.slots.data);
    this.setPair(contact);
    this.contacts.push(contact);
    return contact;
  }

  /** Destroys one contact (its filter now forbids it), waking its bodies if it touched. */
  destroyContact(contact: Contact): void {
    this.destroy(contact, true);
  }

  private destroy(contact: Contact, wakeBodies: boolean): void {
    if (contact.touching) {
      this.recordEnd(contact);
      if (wakeBodies) {
        this.islands.wake(contact.bodyA);
        this.islands.wake(contact.bodyB);
      }
    }
    this.pairs.remove(contact.shapeA.id, contact.shapeB.id);
    removeFromBody(contact.bodyA.contacts, contact.indexInA, contact);
    removeFromBody(contact.bodyB.contacts, contact.indexInB, contact);
    const last = this.contacts.pop()!;
    if (last !== contact) {
      this.contacts[contact.index] = last;
      this.slots.move(last.index, contact.index);
      last.index = contact.index;
    }
    contact.index = -1;
    contact.touching = false;
    this.destroyed++;
    contact.release();
    this.pool.push(contact);
  }

  /**
   * Drops the references the per-step lists still hold past their counts (a removed body's
   * shapes): overwritten with null in place. The ends not yet reported stay.
   */
  releaseReferences(): void {
    releaseFrom(this.began, 0);
    this.beganCount = 0;
    releaseFrom(this.endedA, this.endedCount);
    releaseFrom(this.endedB, this.endedCount);
    releaseFrom(this.pendingA, this.pendingCount);
    releaseFrom(this.pendingB, this.pendingCount);
  }

  /** Frees the pooled contacts and the per-step lists' room after the world shrank a lot. */
  shrink(): void {
    this.pool.length = 0;
    this.began.length = 0;
    this.beganCount = 0;
    this.endedA.length = this.endedCount;
    this.endedB.length = this.endedCount;
    this.pendingA.length = this.pendingCount;
    this.pendingB.length = this.pendingCount;
  }

  private setPair(contact: Contact): void {
    this.slots.setPair(
      contact.index,
      contact.bodyA.worldIndex,
      contact.bodyB.worldIndex,
      contact.shapeA.id,
      contact.shapeB.id,
      contact.pairKind,
    );
  }

  private recordEnd(contact: Contact): void {
    const n = this.endedCount++;
    this.endedA[n] = contact.shapeA;
    this.endedB[n] = contact.shapeB;
  }
}

/** Swap-removes a contact from a body's list, fixing the moved contact's back-index. */
function removeFromBody(list: Contact[], index: number, contact: Contact): void {
  const last = list.pop()!;
  if (last === contact) return;
  list[index] = last;
  // The list belongs to one body, which is either side of the moved contact.
  if (last.bodyA.contacts === list) last.indexInA = index;
  else last.indexInB = index;
}
