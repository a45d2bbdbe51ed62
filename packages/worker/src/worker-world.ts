import {
  PhysicalError,
  bodyAtPoint,
  checkQueryBox,
  checkRay,
  checkTimeStep,
  checkWorldOptions,
  checkWorldSetting,
  type Body,
  type ContactView,
  type Duration,
  type Vec2,
  type Vec2Like,
  type WorldOptions,
  type WorldSettingValues,
} from '@physical/engine';
import {
  MAX_REMOTE_STEPS_IN_FLIGHT,
  type DrawingSource,
  type Pose,
  type RemoteDrawing,
} from '@physical/canvas';
import {
  prepareBody,
  prepareJoint,
  type BodyDefinition,
  type JointDefinition,
} from './definitions.ts';
import type { PageJoint } from './page-joint.ts';
import { plainCopy, plainVector } from './plain-copy.ts';
import type { WorkerEvent, WorkerWorldEvents } from './events.ts';
import type { OffscreenView } from './offscreen-renderer.ts';
import type { BodyId, ForceId, JointId } from './ids.ts';
import { createSharedPoses, POSE_STRIDE, SharedPoses } from './pose-stream.ts';
import {
  BODY_PROPERTIES,
  type BodyOperation,
  type BodyProperty,
  type FromWorker,
  type Query,
  type StreamedEvent,
  type ToWorker,
  type WorldSetting,
} from './protocol.ts';

/** Options of a {@link WorkerWorld}. */
export interface WorkerWorldOptions {
  /** The world's options, as for `new World(options)`. */
  readonly world?: WorldOptions;
  /**
   * Share poses through a SharedArrayBuffer: `'auto'` (default) when the page is cross-origin
   * isolated, `false` never (each step transfers one typed array instead).
   */
  readonly shared?: 'auto' | false;
  /**
   * Draw in the worker instead: the canvas from `canvasElement.transferControlToOffscreen()` and
   * its view. The worker then draws after each step, in `<physical-canvas>`'s default look; drive
   * the steps with {@link WorkerWorld.run} (do not also give the world to a `<physical-canvas>`).
   */
  readonly offscreen?: OffscreenView;
  /** Bodies the shared pose memory holds (more fall back to transferred poses). Default 4096. */
  readonly sharedCapacity?: number;
}

/** A body's full state, as {@link WorkerWorld.getBody} reads it from the worker. */
export interface WorkerBodyState {
  readonly position: Vec2;
  readonly angle: number;
  readonly linearVelocity: Vec2;
  readonly angularVelocity: number;
  readonly isAwake: boolean;
}

/** A ray hit, as {@link WorkerWorld.rayCast} reads it from the worker. */
export interface WorkerRayCastHit {
  readonly body: BodyId;
  readonly point: Vec2;
  readonly normal: Vec2;
  readonly fraction: number;
}

/** The part of a `Worker` a {@link WorkerWorld} uses (a `MessagePort` works too, in tests). */
export interface WorkerLike {
  postMessage(message: unknown, transfer?: Transferable[]): void;
  addEventListener(type: string, listener: (event: Event) => void): void;
  terminate?(): void;
}

const STREAMED: readonly StreamedEvent[] = [
  'collision',
  'contactBegin',
  'contactEnd',
  'sensorBegin',
  'sensorEnd',
  'move',
];

type Listener = (...args: never[]) => void;

/**
 * A world that lives in a Web Worker, driven from the page with the API of `World` for what a page
 * does. Bodies and joints are plain ids ({@link BodyId}, {@link JointId}); every call is checked
 * on the page with the engine's own factories and setters (the same `PhysicalError`, the same
 * field, thrown synchronously), then posted, and the worker replays the calls in order: it steps
 * exactly as the same world would on the page.
 *
 * Each step, the worker sends the poses of the bodies that moved (one transferred `Float32Array`,
 * or shared memory when the page is cross-origin isolated) and the step's events, batched. Give it
 * to `<physical-canvas>` (`canvas.world = workerWorld`) to draw it: the canvas drives its steps
 * and interpolates between the last two.
 *
 * ```ts
 * const world = new WorkerWorld(new Worker(new URL('./physics.worker.ts', import.meta.url), { type: 'module' }));
 * const ball = world.add({ kind: 'particle', radius: 0.2, position: { x: 1, y: 0 } });
 * world.applyImpulse(ball, { x: 2, y: 0 });
 * ```
 */
