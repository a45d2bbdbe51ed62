import { PhysicalError } from '../core/errors.ts';
import { Listeners } from '../core/listeners.ts';
import { describeValue, requireFunction, requireVector } from '../core/validate.ts';
import { BroadPhase } from '../collision/broad-phase.ts';
import type { Vec2, Vec2Like } from '../math/vec2.ts';
import type { Body } from '../dynamics/body.ts';
import { BodyBounds } from '../dynamics/body-bounds.ts';
import { ContactManager } from '../dynamics/contact-manager.ts';
import { ContactEdges } from '../dynamics/contact-edges.ts';
import { ContinuousSolver } from '../dynamics/continuous.ts';
import {
  WORLD_EVENT_NAMES,
  type BodyEvents,
  type ContactView,
  type WorldOnlyEvents,
} from '../dynamics/events.ts';
import { Islands } from '../dynamics/island.ts';
import type { Joint } from '../dynamics/joints/joint.ts';
import { Sensors } from '../dynamics/sensor.ts';
import type { Shape, ShapeOptions } from '../dynamics/shape.ts';
import { Solver } from '../dynamics/solver.ts';
import { EventDispatch, forgetBodies } from './event-dispatch.ts';
import { WorldQueries, type RayCastHit } from './queries.ts';
import type { WorldInternals } from './snapshot-format.ts';
import { ShapeQueries, type QueryPose, type ShapeCastHit } from './shape-queries.ts';
import {
  resolveKernel,
  resolveWorldOptions,
  type ResolvedWorldOptions,
  type WorldOptions,
} from './world-options.ts';
import { SizeWarning } from './size-warning.ts';
import { WorldMembership } from './world-membership.ts';
import { checkQueryBox, checkRay, checkTimeStep, checkWorldSetting } from './world-checks.ts';

// `process` as a bundler or Node provides it (see core/development.ts).
declare const process: { env: { NODE_ENV?: string } | undefined };

/** Events of a world: a body's events for every body, plus bodies added, removed and woken. */
export type WorldEvents = BodyEvents & WorldOnlyEvents;

/**
 * A physics world: the bodies, and the clock that moves them. Add and remove bodies at any time,
 * even from inside an event listener (the change then applies at the end of the current step).
 *
 * @example
 * const world = new World(); // y-down, gravity 9.81 m/s^2
 * world.add(wall({ from: { x: 0, y: 5 }, to: { x: 10, y: 5 } }));
 * const ball = world.add(particle({ position: { x: 5, y: 0 }, radius: 0.25 }));
 * for (let i = 0; i < 60; i++) world.step(1 / 60);
 */
// World is the BodyHost of its bodies (`Body.host` returns it as one, which the compiler checks);
// not declared with `implements`, because the host's methods are internal and leave the
// published types.
export class World {
  private readonly settings: ResolvedWorldOptions;
  private readonly bodyList: Body[] = [];
  private readonly shapesById: (Shape | null)[] = [];
  private readonly broadPhase = new BroadPhase();
  private readonly solver = new Solver();
  private readonly bounds = new BodyBounds(this.broadPhase, this.shapesById, this.solver.memory);
  private readonly contactEdges = new ContactEdges(this.solver.memory);
  private readonly islands = new Islands(this.contactEdges, this.bodyList);
  /** The shapes' numbers: views of the solver memory's shape regions. */
  private readonly shapeTable = this.solver.memory.shapeTable;
  private readonly contactManager = new ContactManager(
    this.islands,
    this.solver.memory,
    this.contactEdges,
    this.bodyList,
    this.shapesById,
  );
  private readonly continuous = new ContinuousSolver();
  private readonly sensors = new Sensors();
  private readonly queries: WorldQueries;
  private readonly shapeQueries: ShapeQueries;
  private readonly freeShapeIds: number[] = [];
  private locked = false;
  private readonly pendingAdds: Body[] = [];
  private readonly pendingRemoves: Body[] = [];
  private readonly jointList: Joint[] = [];
  private readonly pendingJointAdds: Joint[] = [];
  private readonly pendingJointRemoves: Joint[] = [];
  private readonly listeners = new Listeners<WorldEvents>(WORLD_EVENT_NAMES);
  private readonly events: EventDispatch;
  private readonly membership: WorldMembership;
  /** Made at the first body a development build adds (see addBody). */
  private sizeWarning: SizeWarning | null = null;
  private readonly gravityView: Vec2 = { x: 0, y: 0 };
  private readonly onPair = (shapeIdA: number, shapeIdB: number): void => {
    this.contactManager.addPair(shapeIdA, shapeIdB, this.shapesById);
  };
  /** Whether the step's lists still point at bodies of the last step (see releaseReferences). */
  /** Most bodies since the memory was last sized down (see releaseMemory). */
  private lastStep = 1 / 60;
  private stepCount = 0;

