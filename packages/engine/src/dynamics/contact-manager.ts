import { PairSet } from '../collision/pair-set.ts';
import { aabbOverlaps } from '../geometry/aabb.ts';
import type { Body } from './body.ts';
import { filtersCollide } from './filter.ts';
import { canCollide, Contact, shouldSwap } from './contact.ts';
import { ContactData } from './contact-data.ts';
import type { Islands } from './island.ts';
import { jointPreventsCollision } from './joints/joint.ts';
import type { Shape } from './shape.ts';
import type { SolverMemory } from './solver-memory.ts';

/**
 * Owns the contacts: creates one when the broad phase reports a new pair of overlapping fat boxes,
 * updates every active one in the narrow phase, and destroys it when the boxes part. Contacts are
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
  private readonly pairs = new PairSet();
  private readonly pool: Contact[] = [];

  constructor(
    private readonly islands: Islands,
    memory: SolverMemory,
  ) {
    this.slots = new ContactData(memory);
  }

  /**
   * Broad-phase callback: a pair of overlapping fat boxes, by shape id. Most pairs reported
   * already have a contact (a moved box overlaps what it overlapped before): one hash lookup
   * settles those before any shape or body is read.
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
    // Sensors never make contacts; filters may forbid the pair (see filter.ts).
    if (shapeA.sensor || shapeB.sensor || !filtersCollide(shapeA, shapeB)) return;
    if (jointPreventsCollision(bodyA, bodyB)) return;
    this.pairs.add(shapeA.id, shapeB.id);
    const contact = this.pool.pop() ?? new Contact();
    contact.index = this.contacts.length;
    this.slots.reserve(contact.index + 1);
    if (shouldSwap(shapeA, shapeB)) contact.init(shapeB, shapeA, this.slots.data);
    else contact.init(shapeA, shapeB, this.slots.data);
    this.slots.setBodies(contact.index, contact.bodyA.worldIndex, contact.bodyB.worldIndex);
    this.contacts.push(contact);
    contact.indexInA = contact.bodyA.contacts.length;
    contact.bodyA.contacts.push(contact);
    contact.indexInB = contact.bodyB.contacts.length;
    contact.bodyB.contacts.push(contact);
  }

  /**
   * Narrow phase over every contact with an awake body: drop the ones whose fat boxes parted,
   * update the manifolds of the rest, record which started or stopped touching, and wake a
   * sleeping body that something started touching.
   */
  collide(dt: number): void {
    this.beganCount = 0;
    this.endedCount = 0;
    const contacts = this.contacts;
    const data = this.slots.data;
    let i = 0;
    while (i < contacts.length) {
      const contact = contacts[i]!;
      const bodyA = contact.bodyA;
      const bodyB = contact.bodyB;
      if (!bodyA.awake && !bodyB.awake) {
        i++;
        continue;
      }
      if (!aabbOverlaps(contact.shapeA.fatAABB, contact.shapeB.fatAABB)) {
        this.destroy(contact, false);
        continue; // the last contact now sits at index i
      }
      const wasTouching = contact.touching;
      const touching = contact.update(dt, data);
      if (touching && !wasTouching) {
        this.began[this.beganCount++] = contact;
        if (!bodyA.awake) this.islands.wake(bodyA);
        if (!bodyB.awake) this.islands.wake(bodyB);
      } else if (!touching && wasTouching) {
        this.recordEnd(contact);
      }
      i++;
    }
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
    this.slots.setBodies(contact.index, contact.bodyA.worldIndex, contact.bodyB.worldIndex);
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
    this.pool.push(contact);
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
