import {
  PhysicalError,
  World,
  checkWorldSetting,
  mouseJoint,
  type Body,
  type CollisionEvent,
  type ContactEvent,
  type Force,
  type Joint,
  type MouseJoint,
  type SensorEvent,
} from '@physical/engine';
import { buildJoint } from './build-joint.ts';
import { buildBody } from './definitions.ts';
import { OffscreenRenderer } from './offscreen-renderer.ts';
import type { WorkerEvent } from './events.ts';
import type { BodyId } from './ids.ts';
import { POSE_STRIDE, SharedPoses } from './pose-stream.ts';
import { BODY_PROPERTIES } from './protocol.ts';
import type { BodyOperation, FromWorker, Query, StreamedEvent, ToWorker } from './protocol.ts';
import { worldStateHash } from './state-hash.ts';

/**
 * Most steps one `step` message may ask for: the page asks at most a frame's worth (4); a
 * malformed message asking for a billion would hang the worker.
 */
const MAX_STEPS_PER_MESSAGE = 1000;

/** The events a page can listen to. */
const STREAMED: readonly string[] = [
  'collision',
  'contactBegin',
  'contactEnd',
  'sensorBegin',
  'sensorEnd',
  'move',
];

/** A new id from the page: a non-negative integer not in use in `used`. */
function requireNewId(id: unknown, used: Map<number, unknown>): number {
  if (!Number.isInteger(id) || (id as number) < 0 || used.has(id as number)) {
    throw new PhysicalError('id', `must be a new non-negative integer id, got ${String(id)}.`);
  }
  return id as number;
}

/** Fastest throw (m/s), as `<physical-canvas>`'s own dragging. */
const MAX_THROW_SPEED = 50;

/** Where the worker talks to the page: the worker's global scope, or a MessagePort in tests. */
export interface WorkerEndpoint {
  postMessage(message: unknown, transfer: Transferable[]): void;
  addEventListener(type: 'message', listener: (event: MessageEvent) => void): void;
}

/**
 * Serves a world to a {@link WorkerWorld} on the page. Call it once in the worker module:
 *
 * ```ts
 * // physics.worker.ts
 * import { serveWorld } from '@physical/worker';
 * serveWorld();
 * ```
 *
 * Resolves with the world the worker simulates, once the page's `WorkerWorld` has connected and
 * the world was made with its options, so the worker may also build scenes or run logic next to
 * it: what it adds there is simulated, but not known to the page (the page receives neither its
 * poses nor events that name it).
 */
export function serveWorld(
  endpoint: WorkerEndpoint = self as unknown as WorkerEndpoint,
): Promise<World> {
  return new Promise((resolve) => new WorldServer(endpoint, resolve));
}

class WorldServer {
  /** Made on `init`, with the page's options. */
  world = new World();
  private initialized = false;
  private readonly onInit: (world: World) => void;
  private readonly endpoint: WorkerEndpoint;
  private readonly bodies = new Map<number, Body>();
  private readonly ids = new Map<Body, number>();
  private readonly joints = new Map<number, Joint>();
  private readonly forces = new Map<number, Force>();
  private readonly grabs = new Map<number, MouseJoint>();
  private shared: SharedPoses | null = null;
  private renderer: OffscreenRenderer | null = null;
  /** Bodies sent in the last frame (a body that falls asleep is sent once more, at rest). */
  private sentLast = new Set<Body>();
  private sentNow = new Set<Body>();
  private events: WorkerEvent[] = [];
  private readonly offs = new Map<StreamedEvent, () => void>();

  /** Steps of the current `step` message not taken yet (reported lost if one fails). */
  private stepsLeft = 0;