  constructor(options: WorldOptions = {}) {
    this.settings = resolveWorldOptions(options);
    this.solver.memory.start(resolveKernel(options) === 'javascript');
    this.queries = new WorldQueries(this.broadPhase, this.shapesById);
    this.solver.joints.list = this.jointList;
    this.shapeQueries = new ShapeQueries(this.broadPhase, this.shapesById);
    this.events = new EventDispatch(
      this,
      this.listeners,
      this.contactManager,
      this.sensors,
      this.solver,
    );
    this.islands.onWake = (body) => this.events.emitWake(body);
    this.membership = new WorldMembership({
      bodyList: this.bodyList,
      jointList: this.jointList,
      shapesById: this.shapesById,
      freeShapeIds: this.freeShapeIds,
      shapeTable: this.shapeTable,
      broadPhase: this.broadPhase,
      bounds: this.bounds,
      solver: this.solver,
      contactManager: this.contactManager,
      islands: this.islands,
      sensors: this.sensors,
      listeners: this.listeners,
      lastStep: () => this.lastStep,
    });
  }

  // ---------------------------------------------------------------- settings

  /** Gravity (m/s^2), y-down by default. Setting it wakes every body (a tilted phone must move them). */
  get gravity(): Readonly<Vec2> {
    this.gravityView.x = this.settings.gravityX;
    this.gravityView.y = this.settings.gravityY;
    return this.gravityView;
  }

  set gravity(value: Vec2Like) {
    checkWorldSetting('gravity', value);
    if (value.x === this.settings.gravityX && value.y === this.settings.gravityY) return;
    this.settings.gravityX = value.x;
    this.settings.gravityY = value.y;
    for (const body of this.bodyList) if (body.type === 'dynamic') this.islands.wake(body);
  }

  /** Sub-steps per step (1..64). */
  get subSteps(): number {
    return this.settings.subSteps;
  }

  set subSteps(value: number) {
    this.settings.subSteps = checkWorldSetting('subSteps', value) as number;
  }

  /** Approach speed (m/s) below which collisions do not bounce; 0 for exact restitution. */
  get restitutionThreshold(): number {
    return this.settings.restitutionThreshold;
  }

  set restitutionThreshold(value: number) {
    this.settings.restitutionThreshold = checkWorldSetting('restitutionThreshold', value) as number;
  }

  /** Whether resting bodies fall asleep. Turning it off wakes every body. */
  get enableSleep(): boolean {
    return this.settings.enableSleep;
  }

  set enableSleep(value: boolean) {
    this.settings.enableSleep = checkWorldSetting('enableSleep', value) as boolean;
    if (!value) for (const body of this.bodyList) this.islands.wake(body);
  }

  // ---------------------------------------------------------------- bodies

  /** The bodies in the world, in the order they were added. */
  get bodies(): readonly Body[] {
    return this.bodyList;
  }

  /** Number of steps taken. */
  get steps(): number {
    return this.stepCount;
  }

