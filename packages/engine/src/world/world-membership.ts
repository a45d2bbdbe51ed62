import { callAll, type Listeners } from '../core/listeners.ts';
import type { BroadPhase, ProxyType } from '../collision/broad-phase.ts';
import type { Body } from '../dynamics/body.ts';
import { B_SHAPE_HEAD } from '../dynamics/body-memory.ts';
import type { BodyBounds } from '../dynamics/body-bounds.ts';
import { foreseenContacts, type ContactManager } from '../dynamics/contact-manager.ts';
import type { Islands } from '../dynamics/island.ts';
import type { Joint } from '../dynamics/joints/joint.ts';
import type { Sensors } from '../dynamics/sensor.ts';
import type { Shape } from '../dynamics/shape.ts';
import type { ShapeTable } from '../dynamics/shape-table.ts';
import type { Solver } from '../dynamics/solver.ts';
import { AABB } from '../geometry/aabb.ts';
import type { WorldEvents } from './world.ts';

// Who is in a world: bodies, joints and shapes joining and leaving (World.add and remove, the
// deferred changes at a step's end, shapes added to or removed from a body in a world), with
// the ids, proxies, memory rows and references that go with them. World decides when; this
// file does it.

const PROXY_TYPE: Record<Body['type'], ProxyType> = { static: 0, kinematic: 1, dynamic: 2 };
/** The shapes (and bodies) a world's first room is made for: the solver memory's first sizes. */
const FIRST_FORESEEN_SHAPES = 64;
/**
 * How the foreseen room grows once outgrown: by half, not doubling, since every byte of it is
 * touched (a 5,050-box pyramid would hold room for 8,192 boxes' contacts, 30 MB, at doubling;
 * 5,538 at this rate). The pages touched while a world is built are then about three times its
 * last room's, against twice at doubling.
 */
const ROOM_GROWTH = 1.5;

/** @internal The parts of a world that joining and leaving change. */
export interface MembershipParts {
  readonly bodyList: Body[];
  readonly jointList: Joint[];
  readonly shapesById: (Shape | null)[];
  readonly freeShapeIds: number[];
  readonly shapeTable: ShapeTable;
  readonly broadPhase: BroadPhase;
  readonly bounds: BodyBounds;
  readonly solver: Solver;
  readonly contactManager: ContactManager;
  readonly islands: Islands;
  readonly sensors: Sensors;
  readonly listeners: Listeners<WorldEvents>;
  /** The last step's duration (s): a joining shape's box looks that far ahead. */
  readonly lastStep: () => number;
}

/** @internal Bodies, joints and shapes joining and leaving a world. */
export class WorldMembership {
  /** The next body's id (ids are never reused). */
  nextBodyId = 0;
  /** Set by each step: the step's lists point at bodies and shapes until released. */
  holdsReferences = false;
  private mostBodies = 0;
  /**
   * Shapes in the world whose body was not static when they joined (less those that left so):
   * what the contacts foreseen for a step are counted from (foreseenContacts). A body's type
   * changed later only skews this estimate of room, never a result.
   */
  private movingShapes = 0;
  /** The shapes (and bodies) the room last made by {@link foresee} holds. */
  private foreseenShapes = 0;
  /** A joining shape's fat box, read from the broad phase on its way into the shape table. */
  private readonly fatScratch = new AABB();
  private readonly bodyList: Body[];
  private readonly jointList: Joint[];
  private readonly shapesById: (Shape | null)[];
  private readonly freeShapeIds: number[];
  private readonly shapeTable: ShapeTable;
  private readonly broadPhase: BroadPhase;
  private readonly bounds: BodyBounds;
  private readonly solver: Solver;
  private readonly contactManager: ContactManager;
  private readonly islands: Islands;
  private readonly sensors: Sensors;
  private readonly listeners: Listeners<WorldEvents>;
  private readonly lastStep: () => number;

  constructor(parts: MembershipParts) {
    this.bodyList = parts.bodyList;
    this.jointList = parts.jointList;
    this.shapesById = parts.shapesById;
    this.freeShapeIds = parts.freeShapeIds;
    this.shapeTable = parts.shapeTable;
    this.broadPhase = parts.broadPhase;
    this.bounds = parts.bounds;
    this.solver = parts.solver;
    this.contactManager = parts.contactManager;
    this.islands = parts.islands;
    this.sensors = parts.sensors;
    this.listeners = parts.listeners;
    this.lastStep = parts.lastStep;
  }