  constructor(endpoint: WorkerEndpoint, onInit: (world: World) => void) {
    this.endpoint = endpoint;
    this.onInit = onInit;
    endpoint.addEventListener('message', (event) => {
      const message = event.data as ToWorker;
      try {
        this.handle(message);
      } catch (error) {
        // The page validates first, so this is a bug, a race or the worker's own code (a
        // listener that throws): report it rather than die silently, and settle what the page
        // waits for (the query, the steps not taken).
        const field = error instanceof PhysicalError ? error.field : null;
        const queryId =
          message !== null && typeof message === 'object' && message.type === 'query'
            ? message.queryId
            : null;
        const lostSteps = this.stepsLeft;
        this.stepsLeft = 0;
        this.events = []; // a failed step's events name a state the page never receives
        this.post({
          type: 'failure',
          message: String((error as Error | undefined)?.message ?? error),
          field,
          queryId,
          lostSteps,
        });
      }
    });
  }

  private post(message: FromWorker, transfer: Transferable[] = []): void {
    this.endpoint.postMessage(message, transfer);
  }

  private body(id: number): Body {
    const body = this.bodies.get(id);
    if (body === undefined) throw new PhysicalError('id', `no body ${id} in the worker world.`);
    return body;
  }

  private handle(message: ToWorker): void {
    if (message === null || typeof message !== 'object') {
      throw new PhysicalError('message', `must be an object with a type, got ${String(message)}.`);
    }
    switch (message.type) {
      case 'init':
        if (this.initialized) throw new Error('a worker serves one WorkerWorld (init twice).');
        this.world = new World(message.options);
        this.initialized = true;
        this.shared = message.shared === null ? null : new SharedPoses(message.shared);
        this.renderer =
          message.offscreen === null ? null : new OffscreenRenderer(message.offscreen);
        this.onInit(this.world);
        return;
      case 'add': {
        requireNewId(message.id, this.bodies);
        const body = buildBody(message.definition);
        this.world.add(body);
        this.bodies.set(message.id, body);
        this.ids.set(body, message.id);
        return;
      }
      case 'remove': {
        const body = this.body(message.id);
        this.world.remove(body);
        this.bodies.delete(message.id);
        this.ids.delete(body);
        return;
      }
      case 'addJoint':
        requireNewId(message.id, this.joints);
        this.joints.set(
          message.id,
          this.world.addJoint(buildJoint(message.definition, (id) => this.body(id))),
        );
        return;
      case 'removeJoint': {
        const joint = this.joints.get(message.id);
        this.joints.delete(message.id);
        if (joint !== undefined && joint.world !== null) this.world.removeJoint(joint);
        return;
      }
      case 'body':
        this.operate(this.body(message.id), message.operation);
        return;
      case 'setting':
        // Only the four settings, checked as the page checks them: a name such as `__proto__`
        // or `step` would otherwise replace the world's own members.
        (this.world as unknown as Record<string, unknown>)[message.name] = checkWorldSetting(
          message.name,
          message.value,
        );
        return;
      case 'step':
        if (
          !Number.isInteger(message.count) ||
          message.count < 1 ||
          message.count > MAX_STEPS_PER_MESSAGE
        ) {
          throw new PhysicalError(
            'count',
            `must be an integer from 1 to ${MAX_STEPS_PER_MESSAGE}, got ${String(message.count)}.`,
          );
        }
        this.stepsLeft = message.count;
        for (let i = 0; i < message.count; i++) {
          this.step(message.dt);
          this.stepsLeft--;
        }
        // One drawing per step request: the page asks at most its frame rate's worth.
        this.renderer?.draw(this.world);
        return;
      case 'listen':
        this.listen(message.events);
        return;
      case 'query':
        this.post({ type: 'reply', queryId: message.queryId, value: this.answer(message.query) });
        return;
      case 'grab':
        this.grab(message);
        return;
      case 'grabMove': {
        const joint = this.grabs.get(message.pointerId);
        if (joint !== undefined && joint.world !== null)
          joint.target = { x: message.x, y: message.y };
        return;
      }
      case 'grabEnd':
        this.release(message.pointerId, message.vx, message.vy, message.isThrow);
        return;
      case 'close':
        (self as unknown as { close?: () => void }).close?.();
        return;
      default:
        throw new PhysicalError(
          'type',
          `is not a message type of this version, got ${String((message as { type: unknown }).type)}.`,
        );
    }
  }