  /** True while a step (including its event listeners) runs. */
  get isStepping(): boolean {
    return this.locked;
  }

  /**
   * Adds a body and returns it. Inside an event listener the body joins at the end of the step.
   * Throws if the body is already in a world.
   */
  add<B extends Body>(body: B): B {
    if (body === null || typeof body !== 'object' || !('shapeList' in body)) {
      throw new PhysicalError(
        'body',
        `must be a Body (for example particle({...})), got ${describeValue(body)}.`,
      );
    }
    if (body.worldRef === this && body.removalPending) {
      // Removed and added again before the removal applied: the removal is cancelled, and the
      // body stays in the world as if neither call had been made.
      this.pendingRemoves.splice(this.pendingRemoves.indexOf(body), 1);
      body.removalPending = false;
      return body;
    }
    if (body.worldRef !== null) {
      throw new PhysicalError(
        'body',
        body.worldRef === this
          ? 'is already in this world (added twice).'
          : 'is already in another world; remove it there first.',
      );
    }
    body.worldRef = this;
    // Development builds only, written inline as core/development.ts says, so that a production
    // bundle drops the warning's code (0.3 KB gzipped) instead of calling it to do nothing.
    if (
      typeof process !== 'undefined' &&
      process.env !== undefined &&
      process.env.NODE_ENV !== 'production'
    ) {
      (this.sizeWarning ??= new SizeWarning()).check(body);
    }
    if (this.locked) this.pendingAdds.push(body);
    else this.membership.insertBody(body);
    return body;
  }

  /**
   * Removes a body. Inside an event listener the body leaves at the end of the step and gets no
   * more events. Throws if the body is not in this world (for example, removed twice).
   */
  remove(body: Body): void {
    if (
      body === null ||
      typeof body !== 'object' ||
      body.worldRef !== this ||
      body.removalPending
    ) {
      throw new PhysicalError('body', 'is not in this world (removed twice, or never added).');
    }
    const pending = this.pendingAdds.indexOf(body);
    if (pending >= 0) {
      this.pendingAdds.splice(pending, 1);
      body.worldRef = null;
      return;
    }
    if (this.locked) {
      body.removalPending = true;
      this.pendingRemoves.push(body);
      return;
    }
    this.locked = true;
    let thrown: Thrown | null = null;
    try {
      this.membership.extractBody(body);
      this.events.dispatchEnds();
    } catch (error) {
      thrown = { error };
    }
    this.unlock(thrown);
  }

  /** True if the body is in this world (or joins it at the end of the current step). */
  has(body: Body): boolean {
    if (body === null || typeof body !== 'object') return false;
    return body.worldRef === this && !body.removalPending;
  }

  /** Removes every body. */
  clear(): void {
    for (const body of this.bodyList.slice()) this.remove(body);
    for (const body of this.pendingAdds.slice()) this.remove(body);
  }

  // ---------------------------------------------------------------- joints

  /** The joints in the world, in the order they were added. */
  get joints(): readonly Joint[] {
    return this.jointList;
  }

  /**
   * Adds a joint (build one with {@link revoluteJoint}, {@link mouseJoint}, ...) and returns it; its
   * bodies wake. Both bodies must be in this world. Inside an event listener the joint joins at the
   * end of the step.
   */
  addJoint<J extends Joint>(joint: J): J {
    // A shape test, not instanceof: instanceof would bundle the joint classes into every app,
    // joints or not (about 1 KB gzipped).
    if (!isJoint(joint)) {
      throw new PhysicalError(
        'joint',
        `must be a Joint (for example revoluteJoint({...})), got ${describeValue(joint)}.`,
      );
    }
    if (joint.worldRef === this && joint.removalPending) {
      // As for bodies: removed and added again before the removal applied cancels the removal.
      this.pendingJointRemoves.splice(this.pendingJointRemoves.indexOf(joint), 1);
      joint.removalPending = false;
      return joint;
    }
    if (joint.worldRef !== null) {
      throw new PhysicalError(
        'joint',
        joint.worldRef === this
          ? 'is already in this world (added twice).'
          : 'is already in another world; remove it there first.',
      );
    }
    if (!this.has(joint.bodyA)) {
      throw new PhysicalError('bodyA', 'is not in this world: add the body before the joint.');
    }
    if (!this.has(joint.bodyB)) {
      throw new PhysicalError('bodyB', 'is not in this world: add the body before the joint.');
    }
    joint.worldRef = this;
    if (this.locked) {
      this.pendingJointAdds.push(joint);
      return joint;
    }
    this.locked = true;
    let thrown: Thrown | null = null;
    try {
      this.membership.insertJoint(joint);
      this.events.dispatchEnds();
    } catch (error) {
      thrown = { error };
    }
    this.unlock(thrown);
    return joint;
  }

