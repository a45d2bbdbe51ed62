import { B_CONTACT_HEAD, BODY_STRIDE } from './body-memory.ts';
import { CONTACT_STRIDE, POINT_COUNT } from './contact-data.ts';
import type { SolverMemory } from './solver-memory.ts';

// Each body's contacts as a linked list in flat memory (Box2D v3's contact edges, b2ContactEdge):
// a contact in slot s has two edges, key 2s (its side A) and 2s + 1 (side B), each linked into its
// own body's list by `next` and `prev` keys (-1 ends a list). The list's first key is in the body's
// stride of the body memory (B_CONTACT_HEAD, stored as key + 1 so the zero of a fresh stride is an
// empty list). The other body of an edge is the slot's other world index: contactBodies[key ^ 1].
//
// So a contact's begin links two edges at their lists' heads and its end unlinks them, with no
// object, array splice or back-index to fix; the island search walks a body's list by keys.

/** @internal Each body's contacts, as two edges per contact slot linked per body. */
export class ContactEdges {
  /** Per edge key, the next key in its body's list, -1 at the end. */
  next: Int32Array = new Int32Array(256);
  /** Per edge key, the previous key in its body's list, -1 at the head. */
  prev: Int32Array = new Int32Array(256);

  constructor(private readonly memory: SolverMemory) {}

  /** Makes room for `count` contact slots' edges, keeping the existing ones. */
  reserve(count: number): void {
    if (this.next.length >= 2 * count) return;
    let size = this.next.length;
    while (size < 2 * count) size *= 2;
    const next = new Int32Array(size);
    next.set(this.next);
    this.next = next;
    const prev = new Int32Array(size);
    prev.set(this.prev);
    this.prev = prev;
  }

  /** The first edge key of the body at world index `body`, -1 if it has no contact. */
  first(body: number): number {
    return this.memory.bodyStore.data[body * BODY_STRIDE + B_CONTACT_HEAD]! - 1;
  }

  /** The world index of the body on the other side of edge `key`. */
  other(key: number): number {
    return this.memory.contactBodies[key ^ 1]!;
  }

  /** Whether the contact of edge `key` touches (its slot holds manifold points, contact.ts). */
  touching(key: number): boolean {
    return this.memory.contactData[(key >> 1) * CONTACT_STRIDE + POINT_COUNT] !== 0;
  }

  /** Links both edges of `slot` at the heads of its bodies' lists (contactBodies already set). */
  link(slot: number): void {
    const bodies = this.memory.contactBodies;
    const heads = this.memory.bodyStore.data;
    this.push(2 * slot, bodies[2 * slot]! * BODY_STRIDE + B_CONTACT_HEAD, heads);
    this.push(2 * slot + 1, bodies[2 * slot + 1]! * BODY_STRIDE + B_CONTACT_HEAD, heads);
  }

  /** Links edge `key` alone at the head of its body's list (restoring a snapshot). */
  pushEdge(key: number): void {
    const head = this.memory.contactBodies[key]! * BODY_STRIDE + B_CONTACT_HEAD;
    this.push(key, head, this.memory.bodyStore.data);
  }

  /** Unlinks both edges of `slot` from its bodies' lists. */
  unlink(slot: number): void {
    const bodies = this.memory.contactBodies;
    const heads = this.memory.bodyStore.data;
    this.remove(2 * slot, bodies[2 * slot]! * BODY_STRIDE + B_CONTACT_HEAD, heads);
    this.remove(2 * slot + 1, bodies[2 * slot + 1]! * BODY_STRIDE + B_CONTACT_HEAD, heads);
  }

  /**
   * The contact in slot `from` now lives in slot `to` (swap-removal keeps the slots dense; slot
   * `to` is unlinked and contactBodies still names `from`'s bodies at `from`): its edges take the
   * new keys, and their neighbours and heads point at them.
   */
  move(from: number, to: number): void {
    const bodies = this.memory.contactBodies;
    const heads = this.memory.bodyStore.data;
    for (let side = 0; side < 2; side++) {
      const old = 2 * from + side;
      const key = 2 * to + side;
      const prev = this.prev[old]!;
      const next = this.next[old]!;
      this.prev[key] = prev;
      this.next[key] = next;
      if (prev >= 0) this.next[prev] = key;
      else heads[bodies[old]! * BODY_STRIDE + B_CONTACT_HEAD] = key + 1;
      if (next >= 0) this.prev[next] = key;
    }
  }

  private push(key: number, head: number, heads: Float64Array): void {
    const first = heads[head]! - 1;
    this.prev[key] = -1;
    this.next[key] = first;
    if (first >= 0) this.prev[first] = key;
    heads[head] = key + 1;
  }

  private remove(key: number, head: number, heads: Float64Array): void {
    const prev = this.prev[key]!;
    const next = this.next[key]!;
    if (prev >= 0) this.next[prev] = next;
    else heads[head] = next + 1;
    if (next >= 0) this.prev[next] = prev;
  }
}