export class WorkerWorld implements DrawingSource {
  /** True when poses come through shared memory (the page is cross-origin isolated). */
  readonly isShared: boolean;
  /** Bytes of pose data received in the last applied step(s) (transferred mode; 0 when shared). */
  lastPoseBytes = 0;
  private readonly worker: WorkerLike;
  // The page side keeps no World (no solver, broad phase or contacts: the worker has them): copies
  // of the bodies and joints built by the engine's factories, for checking input, drawing and
  // hit-testing, in the world's order, and the settings the page can read. Input the World would
  // refuse is refused here with the engine's own checks (`checkTimeStep`, `checkWorldSetting`...).
  private readonly bodyList: Body[] = [];
  private readonly jointList: PageJoint[] = [];
  private readonly settings: WorldSettingValues;
  private readonly bodyById = new Map<number, Body>();
  private readonly idByBody = new Map<Body, number>();
  private readonly jointById = new Map<number, PageJoint>();
  private readonly listeners = new Map<keyof WorkerWorldEvents, Set<Listener>>();
  private readonly pending = new Map<
    number,
    { resolve: (value: unknown) => void; reject: (error: Error) => void }
  >();
  private readonly shared: SharedPoses | null;
  private nextBodyId = 1;
  private nextJointId = 1;
  private nextForceId = 1;
  private nextQueryId = 1;
  // Poses by id: the current (last applied step) and the one before, for interpolation.
  private current = new Float64Array(0);
  private previous = new Float64Array(0);
  private readonly touched: number[] = [];
  /** The batch in which each id was last touched. */
  private stamps = new Int32Array(0);
  private batch = 0;
  /** Requested steps when the page last changed the world: it counts as awake until then. */
  private changedAt = 0;
  /** Bodies whose mirror pose is behind `current` (synced before a page-side query). */
  private readonly stale = new Set<number>();
  private readonly frames: Float32Array[] = [];
  private sharedFrame = 0;
  private awake = 0;
  private stepsValue = 0;
  private sentSteps = 0;
  /** Steps asked for that will never come back (the worker failed while taking them). */
  private lostSteps = 0;
  private failure: Error | null = null;
  private listening = '';

  constructor(worker: WorkerLike, options: WorkerWorldOptions = {}) {
    if (options === null || typeof options !== 'object') {
      throw new PhysicalError('options', `must be an object, got ${String(options)}.`);
    }
    this.worker = worker;
    const worldOptions = plainCopy(options.world ?? {}, 'world') as WorldOptions;
    this.settings = checkWorldOptions(worldOptions);
    const isolated =
      typeof SharedArrayBuffer !== 'undefined' &&
      (globalThis as { crossOriginIsolated?: boolean }).crossOriginIsolated === true;
    const capacity = options.sharedCapacity ?? 4096;
    if (!Number.isInteger(capacity) || capacity < 1) {
      throw new PhysicalError(
        'sharedCapacity',
        `must be a positive integer, got ${String(capacity)}.`,
      );
    }
    const memory = options.shared !== false && isolated ? createSharedPoses(capacity) : null;
    this.shared = memory === null ? null : new SharedPoses(memory);
    this.isShared = memory !== null;
    worker.addEventListener('message', (event) =>
      this.receive((event as MessageEvent).data as FromWorker),
    );
    worker.addEventListener('error', (event) => {
      const message = (event as ErrorEvent).message;
      this.fail(new Error(`the physics worker failed: ${message || 'an error (see the console)'}`));
    });
    worker.addEventListener('messageerror', () =>
      this.fail(new Error('a message from the physics worker could not be read')),
    );
    const offscreen = options.offscreen ?? null;
    this.post(
      { type: 'init', options: worldOptions, shared: memory, offscreen },
      offscreen === null ? [] : [offscreen.canvas],
    );
  }

  // ------------------------------------------------------------------ bodies and joints