  /**
   * Removes a joint; its bodies wake. Inside an event listener the joint leaves at the end of the
   * step. Removing a body removes its joints. Throws if the joint is not in this world.
   */
  removeJoint(joint: Joint): void {
    if (
      joint === null ||
      typeof joint !== 'object' ||
      joint.worldRef !== this ||
      joint.removalPending
    ) {
      throw new PhysicalError('joint', 'is not in this world (removed twice, or never added).');
    }
    const pending = this.pendingJointAdds.indexOf(joint);
    if (pending >= 0) {
      this.pendingJointAdds.splice(pending, 1);
      joint.worldRef = null;
      return;
    }
    if (this.locked) {
      joint.removalPending = true;
      this.pendingJointRemoves.push(joint);
      return;
    }
    this.locked = true;
    let thrown: Thrown | null = null;
    try {
      this.membership.extractJoint(joint);
    } catch (error) {
      thrown = { error };
    }
    this.unlock(thrown);
  }

  // ---------------------------------------------------------------- stepping

  /**
   * Advances the world by `dt` seconds (default 1/60): the thesis's tick. For the same physics at
   * any display rate, call it with a fixed dt (see the canvas package's fixed-step loop).
   *
   * Stages, in order: find new pairs (broad phase); update contacts (narrow phase); gather awake
   * bodies and their forces; solve (soft step sub-steps, restitution); continuous collision of
   * fast bodies; update the broad phase; sleep resting islands; emit events; apply the adds and
   * removes made by listeners.
   */
  step(dt: number = 1 / 60): void {
    if (this.locked) {
      throw new PhysicalError(
        'step',
        'cannot be called while the world is stepping (from a listener).',
      );
    }
    checkTimeStep(dt);
    if (dt === 0) return;
    this.locked = true;
    this.membership.holdsReferences = true;
    let thrown: Thrown | null = null;
    try {
      this.contactManager.reservePairs(this.shapesById.length);
      this.broadPhase.updatePairs(this.onPair, this.contactManager.pairs, this.shapeTable.filters);
      // Room for the whole step in one move of the solver memory, then the new contacts.
      this.solver.reserve(
        this.bodyList.length,
        this.contactManager.countWithPending,
        this.contactManager.count,
      );
      this.contactManager.createPending();
      this.contactManager.collide(dt);
      this.solver.gatherBodies(this.bodyList, dt);
      this.solver.solve(this.contactManager.count, this.settings, dt);
      // The step moves its bodies' proxies together: their trees only grow until the rebuild
      // below (BroadPhase.deferring), which queries may precede, since grown trees stay exact.
      this.broadPhase.deferring = true;
      // The boxes look one step ahead, as long as the last (a field: V8 boxes a double argument).
      this.bounds.dt = this.lastStep;
      this.solver.finalizeBodies(dt, this.bounds, this.settings.enableContinuous);
      this.solveContinuous();
      this.solveBullets();
      if (this.sensors.shapes.length > 0) this.sensors.update(this.broadPhase, this.shapesById);
      if (this.settings.enableSleep) {
        this.islands.sleepRestingIslands(
          this.solver.awake,
          this.solver.awakeCount,
          this.settings.timeToSleep,
        );
      }
      this.lastStep = dt;
      this.stepCount++;
      this.events.dispatchStep();
    } catch (error) {
      // A listener threw: the step's remaining events are not delivered, but the changes queued
      // so far still apply (below), so the world is consistent when the error reaches the caller.
      thrown = { error };
    }
    this.unlock(thrown);
  }