  /** A body joins: its numbers move into the world's memory, its shapes get ids and proxies. */
  insertBody(body: Body): void {
    body.id = this.nextBodyId++;
    body.worldIndex = this.bodyList.length;
    // The body's numbers join the world's body memory (body-memory.ts): their one copy from now on.
    const joining = body.shapeList.length;
    this.foresee(
      body.worldIndex + 1,
      this.shapesById.length + joining,
      this.movingShapes + (body.type === 'static' ? 0 : joining),
    );
    const memory = this.solver.memory;
    memory.reserveBodies(body.worldIndex + 1);
    body.moveTo(memory.bodyStore, body.worldIndex);
    body.removalPending = false;
    body.center0X = body.centerX;
    body.center0Y = body.centerY;
    body.angle0 = body.angleValue;
    this.bodyList.push(body);
    if (this.bodyList.length > this.mostBodies) this.mostBodies = this.bodyList.length;
    for (const shape of body.shapeList) this.createProxy(shape);
    this.linkShapes(body);
    callAll(this.listeners.get('bodyAdded'), body);
  }

  /** A joint joins, unless one of its bodies left (or never joined) while it waited. */
  insertJoint(joint: Joint): void {
    const a = joint.bodyA;
    const b = joint.bodyB;
    // A body removed (or never joined) while the joint waited: the joint never joins.
    if (this.bodyList[a.worldIndex] !== a || this.bodyList[b.worldIndex] !== b) {
      joint.worldRef = null;
      return;
    }
    joint.worldIndex = this.jointList.length;
    joint.removalPending = false;
    joint.resetImpulses();
    joint.resetReaction();
    this.jointList.push(joint);
    a.jointList.push(joint);
    if (b !== a) {
      b.jointList.push(joint);
      if (!joint.collideConnected) this.contactManager.destroyContactsBetween(a, b);
    }
    this.islands.wake(a);
    this.islands.wake(b);
  }

  /** A joint leaves; its bodies wake and may touch again. */
  extractJoint(joint: Joint): void {
    const a = joint.bodyA;
    const b = joint.bodyB;
    this.jointList.splice(joint.worldIndex, 1);
    for (let i = joint.worldIndex; i < this.jointList.length; i++)
      this.jointList[i]!.worldIndex = i;
    a.jointList.splice(a.jointList.indexOf(joint), 1);
    if (b !== a) b.jointList.splice(b.jointList.indexOf(joint), 1);
    joint.worldRef = null;
    joint.worldIndex = -1;
    joint.removalPending = false;
    if (!joint.collideConnected && b !== a) {
      // The pair may touch again: let the broad phase look for it.
      for (const shape of a.shapeList)
        if (shape.proxyKey >= 0) this.broadPhase.bufferMove(shape.proxyKey);
      for (const shape of b.shapeList)
        if (shape.proxyKey >= 0) this.broadPhase.bufferMove(shape.proxyKey);
    }
    this.islands.wake(a);
    this.islands.wake(b);
    callAll(this.listeners.get('jointRemoved'), joint);
  }

  /** A body leaves with its joints, contacts and proxies; later bodies move down one place. */
  extractBody(body: Body): void {
    while (body.jointList.length > 0) this.extractJoint(body.jointList[body.jointList.length - 1]!);
    this.contactManager.destroyContactsOf(body);
    for (const shape of body.shapeList) this.destroyProxy(shape);
    // The body's numbers leave with it; the bodies after it move down one place, numbers and all.
    body.detachMemory();
    this.bodyList.splice(body.worldIndex, 1);
    const store = this.solver.memory.bodyStore;
    for (let i = body.worldIndex; i < this.bodyList.length; i++) {
      const moved = this.bodyList[i]!;
      moved.worldIndex = i;
      moved.moveTo(store, i);
    }
    this.contactManager.bodyRemoved(body.worldIndex);
    body.worldRef = null;
    body.worldIndex = -1;
    body.removalPending = false;
    body.solverIndex = 0;
    this.releaseReferences();
    this.islands.releaseWoken();
    this.releaseMemory();
    callAll(this.listeners.get('bodyRemoved'), body);
  }

  /**
   * A removed body (and its userData) must not stay reachable from the world: the step's lists
   * still point at the last step's bodies and shapes, so the first removal after a step
   * overwrites them with null (in place: the next step allocates nothing). Contacts hold no
   * references: they are slots of numbers (ContactManager).
   */
  releaseReferences(): void {
    if (!this.holdsReferences) return;
    this.holdsReferences = false;
    this.solver.releaseReferences();
    this.contactManager.releaseReferences();
    this.islands.releaseReferences();
    this.sensors.releaseReferences();
  }