  /**
   * Adds a body built from `definition` (a factory name and its options) and returns its id.
   * Bad options throw the engine's PhysicalError here, before anything is posted.
   */
  add<UserData>(definition: BodyDefinition<UserData>): BodyId {
    // Checked, copied and posted before the page's copy joins: a definition the worker could not
    // receive leaves both worlds as they were.
    const { posted, body } = prepareBody(definition as BodyDefinition);
    const id = this.nextBodyId;
    this.post({ type: 'add', id, definition: posted });
    this.nextBodyId++;
    this.bodyList.push(body);
    this.bodyById.set(id, body);
    this.idByBody.set(body, id);
    this.ensureCapacity(id);
    const position = body.position;
    for (const poses of [this.current, this.previous]) {
      poses[3 * id] = position.x;
      poses[3 * id + 1] = position.y;
      poses[3 * id + 2] = body.angle;
    }
    this.changed();
    this.emit('bodyAdded');
    return id as BodyId;
  }

  /** Removes a body (and its joints). Unknown ids throw a PhysicalError naming `id`. */
  remove(id: BodyId): void {
    const body = this.requireBody(id);
    this.post({ type: 'remove', id });
    for (const [jointId, joint] of this.jointById) {
      if (joint.bodyA === body || joint.bodyB === body) {
        this.jointById.delete(jointId);
        this.jointList.splice(this.jointList.indexOf(joint), 1);
      }
    }
    this.bodyList.splice(this.bodyList.indexOf(body), 1);
    this.bodyById.delete(id);
    this.idByBody.delete(body);
    this.stale.delete(id);
    this.emit('bodyRemoved');
  }

  /** True while the body is in the world. */
  has(id: BodyId): boolean {
    return this.bodyById.has(id);
  }

  /** Ids of the bodies, in the world's order. */
  get bodyIds(): BodyId[] {
    return this.bodyList.map((body) => this.idByBody.get(body)! as BodyId);
  }

  /** Adds a joint between bodies of this world (ids in place of bodies) and returns its id. */
  addJoint(definition: JointDefinition): JointId {
    const { posted, joint } = prepareJoint(definition, (id) => this.requireBody(id, 'body'));
    const id = this.nextJointId;
    this.post({ type: 'addJoint', id, definition: posted });
    this.nextJointId++;
    this.jointList.push(joint);
    this.jointById.set(id, joint);
    this.changed();
    return id as JointId;
  }

  /** Removes a joint. */
  removeJoint(id: JointId): void {
    const joint = this.jointById.get(id);
    if (joint === undefined) throw new PhysicalError('id', `no joint ${String(id)} in this world.`);
    this.post({ type: 'removeJoint', id });
    this.jointById.delete(id);
    this.jointList.splice(this.jointList.indexOf(joint), 1);
  }

  /**
   * The page's copy of a body, for styles (`canvas.setStyle(world.bodyOf(id), style)`), its
   * shapes, type and `userData`. Its pose is not kept up to date: read {@link position}.
   */
  bodyOf(id: BodyId): Body {
    return this.requireBody(id);
  }

  /** The id of a page copy of a body (as `<physical-canvas>` events report bodies), or null. */
  idOf(body: Body): BodyId | null {
    return (this.idByBody.get(body) ?? null) as BodyId | null;
  }

  // ------------------------------------------------------------------ forces and velocities

  /**
   * Applies a force (N) for a duration (see `Body.applyForce`); returns its id, for
   * {@link removeForce}.
   */
  applyForce(
    id: BodyId,
    force: Vec2Like,
    options: { duration?: Duration; point?: Vec2Like } = {},
  ): ForceId {
    const body = this.requireBody(id);
    const plainForce = plainVector(force) as Vec2Like;
    const plainOptions = plainCopy(options, 'options') as { duration?: Duration; point?: Vec2Like };
    body.removeForce(body.applyForce(plainForce, plainOptions));
    const forceId = this.nextForceId++;
    this.operate(id, {
      op: 'applyForce',
      force: plainForce,
      duration: plainOptions.duration,
      ...(plainOptions.point === undefined ? {} : { point: plainOptions.point }),
      forceId,
    });
    return forceId as ForceId;
  }

  /** Applies a torque (N m) for a duration; returns its id. */
  applyTorque(id: BodyId, torque: number, options: { duration?: Duration } = {}): ForceId {
    const body = this.requireBody(id);
    const plainOptions = plainCopy(options, 'options') as { duration?: Duration };
    body.removeForce(body.applyTorque(torque, plainOptions));
    const forceId = this.nextForceId++;
    this.operate(id, { op: 'applyTorque', torque, duration: plainOptions.duration, forceId });
    return forceId as ForceId;
  }