  // ---------------------------------------------------------------- queries

  /**
   * The body with a shape containing the world point (m), or null. If several do, the one added
   * last (drawn on top).
   */
  bodyAt(point: Vec2Like): Body | null {
    requireVector('point', point);
    return this.queries.bodyAt(point.x, point.y);
  }

  /** Bodies with a shape whose bounding box overlaps the box (m), each once, in world order. */
  bodiesInAABB(box: {
    readonly minX: number;
    readonly minY: number;
    readonly maxX: number;
    readonly maxY: number;
  }): Body[] {
    checkQueryBox(box);
    return this.queries.bodiesInAABB(box.minX, box.minY, box.maxX, box.maxY);
  }

  /** The first shape hit by the ray from `from` to `to` (m), or null. */
  rayCast(from: Vec2Like, to: Vec2Like): RayCastHit | null {
    checkRay(from, to);
    return this.queries.rayCast(from.x, from.y, to.x, to.y);
  }

  /**
   * Every shape hit by the ray from `from` to `to` (m), sorted by fraction along the ray (ties in
   * world order), one hit per shape. Sensors are not hit. A new array each call.
   */
  rayCastAll(from: Vec2Like, to: Vec2Like): RayCastHit[] {
    checkRay(from, to);
    return this.queries.rayCastAll(from.x, from.y, to.x, to.y);
  }

  /**
   * Sweeps a shape (described as for a body: circle, box, polygon or segment; material ignored)
   * from `pose` along `translation` (m) and returns the first shape it would hit, or null.
   * Sensors are not hit.
   *
   * @example
   * // Will a 0.25 m ball thrown right from (0, 0) hit something within 10 m?
   * const hit = world.shapeCast({ type: 'circle', radius: 0.25 }, { position: { x: 0, y: 0 } }, { x: 10, y: 0 });
   */
  shapeCast(shape: ShapeOptions, pose: QueryPose, translation: Vec2Like): ShapeCastHit | null {
    return this.shapeQueries.shapeCast(shape, pose, translation);
  }

  /**
   * Bodies with a shape overlapping (or touching) the given shape placed at `pose`, each once, in
   * world order. Sensors are not reported.
   */
  overlapShape(shape: ShapeOptions, pose: QueryPose): Body[] {
    return this.shapeQueries.overlapShape(shape, pose);
  }

  /** Number of bodies that are awake and not static: 0 means the world is at rest. */
  get awakeBodyCount(): number {
    let count = 0;
    for (const body of this.bodyList) if (body.awake) count++;
    return count;
  }

  /**
   * Visits every pair of shapes in contact (touching, or within the speculative margin), with the
   * manifold and the impulses of the last step: for debug drawing and inspection. The view object
   * is reused between calls: copy what you keep.
   */
  forEachContact(visitor: (contact: ContactView) => void): void {
    requireFunction('visitor', visitor);
    const event = this.events.collisionEvent;
    const manager = this.contactManager;
    for (let slot = 0; slot < manager.count; slot++) {
      if (!manager.touching(slot)) continue;
      this.events.fillCollisionEvent(slot, event);
      visitor(event);
    }
    forgetBodies(event);
  }

  // ---------------------------------------------------------------- events