  private operate(body: Body, operation: BodyOperation): void {
    switch (operation.op) {
      case 'applyForce': {
        const options = forceOptions(operation.duration, operation.point);
        this.forces.set(operation.forceId, body.applyForce(operation.force, options));
        return;
      }
      case 'applyTorque': {
        const options = forceOptions(operation.duration, undefined);
        this.forces.set(operation.forceId, body.applyTorque(operation.torque, options));
        return;
      }
      case 'removeForce': {
        const force = this.forces.get(operation.forceId);
        this.forces.delete(operation.forceId);
        if (force !== undefined) body.removeForce(force);
        return;
      }
      case 'clearForces':
        body.clearForces();
        return;
      case 'applyImpulse':
        body.applyImpulse(operation.impulse, operation.point);
        return;
      case 'applyAngularImpulse':
        body.applyAngularImpulse(operation.impulse);
        return;
      case 'set':
        // Only the settable properties: another name (`__proto__`, `type`) would corrupt the body.
        if (!(BODY_PROPERTIES as readonly unknown[]).includes(operation.property)) {
          throw new PhysicalError(
            'property',
            `must be one of ${BODY_PROPERTIES.join(', ')}, got ${String(operation.property)}.`,
          );
        }
        (body as unknown as Record<string, unknown>)[operation.property] = operation.value;
        return;
      case 'wake':
        body.wake();
        return;
      case 'sleep':
        body.sleep();
        return;
    }
  }

  private step(dt: number): void {
    const world = this.world;
    world.step(dt);
    this.publish();
  }

  /** Sends the step's poses and events. */
  private publish(): void {
    const world = this.world;
    const bodies = world.bodies;
    let awake = 0;
    for (let i = 0; i < bodies.length; i++) if (bodies[i]!.isAwake) awake++;
    const events = this.events.length === 0 ? null : this.events;
    this.events = [];
    const shared = this.shared;
    if (shared !== null && bodies.length <= shared.capacity) {
      const out = shared.next();
      let n = 0;
      for (let i = 0; i < bodies.length; i++) {
        const body = bodies[i]!;
        if (body.type === 'static') continue;
        n = this.write(out, n, body);
      }
      shared.publish(n / POSE_STRIDE, awake, world.steps);
      this.post({ type: 'frame', step: world.steps, awake, poses: null, events });
      return;
    }
    const sentNow = this.sentNow;
    sentNow.clear();
    for (let i = 0; i < bodies.length; i++) {
      const body = bodies[i]!;
      if (body.type !== 'static' && (body.isAwake || this.sentLast.has(body))) sentNow.add(body);
    }
    const poses = new Float32Array(sentNow.size * POSE_STRIDE);
    let n = 0;
    for (const body of sentNow) n = this.write(poses, n, body);
    this.sentNow = this.sentLast;
    this.sentLast = sentNow;
    this.post({ type: 'frame', step: world.steps, awake, poses, events }, [poses.buffer]);
  }

  private write(out: Float32Array, n: number, body: Body): number {
    const position = body.position;
    out[n] = this.ids.get(body) ?? -1;
    out[n + 1] = position.x;
    out[n + 2] = position.y;
    out[n + 3] = body.angle;
    return n + POSE_STRIDE;
  }