  /** Stops a force or torque before its duration ends. */
  removeForce(id: BodyId, force: ForceId): void {
    this.requireBody(id);
    if (!Number.isInteger(force) || force < 1 || force >= this.nextForceId) {
      throw new PhysicalError('force', `must be a force id from this world, got ${String(force)}.`);
    }
    this.operate(id, { op: 'removeForce', forceId: force });
  }

  /** Removes every force of a body. */
  clearForces(id: BodyId): void {
    this.requireBody(id);
    this.operate(id, { op: 'clearForces' });
  }

  /** Applies an impulse (N s) at a world point (default: the centre of mass). */
  applyImpulse(id: BodyId, impulse: Vec2Like, point?: Vec2Like): void {
    const body = this.requireBody(id);
    const plainImpulse = plainVector(impulse) as Vec2Like;
    const plainPoint = plainVector(point) as Vec2Like | undefined;
    checkOnCopy(body, (copy) => copy.applyImpulse(plainImpulse, plainPoint));
    this.operate(id, {
      op: 'applyImpulse',
      impulse: plainImpulse,
      ...(plainPoint === undefined ? {} : { point: plainPoint }),
    });
  }

  /** Applies an angular impulse (N m s). */
  applyAngularImpulse(id: BodyId, impulse: number): void {
    const body = this.requireBody(id);
    checkOnCopy(body, (copy) => copy.applyAngularImpulse(impulse));
    this.operate(id, { op: 'applyAngularImpulse', impulse });
  }

  /** Sets the velocity of the centre of mass (m/s). */
  setLinearVelocity(id: BodyId, velocity: Vec2Like): void {
    this.set(id, 'linearVelocity', velocity);
  }

  /** Sets the angular velocity (rad/s). */
  setAngularVelocity(id: BodyId, velocity: number): void {
    this.set(id, 'angularVelocity', velocity);
  }

  /** Teleports a body (m); it is drawn there at once. */
  setPosition(id: BodyId, position: Vec2Like): void {
    this.set(id, 'position', position);
  }

  /** Turns a body (rad); it is drawn so at once. */
  setAngle(id: BodyId, angle: number): void {
    this.set(id, 'angle', angle);
  }

  /**
   * Sets a property of a body as `body[property] = value` would (checked on the page copy first:
   * the same PhysicalError). Only the settable properties ({@link BodyProperty}) are accepted;
   * another name throws a PhysicalError naming `property`.
   */
  set(id: BodyId, property: BodyProperty, value: unknown): void {
    const body = this.requireBody(id);
    if (
      typeof property !== 'string' ||
      !(BODY_PROPERTIES as readonly string[]).includes(property)
    ) {
      throw new PhysicalError(
        'property',
        `must be one of ${BODY_PROPERTIES.join(', ')}, got ${String(property)}.`,
      );
    }
    // Vectors are read once into plain { x, y }: the page checks what the worker receives.
    if (property === 'position' || property === 'linearVelocity') value = plainVector(value);
    (body as unknown as Record<string, unknown>)[property] = value;
    if (property === 'position' || property === 'angle') {
      const position = body.position;
      for (const poses of [this.current, this.previous]) {
        poses[3 * id] = position.x;
        poses[3 * id + 1] = position.y;
        poses[3 * id + 2] = body.angle;
      }
    }
    this.operate(id, { op: 'set', property, value });
  }

  /** Wakes a body. */
  wake(id: BodyId): void {
    this.requireBody(id);
    this.operate(id, { op: 'wake' });
  }

  /** Puts a body to sleep. */
  sleep(id: BodyId): void {
    this.requireBody(id);
    this.operate(id, { op: 'sleep' });
  }

  // ------------------------------------------------------------------ settings

  /** Gravity (m/s^2). */
  get gravity(): Readonly<Vec2> {
    return this.settings.gravity;
  }

  set gravity(value: Vec2Like) {
    this.setting('gravity', plainVector(value));
  }

  /** Sub-steps per step. */
  get subSteps(): number {
    return this.settings.subSteps;
  }

  set subSteps(value: number) {
    this.setting('subSteps', value);
  }

  /** Restitution threshold (m/s). */
  get restitutionThreshold(): number {
    return this.settings.restitutionThreshold;
  }

  set restitutionThreshold(value: number) {
    this.setting('restitutionThreshold', value);
  }

  /** Whether resting bodies sleep. */
  get enableSleep(): boolean {
    return this.settings.enableSleep;
  }