  /**
   * Listens to an event of the world ({@link WorldEvents}). Each body's events, for every body:
   * `'move'` (a body moved this step), `'collision'` (a body took part in a collision),
   * `'contactBegin'` and `'contactEnd'` (two shapes started or stopped touching),
   * `'sensorBegin'` and `'sensorEnd'` (a shape entered or left a sensor); and the world's own:
   * `'bodyAdded'`, `'bodyRemoved'`, `'jointRemoved'` and `'wake'` (a sleeping body woke up).
   * Step events run after the step, in the order the listeners were added. Returns a function
   * that removes the listener. An unknown name throws a `PhysicalError` naming `type`.
   */
  on<K extends keyof WorldEvents>(type: K, listener: WorldEvents[K]): () => void {
    return this.listeners.on(type, listener);
  }

  /** Removes a listener added with {@link on}. */
  off<K extends keyof WorldEvents>(type: K, listener: WorldEvents[K]): void {
    this.listeners.off(type, listener);
  }

  // ---------------------------------------------------------------- hooks used by Body (BodyHost)

  /** @internal A body was moved by hand (teleport): refresh its boxes and wake it. */
  bodyMoved(body: Body): void {
    body.center0X = body.centerX;
    body.center0Y = body.centerY;
    body.angle0 = body.angleValue;
    if (this.bodyList[body.worldIndex] !== body) return; // joins at the end of the step
    this.refreshProxies(body, true);
    if (body.type === 'static') {
      this.contactManager.wakeContactsOf(body);
    } else {
      this.islands.wake(body);
    }
  }

  /** @internal */
  wakeBody(body: Body): void {
    this.islands.wake(body);
  }

  /** @internal */
  sleepBody(body: Body): void {
    this.islands.sleep(body);
  }

  /** @internal */
  requireUnlocked(what: string): void {
    if (this.locked) {
      throw new PhysicalError(
        what,
        'cannot change shapes while the world is stepping; do it after step().',
      );
    }
  }

  /** @internal */
  shapeAdded(shape: Shape): void {
    if (this.bodyList[shape.body.worldIndex] !== shape.body) return;
    this.membership.createProxy(shape);
    this.membership.linkShapes(shape.body);
  }

  /**
   * @internal A shape's filter changed: contacts it now forbids end (and wake their bodies), and
   * the shape looks for pairs again at the next step.
   */
  shapeFilterChanged(shape: Shape): void {
    if (shape.proxyKey < 0) return;
    this.contactManager.destroyForbiddenContactsOf(shape);
    this.broadPhase.bufferMove(shape.proxyKey);
    this.wakeBody(shape.body);
    this.events.dispatchEnds();
  }

  /** @internal */
  shapeRemoved(shape: Shape): void {
    if (shape.proxyKey < 0) return;
    this.contactManager.destroyContactsOfShape(shape);
    this.membership.destroyProxy(shape);
    this.membership.linkShapes(shape.body);
    this.events.dispatchEnds();
  }

  // ---------------------------------------------------------------- internals

  /** Moves the body's shapes' broad-phase boxes to where the body is now (see BodyBounds). */
  private refreshProxies(body: Body, forcePairs: boolean): void {
    this.bounds.dt = this.lastStep;
    this.bounds.refresh(body, forcePairs);
  }

  /** Sweeps the fast bodies that finalizeBodies listed, then moves their boxes. */
  private solveContinuous(): void {
    const fast = this.solver.fastBodies;
    for (let i = 0; i < this.solver.fastCount; i++) {
      const body = fast[i]!;
      this.continuous.solve(body, this.broadPhase, this.shapesById);
      this.refreshProxies(body, false);
    }
  }

  /**
   * Bullets sweep last, against static shapes and the final poses of every other body (Box2D
   * v3's order), so the broad phase already holds those poses; a bullet moved back to its first
   * impact gets its boxes refreshed again.
   */
  private solveBullets(): void {
    const bullets = this.solver.fastBullets;
    const count = this.solver.fastBulletCount;
    for (let i = 0; i < count; i++) this.refreshProxies(bullets[i]!, false);
    for (let i = 0; i < count; i++) {
      const body = bullets[i]!;
      if (this.continuous.solve(body, this.broadPhase, this.shapesById, true)) {
        this.refreshProxies(body, false);
      }
    }
  }