  private listen(events: readonly StreamedEvent[]): void {
    if (!Array.isArray(events) || !events.every((type) => STREAMED.includes(type))) {
      throw new PhysicalError('events', `must be an array of ${STREAMED.join(', ')}.`);
    }
    for (const [type, off] of this.offs) {
      if (!events.includes(type)) {
        off();
        this.offs.delete(type);
      }
    }
    const id = (body: Body): BodyId => (this.ids.get(body) ?? -1) as BodyId;
    for (const type of events) {
      if (this.offs.has(type)) continue;
      const world = this.world;
      let off: () => void = () => undefined;
      switch (type) {
        case 'collision':
          off = world.on('collision', (event: CollisionEvent) => {
            const points = [];
            for (let i = 0; i < event.pointCount; i++) {
              const p = event.points[i]!;
              points.push({
                x: p.x,
                y: p.y,
                separation: p.separation,
                normalImpulse: p.normalImpulse,
                tangentImpulse: p.tangentImpulse,
              });
            }
            this.events.push({
              type: 'collision',
              bodyA: id(event.bodyA),
              bodyB: id(event.bodyB),
              normalX: event.normalX,
              normalY: event.normalY,
              points,
              normalImpulse: event.normalImpulse,
              tangentImpulse: event.tangentImpulse,
              approachSpeed: event.approachSpeed,
            });
          });
          break;
        case 'contactBegin':
        case 'contactEnd':
          off = world.on(type, (event: ContactEvent) => {
            this.events.push({ type, bodyA: id(event.bodyA), bodyB: id(event.bodyB) });
          });
          break;
        case 'sensorBegin':
        case 'sensorEnd':
          off = world.on(type, (event: SensorEvent) => {
            this.events.push({
              type,
              sensorBody: id(event.sensorBody),
              visitorBody: id(event.visitorBody),
            });
          });
          break;
        case 'move':
          off = world.on('move', (body: Body) => {
            this.events.push({ type: 'move', body: id(body) });
          });
          break;
      }
      this.offs.set(type, off);
    }
  }

  private answer(query: Query): unknown {
    const world = this.world;
    const id = (body: Body | null | undefined): number | null =>
      body === null || body === undefined ? null : (this.ids.get(body) ?? null);
    switch (query.kind) {
      case 'bodyAt':
        return id(world.bodyAt(query.point));
      case 'bodiesInAABB':
        return world.bodiesInAABB(query.box).map((body) => id(body));
      case 'rayCast': {
        const hit = world.rayCast(query.from, query.to);
        if (hit === null) return null;
        return {
          body: id(hit.shape.body),
          point: { x: hit.point.x, y: hit.point.y },
          normal: { x: hit.normal.x, y: hit.normal.y },
          fraction: hit.fraction,
        };
      }
      case 'hash':
        return worldStateHash(world);
      case 'body': {
        const body = this.bodies.get(query.id);
        if (body === undefined) return null;
        return {
          position: { ...body.position },
          angle: body.angle,
          linearVelocity: { ...body.linearVelocity },
          angularVelocity: body.angularVelocity,
          isAwake: body.isAwake,
        };
      }
      default:
        throw new PhysicalError('query', 'must be a query of this version.');
    }
  }

  private grab(message: Extract<ToWorker, { type: 'grab' }>): void {
    this.release(message.pointerId, 0, 0, false);
    const body = this.bodies.get(message.id);
    if (body === undefined || body.type !== 'dynamic' || !this.world.has(body)) return;
    const joint = this.world.addJoint(mouseJoint({ body, target: { x: message.x, y: message.y } }));
    joint.target = { x: message.toX, y: message.toY };
    this.grabs.set(message.pointerId, joint);
  }

  private release(pointerId: number, vx: number, vy: number, isThrow: boolean): void {
    const joint = this.grabs.get(pointerId);
    if (joint === undefined) return;
    this.grabs.delete(pointerId);
    if (joint.world === null) return;
    this.world.removeJoint(joint);
    if (!isThrow) return;
    const speed = Math.hypot(vx, vy);
    const cap = speed > MAX_THROW_SPEED ? MAX_THROW_SPEED / speed : 1;
    joint.body.linearVelocity = { x: vx * cap, y: vy * cap };
  }
}

function forceOptions(duration: unknown, point: unknown): object {
  const options: Record<string, unknown> = {};
  if (duration !== undefined) options['duration'] = duration;
  if (point !== undefined) options['point'] = point;
  return options;
}