  set enableSleep(value: boolean) {
    this.setting('enableSleep', value);
  }

  // ------------------------------------------------------------------ time

  /**
   * Asks the worker for one step of `dt` seconds (default 1/60), after every change made so far.
   * Applies the poses of the steps that arrived since the last call first: the page is drawn one
   * step behind the worker, and never waits for it.
   */
  step(dt: number = 1 / 60): void {
    // The engine's own rule (range, and 0 is no step), thrown here rather than in the worker.
    checkTimeStep(dt);
    if (dt === 0) return;
    this.requestSteps(dt, 1);
  }

  /** Applies what arrived, then asks the worker for `count` steps of `dt` in one message. */
  private requestSteps(dt: number, count: number): void {
    this.applyArrived();
    this.sentSteps += count;
    this.post({ type: 'step', dt, count });
  }

  /**
   * Steps the world at `stepsPerSecond` from the page's animation frames, without a
   * `<physical-canvas>` (for a world drawn in the worker, see `offscreen`); at most 4 steps a
   * frame. Returns a function that stops it.
   */
  run(stepsPerSecond = 60): () => void {
    if (!(stepsPerSecond > 0) || !Number.isFinite(stepsPerSecond)) {
      throw new PhysicalError(
        'stepsPerSecond',
        `must be a positive number, got ${String(stepsPerSecond)}.`,
      );
    }
    const dt = 1 / stepsPerSecond;
    checkTimeStep(dt);
    let last = -1;
    let debt = 0;
    let handle = 0;
    const frame = (now: number): void => {
      debt = last < 0 ? dt : Math.min(debt + (now - last) / 1000, 4 * dt);
      last = now;
      // The steps this frame owes, as far as the worker is not still busy with earlier ones
      // (then the time is dropped rather than queued: see stepsInFlight).
      let count = 0;
      while (debt >= dt && this.stepsInFlight + count < MAX_REMOTE_STEPS_IN_FLIGHT) {
        count++;
        debt -= dt;
      }
      if (debt >= dt) debt %= dt;
      // One message per frame: a worker that draws (offscreen) draws once for all of them.
      if (count > 0 && this.failure === null) this.requestSteps(dt, count);
      if (this.failure === null) handle = requestAnimationFrame(frame);
    };
    handle = requestAnimationFrame(frame);
    return () => cancelAnimationFrame(handle);
  }

  /** Steps whose poses the page has applied. */
  get steps(): number {
    return this.stepsValue;
  }

  /** Steps asked for so far. */
  get requestedSteps(): number {
    return this.sentSteps;
  }

  /**
   * Steps asked for whose results have not come back from the worker yet. {@link run} and
   * `<physical-canvas>` take no new steps while {@link MAX_REMOTE_STEPS_IN_FLIGHT} are in flight,
   * so a worker that cannot keep up slows the simulation down instead of falling ever further
   * behind the page. {@link step} itself always queues.
   */
  get stepsInFlight(): number {
    return this.sentSteps - this.stepsValue - this.frames.length - this.lostSteps;
  }

  /**
   * Resolves once the worker has handled everything posted so far, with its poses applied: after
   * `await world.flush()`, {@link position} reads the state after the last {@link step}.
   */
  async flush(): Promise<void> {
    await this.ask({ kind: 'hash' });
    this.applyArrived();
  }

  /** Awake bodies after the last applied step. */
  get awakeBodyCount(): number {
    // Until a step asked for after the page's last change has come back, the change may have
    // woken something: count one, so a canvas keeps stepping.
    if (this.awake === 0 && this.stepsValue <= this.changedAt) return 1;
    return this.awake;
  }

  // ------------------------------------------------------------------ poses and queries

  /** Position (m) of a body after the last applied step (a new object). */
  position(id: BodyId): Vec2 {
    this.requireBody(id);
    return { x: this.current[3 * id]!, y: this.current[3 * id + 1]! };
  }

  /** Angle (rad) of a body after the last applied step. */
  angle(id: BodyId): number {
    this.requireBody(id);
    return this.current[3 * id + 2]!;
  }

  /**
   * The body under a world point (m) at the last applied step, or null; answered on the page at
   * once (from the poses), as `World.bodyAt`.
   */
  bodyIdAt(point: Vec2Like): BodyId | null {
    const body = this.bodyAt(point);
    return body === null ? null : (this.idByBody.get(body)! as BodyId);
  }