  /**
   * Ends a locked section (a step, or a change that reports contact ends): unlocks, rebuilds the
   * trees the step grew, then applies the changes listeners queued (the deferred point), even
   * when a listener threw; then rethrows the first error.
   */
  private unlock(thrown: Thrown | null): void {
    this.locked = false;
    this.broadPhase.rebuildMoved();
    try {
      this.flushPending();
    } catch (error) {
      thrown ??= { error };
    }
    if (thrown !== null) throw thrown.error;
  }

  /**
   * Applies the queued changes, and then the events they cause, which may queue more. A listener
   * that throws (bodyAdded, bodyRemoved, jointRemoved, an end) does not stop the rest: every
   * queued change applies, and the first error is rethrown at the end.
   */
  private flushPending(): void {
    let thrown: Thrown | null = null;
    while (
      this.pendingAdds.length > 0 ||
      this.pendingRemoves.length > 0 ||
      this.pendingJointAdds.length > 0 ||
      this.pendingJointRemoves.length > 0
    ) {
      this.locked = true;
      try {
        while (this.pendingJointRemoves.length > 0) {
          const joint = this.pendingJointRemoves.shift()!;
          if (joint.worldRef === this) this.membership.extractJoint(joint);
        }
        while (this.pendingRemoves.length > 0)
          this.membership.extractBody(this.pendingRemoves.shift()!);
        while (this.pendingAdds.length > 0) this.membership.insertBody(this.pendingAdds.shift()!);
        while (this.pendingJointAdds.length > 0)
          this.membership.insertJoint(this.pendingJointAdds.shift()!);
        this.events.dispatchEnds();
      } catch (error) {
        thrown ??= { error };
      } finally {
        this.locked = false;
      }
    }
    if (thrown !== null) throw thrown.error;
  }

  /**
   * @internal The parts of the world a snapshot reads and writes (`takeSnapshot` and
   * `restoreSnapshot` in snapshot.ts, kept out of World so that apps without snapshots do not
   * bundle them, nor every joint kind they import).
   */
  internals(): WorldInternals {
    // eslint-disable-next-line @typescript-eslint/no-this-alias
    const world = this;
    return {
      world,
      settings: this.settings,
      bodies: this.bodyList,
      joints: this.jointList,
      broadPhase: this.broadPhase,
      islands: this.islands,
      contactManager: this.contactManager,
      sensors: this.sensors,
      shapesById: this.shapesById,
      shapeTable: this.shapeTable,
      freeShapeIds: this.freeShapeIds,
      placeBody(body: Body, index: number): void {
        const memory = world.solver.memory;
        memory.reserveBodies(index + 1);
        body.moveTo(memory.bodyStore, index);
      },
      linkShapes(body: Body): void {
        world.membership.linkShapes(body);
      },
      get nextBodyId(): number {
        return world.membership.nextBodyId;
      },
      set nextBodyId(value: number) {
        world.membership.nextBodyId = value;
      },
      get stepCount(): number {
        return world.stepCount;
      },
      set stepCount(value: number) {
        world.stepCount = value;
      },
      get lastStep(): number {
        return world.lastStep;
      },
      set lastStep(value: number) {
        world.lastStep = value;
      },
    };
  }

  /** @internal Duration of the last step (s), for tools that turn impulses into forces. */
  get lastStepDuration(): number {
    return this.lastStep;
  }
}

/** An error caught in a locked section, rethrown once the deferred changes applied. */
interface Thrown {
  readonly error: unknown;
}

/** A joint made by one of the joint factories (it has the solver's methods and a world slot). */
function isJoint(value: unknown): value is Joint {
  return (
    typeof value === 'object' &&
    value !== null &&
    'worldRef' in value &&
    typeof (value as { createBatch?: unknown }).createBatch === 'function'
  );
}
