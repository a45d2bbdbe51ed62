import type { SolverMemory } from './solver-memory.ts';

// The numbers of every contact in one flat array, one slot per contact (slot = the contact's
// index in the contact manager). The narrow phase writes a slot, the solver prepares its
// constraints from it and stores the impulses back, and events read it. Keeping them out of the
// Contact object graph (manifold, point objects, cache) makes those passes stream through memory
// instead of chasing a dozen objects per contact: Box2D v3 keeps its b2ContactSim in arrays for the
// same reason.

/** Unit normal from shape A to shape B (world frame). */
export const NORMAL_X = 0;
export const NORMAL_Y = 1;
/** Number of manifold points, 0..2. */
export const POINT_COUNT = 2;
/** Mixed material: sqrt(fA fB) and max(eA, eB). */
export const FRICTION = 3;
export const RESTITUTION = 4;
/** Radius of a circle shape centred on its body's centre of mass, else 0 (see contact-solver). */
export const RADIUS_A = 5;
export const RADIUS_B = 6;
/** 1 when the manifold-reuse cache below is valid. */
export const HAS_CACHE = 7;
/**
 * Manifold reuse cache: B's pose in A's frame when the manifold was last computed in full
 * (x, y, cosine, sine), then per point the surface point of A in A's frame and of B in B's frame
 * (4 numbers each), then the normal in A's frame (2): 14 numbers.
 */
export const CACHE = 8;
/** Steps in a row, up to the last, in which a point of this contact bounced (contact-solver.ts). */
export const BOUNCING_STEPS = 22;
/** First point; point j starts at POINTS + j * POINT_STRIDE. */
export const POINTS = 23;

// Per point, relative to its start.
/** World position (m), midway between the surfaces. */
export const P_X = 0;
export const P_Y = 1;
/** Signed distance along the normal (m), negative when overlapping. */
export const P_SEPARATION = 2;
/** Feature id, to carry impulses over to the same point next step. */
export const P_ID = 3;
/** Accumulated impulses of the last sub-step (N s), for warm starting. */
export const P_NORMAL_IMPULSE = 4;
export const P_TANGENT_IMPULSE = 5;
/** Largest normal impulse of any sub-step of the last step (N s). */
export const P_MAX_NORMAL_IMPULSE = 6;
/** Normal relative velocity before the solve (m/s); negative when approaching. */
export const P_RELATIVE_VELOCITY = 7;
/** What the last step delivered (sum over the sub-steps plus restitution, N s), for events. */
export const P_STEP_NORMAL_IMPULSE = 8;
export const P_STEP_TANGENT_IMPULSE = 9;
export const POINT_STRIDE = 10;

/** Doubles per contact slot. */
export const CONTACT_STRIDE: number = POINTS + 2 * POINT_STRIDE;

/**
 * Growable flat storage of contact slots, in the solver's memory (solver-memory.ts), where the
 * solver's preparation reads them (in WebAssembly too).
 */
export class ContactData {
  constructor(private readonly memory: SolverMemory) {}

  /**
   * Per slot, the ids of shape A and shape B (2 per slot), so the narrow phase's gates read the
   * shapes' boxes without loading the contact (contact-manager.ts): the solver memory's
   * CONTACT_SHAPES, a view a later reserve replaces.
   */
  get shapes(): Int32Array {
    return this.memory.contactShapes;
  }

  /** Per slot, the pair kind (which collide function applies, pair-kinds.ts): CONTACT_KINDS. */
  get kinds(): Int32Array {
    return this.memory.contactKinds;
  }

  /** The slots' numbers; a view that a later reserve of the memory replaces. */
  get data(): Float64Array {
    return this.memory.contactData;
  }

  /**
   * Per slot, the world indices of body A and body B (2 per slot), so the solver's preparation
   * reads no contact or body object (see Solver.gatherBodies' body table).
   */
  get bodies(): Int32Array {
    return this.memory.contactBodies;
  }

  /** Makes room for `count` slots, keeping the existing ones. */
  reserve(count: number): void {
    this.memory.reserveContacts(count);
  }

  /** Copies slot `from` over slot `to` (swap-removal keeps the slots dense). */
  move(from: number, to: number): void {
    const d = this.memory.contactData;
    d.copyWithin(to * CONTACT_STRIDE, from * CONTACT_STRIDE, (from + 1) * CONTACT_STRIDE);
    const bodies = this.memory.contactBodies;
    bodies[2 * to] = bodies[2 * from]!;
    bodies[2 * to + 1] = bodies[2 * from + 1]!;
    const shapes = this.shapes;
    shapes[2 * to] = shapes[2 * from]!;
    shapes[2 * to + 1] = shapes[2 * from + 1]!;
    const kinds = this.kinds;
    kinds[to] = kinds[from]!;
  }

  /** Records the world indices of a slot's bodies, the ids of its shapes and its pair kind. */
  setPair(
    slot: number,
    indexA: number,
    indexB: number,
    shapeA: number,
    shapeB: number,
    kind: number,
  ): void {
    this.kinds[slot] = kind;
    const bodies = this.memory.contactBodies;
    bodies[2 * slot] = indexA;
    bodies[2 * slot + 1] = indexB;
    const shapes = this.shapes;
    shapes[2 * slot] = shapeA;
    shapes[2 * slot + 1] = shapeB;
  }

  /** The body at world index `removed` left the world: later bodies moved down by one. */
  bodyRemoved(removed: number, slotCount: number): void {
    const bodies = this.memory.contactBodies;
    for (let i = 0; i < 2 * slotCount; i++) {
      if (bodies[i]! > removed) bodies[i]!--;
    }
  }
}