  /** The full state of a body, read from the worker. */
  getBody(id: BodyId): Promise<WorkerBodyState | null> {
    if (!Number.isInteger(id)) {
      throw new PhysicalError('id', `must be a body id, got ${String(id)}.`);
    }
    return this.ask({ kind: 'body', id }) as Promise<WorkerBodyState | null>;
  }

  /** The first body hit by a ray, read from the worker. */
  rayCast(from: Vec2Like, to: Vec2Like): Promise<WorkerRayCastHit | null> {
    const a = plainVector(from) as Vec2Like;
    const b = plainVector(to) as Vec2Like;
    checkRay(a, b);
    return this.ask({ kind: 'rayCast', from: a, to: b }) as Promise<WorkerRayCastHit | null>;
  }

  /** Bodies whose boxes overlap a box (m), read from the worker. */
  bodiesInAABB(box: { minX: number; minY: number; maxX: number; maxY: number }): Promise<BodyId[]> {
    const copy = plainCopy(box, 'box') as {
      minX: number;
      minY: number;
      maxX: number;
      maxY: number;
    };
    checkQueryBox(copy);
    const { minX, minY, maxX, maxY } = copy;
    return this.ask({ kind: 'bodiesInAABB', box: { minX, minY, maxX, maxY } }) as Promise<BodyId[]>;
  }

  /**
   * The worker world's state hash (FNV-1a over every body's float64 position, angle and
   * velocities; see `worldStateHash`), after everything posted so far.
   */
  stateHash(): Promise<string> {
    return this.ask({ kind: 'hash' }) as Promise<string>;
  }

  // ------------------------------------------------------------------ events

  /**
   * Listens to an event. Step events (`collision`, `contactBegin`, `contactEnd`, `sensorBegin`,
   * `sensorEnd`, `move`) arrive batched, once per step, in the engine's order; the worker records
   * only the kinds someone listens to. Returns a function that removes the listener.
   */
  on<K extends keyof WorkerWorldEvents>(type: K, listener: WorkerWorldEvents[K]): () => void {
    let set = this.listeners.get(type);
    if (set === undefined) {
      set = new Set();
      this.listeners.set(type, set);
    }
    set.add(listener as Listener);
    this.updateListening();
    return () => this.off(type, listener);
  }

  /** Removes a listener added with {@link on}. */
  off<K extends keyof WorkerWorldEvents>(type: K, listener: WorkerWorldEvents[K]): void {
    this.listeners.get(type)?.delete(listener as Listener);
    this.updateListening();
  }

  /** Stops the worker. The world cannot be used afterwards. */
  terminate(): void {
    this.post({ type: 'close' });
    this.worker.terminate?.();
    this.fail(new Error('the worker world was terminated'), false);
  }

  // ------------------------------------------------------------------ DrawingSource

  /**
   * The page copies of the bodies (for `<physical-canvas>`): their shapes, type and userData;
   * their own poses lag (read {@link position}).
   */
  get bodies(): readonly Body[] {
    // Not synced: the canvas draws them at `remote.poseOf`, and syncing 2,000 copies each frame
    // would cost the main thread what the worker saves it.
    return this.bodyList;
  }

  /**
   * The page copies of the joints (for `<physical-canvas>`): type, bodies and anchors. The joints
   * themselves live in the worker.
   */
  get joints(): readonly PageJoint[] {
    return this.jointList;
  }

  /** The page copy under a world point (m), or null (for `<physical-canvas>`'s hit-testing). */
  bodyAt(point: Vec2Like): Body | null {
    this.syncCopies();
    return bodyAtPoint(this.bodyList, point);
  }

  /** Contacts are not streamed: visits none. */
  forEachContact(_visitor: (contact: ContactView) => void): void {}