  /**
   * Once the world has lost three quarters of its most bodies, the room sized for them goes too
   * (solver memory, per-body tables, pooled contacts), so a world emptied of 100,000 bodies
   * weighs about what an empty one does. The next steps grow it again if needed.
   */
  releaseMemory(): void {
    const count = this.bodyList.length;
    if (this.mostBodies < 1024 || 4 * count > this.mostBodies) return;
    this.mostBodies = count;
    this.solver.shrink(count, this.contactManager.count);
    this.contactManager.shrink();
  }

  /** A shape joins: an id (a freed one first), its row in the shape table, a proxy. */
  createProxy(shape: Shape): void {
    this.foresee(
      this.bodyList.length,
      this.shapesById.length + 1,
      this.movingShapes + (shape.body.type === 'static' ? 0 : 1),
    );
    const id = this.freeShapeIds.length > 0 ? this.freeShapeIds.pop()! : this.shapesById.length;
    shape.id = id;
    this.shapesById[id] = shape;
    shape.attachTable(this.shapeTable);
    const box = this.bounds.speculativeBox(shape, this.lastStep());
    shape.proxyKey = this.broadPhase.createProxy(box, PROXY_TYPE[shape.body.type], id, false);
    shape.setFatBox(this.broadPhase.getFatAABB(shape.proxyKey, this.fatScratch));
    if (shape.sensor) this.sensors.add(shape);
    if (shape.body.type !== 'static') this.movingShapes++;
  }

  /**
   * Makes room, before `shapes` shapes (`moving` of them on bodies that are not static) and
   * `bodies` bodies are in the world, for the step it can foresee: the pair set, and the solver
   * memory's bodies, shapes, contacts and constraints (contact-manager.ts's foreseenContacts) in
   * one move with its pages touched, so the world's first step finds it made. Only when the
   * shapes (or bodies) outgrow the last room made, which then grows by half: a world built body
   * by body moves its memory O(log n) times, all regions in the same move, and holds room for at
   * most 1.5 times its shapes (and as many bodies). The one place the room is reserved while a
   * world is built.
   */
  private foresee(bodies: number, shapes: number, moving: number): void {
    if (shapes <= this.foreseenShapes && bodies <= this.foreseenShapes) return;
    let room = Math.max(this.foreseenShapes, FIRST_FORESEEN_SHAPES);
    while (room < shapes || room < bodies) room = Math.ceil(ROOM_GROWTH * room);
    this.foreseenShapes = room;
    this.contactManager.reservePairs(room);
    // The contacts of as many moving shapes, in the proportion the world has now.
    const movingRoom = Math.ceil((moving * room) / Math.max(shapes, 1));
    this.solver.reserveForeseen(room, room, foreseenContacts(movingRoom));
  }

  /**
   * Writes `body`'s shape chain (B_SHAPE_HEAD in its numbers, SHAPE_NEXT by shape id: id plus one,
   * 0 none) in its shapeList's order, skipping shapes without an id (one leaving): the order the
   * kernel's shapeBounds (wasm/shape-bounds.ts) lists escaped proxies in, which the trees' shape
   * and the pairs' order depend on. Runs whenever a body's shapes in a world change.
   */
  linkShapes(body: Body): void {
    const memory = this.solver.memory;
    const next = memory.shapeNext;
    let last = -1;
    let head = 0;
    for (const shape of body.shapeList) {
      if (shape.id < 0) continue;
      if (last < 0) head = shape.id + 1;
      else next[last] = shape.id + 1;
      last = shape.id;
    }
    if (last >= 0) next[last] = 0;
    memory.bodyStore.data[body.base + B_SHAPE_HEAD] = head;
  }

  /** A shape leaves: its id is freed and its numbers move to a table of its own. */
  destroyProxy(shape: Shape): void {
    this.sensors.remove(shape);
    if (shape.body.type !== 'static' && this.movingShapes > 0) this.movingShapes--;
    this.broadPhase.destroyProxy(shape.proxyKey);
    this.shapesById[shape.id] = null;
    this.freeShapeIds.push(shape.id);
    shape.attachTable(null);
    shape.id = -1;
    shape.proxyKey = -1;
  }
}