  /** How `<physical-canvas>` draws and drags this world. */
  readonly remote: RemoteDrawing = {
    poseOf: (body: Body, _index: number, alpha: number, out: Pose): Pose => {
      const id = this.idByBody.get(body);
      if (id === undefined) {
        out.x = body.position.x;
        out.y = body.position.y;
        out.angle = body.angle;
        return out;
      }
      const k = 3 * id;
      const beta = 1 - alpha;
      const current = this.current;
      const previous = this.previous;
      out.x = beta * previous[k]! + alpha * current[k]!;
      out.y = beta * previous[k + 1]! + alpha * current[k + 1]!;
      out.angle = beta * previous[k + 2]! + alpha * current[k + 2]!;
      return out;
    },
    grab: (pointerId, body, x, y, toX, toY) => {
      const id = this.idByBody.get(body);
      if (id === undefined || body.type !== 'dynamic') return false;
      this.post({ type: 'grab', pointerId, id, x, y, toX, toY });
      this.changed();
      return true;
    },
    // A held body may have fallen asleep (and the canvas gone idle): moving or letting go
    // wakes it in the worker, and the canvas here.
    moveGrab: (pointerId, x, y) => {
      this.post({ type: 'grabMove', pointerId, x, y });
      this.changed();
    },
    releaseGrab: (pointerId, vx, vy, isThrow) => {
      this.post({ type: 'grabEnd', pointerId, vx, vy, isThrow });
      this.changed();
    },
    stepsInFlight: () => this.stepsInFlight,
  };

  // ------------------------------------------------------------------ internals

  private requireBody(id: BodyId, field = 'id'): Body {
    const body = this.bodyById.get(id);
    if (body === undefined) {
      throw new PhysicalError(field, `must be the id of a body in this world, got ${String(id)}.`);
    }
    return body;
  }

  private operate(id: number, operation: BodyOperation): void {
    this.post({ type: 'body', id, operation });
    this.changed();
  }

  /** The page changed the world: a sleeping canvas wakes up. */
  private changed(): void {
    this.changedAt = this.sentSteps;
    this.emit('wake');
  }

  /** Checks a setting with the engine's own rule (its error), posts what it holds, keeps it. */
  private setting(name: WorldSetting, value: unknown): void {
    const held = checkWorldSetting(name, value);
    this.post({ type: 'setting', name, value: held });
    (this.settings as unknown as Record<string, unknown>)[name] = held;
    this.changed();
  }

  private post(message: ToWorker, transfer: Transferable[] = []): void {
    if (this.failure !== null) throw this.failure;
    this.worker.postMessage(message, transfer);
  }

  private ask(query: Query): Promise<unknown> {
    if (this.failure !== null) return Promise.reject(this.failure);
    const queryId = this.nextQueryId++;
    return new Promise((resolve, reject) => {
      this.pending.set(queryId, { resolve, reject });
      try {
        this.post({ type: 'query', queryId, query });
      } catch (error) {
        this.pending.delete(queryId);
        reject(error as Error);
      }
    });
  }

  private receive(message: FromWorker): void {
    switch (message.type) {
      case 'frame':
        if (message.poses !== null) this.frames.push(message.poses);
        this.awake = message.awake;
        if (message.events !== null) this.dispatch(message.events as WorkerEvent[]);
        if (message.poses === null) this.frames.push(EMPTY); // a shared frame: read at apply
        return;
      case 'reply': {
        const entry = this.pending.get(message.queryId);
        this.pending.delete(message.queryId);
        entry?.resolve(message.value);
        return;
      }
      case 'failure': {
        const error =
          message.field === null
            ? new Error(message.message)
            : new PhysicalError(message.field, message.message.replace(`${message.field}: `, ''));
        // A request the worker failed to answer settles with the error; steps it failed to take
        // never come back, so they stop counting as in flight.
        this.lostSteps += message.lostSteps;
        if (message.queryId !== null) {
          const entry = this.pending.get(message.queryId);
          this.pending.delete(message.queryId);
          entry?.reject(error);
        }
        this.emit('error', error);
        return;
      }
    }
  }

  /**
   * Calls the listeners of a step's events. An event naming a body that is not in the page's
   * world (removed since the worker recorded it, even by an earlier listener of the same batch,
   * or one the worker added itself) is dropped: no event names a body after `remove` returned.
   */
  private dispatch(events: readonly WorkerEvent[]): void {
    for (const event of events) {
      const set = this.listeners.get(event.type);
      if (set === undefined) continue;
      for (const listener of set) {
        if (!this.namesKnownBodies(event)) break;
        (listener as (event: WorkerEvent) => void)(event);
      }
    }
  }

  private namesKnownBodies(event: WorkerEvent): boolean {
    const known = this.bodyById;
    switch (event.type) {
      case 'move':
        return known.has(event.body);
      case 'sensorBegin':
      case 'sensorEnd':
        return known.has(event.sensorBody) && known.has(event.visitorBody);
      default:
        return known.has(event.bodyA) && known.has(event.bodyB);
    }
  }

  /** Applies the poses of every step that arrived since the last call. */
  private applyArrived(): void {
    const frames = this.frames;
    if (frames.length === 0) return;
    const current = this.current;
    const previous = this.previous;
    // Bodies that moved in the last applied batch stop blending (their previous catches up).
    for (const id of this.touched) {
      const k = 3 * id;
      previous[k] = current[k]!;
      previous[k + 1] = current[k + 1]!;
      previous[k + 2] = current[k + 2]!;
    }
    this.touched.length = 0;
    this.batch++;
    let bytes = 0;
    for (const frame of frames) {
      if (frame === EMPTY) {
        if (this.shared !== null) this.readShared();
        continue;
      }
      bytes += frame.byteLength;
      this.applyPoses(frame, frame.length / POSE_STRIDE);
    }
    this.stepsValue += frames.length;
    frames.length = 0;
    this.lastPoseBytes = bytes;
    this.emit('frame', this.stepsValue);
  }

  private readShared(): void {
    const shared = this.shared!;
    const frame = shared.frame;
    if (frame === this.sharedFrame) return;
    this.sharedFrame = frame;
    const { poses, count } = shared.read(frame);
    this.applyPoses(poses, count);
  }

  private applyPoses(poses: Float32Array, count: number): void {
    const current = this.current;
    const previous = this.previous;
    for (let i = 0; i < count; i++) {
      const n = POSE_STRIDE * i;
      const id = poses[n]!;
      if (!this.bodyById.has(id)) continue; // removed since
      const k = 3 * id;
      if (this.stamps[id] !== this.batch) {
        this.stamps[id] = this.batch;
        this.touched.push(id);
      }
      this.stale.add(id);
      previous[k] = current[k]!;
      previous[k + 1] = current[k + 1]!;
      previous[k + 2] = current[k + 2]!;
      current[k] = poses[n + 1]!;
      current[k + 1] = poses[n + 2]!;
      current[k + 2] = poses[n + 3]!;
    }
  }

  /** Brings the page copies' poses up to date (only for queries: drawing reads `current`). */
  private syncCopies(): void {
    if (this.stale.size === 0) return;
    const current = this.current;
    for (const id of this.stale) {
      const body = this.bodyById.get(id);
      if (body === undefined) continue;
      const k = 3 * id;
      body.position = { x: current[k]!, y: current[k + 1]! };
      body.angle = current[k + 2]!;
    }
    this.stale.clear();
  }

  private ensureCapacity(id: number): void {
    if (this.current.length >= 3 * (id + 1)) return;
    const size = Math.max(3 * (id + 1), 2 * this.current.length, 3 * 64);
    const current = new Float64Array(size);
    current.set(this.current);
    const previous = new Float64Array(size);
    previous.set(this.previous);
    this.current = current;
    this.previous = previous;
    const stamps = new Int32Array(size / 3 + 1);
    stamps.set(this.stamps);
    this.stamps = stamps;
  }

  private updateListening(): void {
    const events = STREAMED.filter((type) => (this.listeners.get(type)?.size ?? 0) > 0);
    const key = events.join(',');
    if (key === this.listening) return;
    this.listening = key;
    this.post({ type: 'listen', events });
  }

  private emit<K extends keyof WorkerWorldEvents>(
    type: K,
    ...args: Parameters<WorkerWorldEvents[K]>
  ): void {
    const set = this.listeners.get(type);
    if (set === undefined) return;
    for (const listener of set) (listener as (...a: unknown[]) => void)(...args);
  }

  private fail(error: Error, report = true): void {
    if (this.failure !== null) return;
    this.failure = error;
    // Nothing more comes back: no step stays in flight.
    this.lostSteps = this.sentSteps - this.stepsValue - this.frames.length;
    for (const { reject } of this.pending.values()) reject(error);
    this.pending.clear();
    if (report) this.emit('error', error);
  }
}

/** Marks a frame whose poses are in shared memory. */
const EMPTY = new Float32Array(0);

/** Runs a check that changes the body on the page copy, then puts its velocity back. */
function checkOnCopy(body: Body, change: (copy: Body) => void): void {
  const v = body.linearVelocity;
  const vx = v.x;
  const vy = v.y;
  const w = body.angularVelocity;
  change(body);
  body.linearVelocity = { x: vx, y: vy };
  body.angularVelocity = w;
}
