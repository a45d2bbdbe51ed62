import { callAll, type Listeners, type ListenerEntry } from '../core/listeners.ts';
import { bodyListeners, type Body } from '../dynamics/body.ts';
import {
  CONTACT_STRIDE,
  NORMAL_X,
  NORMAL_Y,
  POINT_COUNT,
  POINT_STRIDE,
  POINTS,
  P_RELATIVE_VELOCITY,
  P_SEPARATION,
  P_STEP_NORMAL_IMPULSE,
  P_STEP_TANGENT_IMPULSE,
  P_X,
  P_Y,
} from '../dynamics/contact-data.ts';
import type { ContactManager } from '../dynamics/contact-manager.ts';
import {
  CollisionEventData,
  ContactEventData,
  SensorEventData,
  type BodyEvents,
  type WorldOnlyEvents,
} from '../dynamics/events.ts';
import type { Sensors } from '../dynamics/sensor.ts';
import type { Shape } from '../dynamics/shape.ts';
import type { Solver } from '../dynamics/solver.ts';
import type { World } from './world.ts';

// The events of a step, after it (stage 8 of World.step), and the contact and sensor ends that
// adding, removing and changing bodies report. The rules, written down in the engine's README
// ("Changes made during a step or an event"):
// - An event that names a body queued for removal is not delivered, except the ends (contactEnd,
//   sensorEnd): every begin gets its end. The check runs before each listener, so a listener that
//   removes a body stops the same event from reaching the listeners after it.
// - A body's own listeners get nothing once it is not in the world (`world.has(body)` false):
//   neither the rest of the step's events nor the ends of the contacts it leaves.
// Event objects are reused: nothing here allocates.

/** A listener list of one event type. */
type List<E> = readonly ListenerEntry<(event: E) => void>[] | undefined;

/** @internal Delivers a world's events to its listeners and its bodies' listeners. */
export class EventDispatch {
  readonly collisionEvent = new CollisionEventData();
  private readonly contactEvent = new ContactEventData();
  private readonly sensorEvent = new SensorEventData();

  constructor(
    private readonly world: World,
    private readonly listeners: Listeners<BodyEvents & WorldOnlyEvents>,
    private readonly contactManager: ContactManager,
    private readonly sensors: Sensors,
    private readonly solver: Solver,
  ) {}

  /** The step's events: contact begins and ends, sensor begins, collisions, moves. */
  dispatchStep(): void {
    const manager = this.contactManager;
    for (let i = 0; i < manager.beganCount; i++) {
      this.emitContact('contactBegin', manager.beganShapeA(i), manager.beganShapeB(i));
    }
    this.dispatchEnds();
    this.dispatchSensorBegins();
    this.dispatchCollisions();
    this.dispatchMoves();
  }

  /** The contact and sensor ends recorded so far (by the step, or by a removal). */
  dispatchEnds(): void {
    const manager = this.contactManager;
    const count = manager.endedCount;
    manager.endedCount = 0;
    const endedA = manager.endedA;
    const endedB = manager.endedB;
    for (let i = 0; i < count; i++) {
      this.emitContact('contactEnd', endedA[i]!, endedB[i]!);
      // Reported: the list no longer keeps the shapes (of a removed body) reachable.
      endedA[i] = endedB[i] = null as unknown as Shape;
    }
    const sensors = this.sensors;
    const ended = sensors.endedCount;
    sensors.endedCount = 0;
    const endedSensor = sensors.endedSensor;
    const endedVisitor = sensors.endedVisitor;
    for (let i = 0; i < ended; i++) {
      this.emitSensor('sensorEnd', endedSensor[i]!, endedVisitor[i]!);
      endedSensor[i] = endedVisitor[i] = null as unknown as Shape;
    }
  }

  /** A sleeping body woke (world listeners only; none for a body queued for removal). */
  emitWake(body: Body): void {
    const listeners = this.listeners.get('wake');
    if (listeners !== undefined) callWhileBoth(listeners, body, body, body);
  }

  private dispatchSensorBegins(): void {
    const sensors = this.sensors;
    const count = sensors.beganCount;
    sensors.beganCount = 0;
    for (let i = 0; i < count; i++) {
      this.emitSensor('sensorBegin', sensors.beganSensor[i]!, sensors.beganVisitor[i]!);
    }
  }

  private emitSensor(type: 'sensorBegin' | 'sensorEnd', sensor: Shape, visitor: Shape): void {
    const sensorBody = sensor.body;
    const visitorBody = visitor.body;
    const worldListeners = this.listeners.get(type);
    const sensorListeners = sensorBody.listeners.get(type);
    const visitorListeners = visitorBody.listeners.get(type);
    if (
      worldListeners === undefined &&
      sensorListeners === undefined &&
      visitorListeners === undefined
    )
      return;
    const event = this.sensorEvent;
    event.sensorShape = sensor;
    event.sensorBody = sensorBody;
    event.visitorShape = visitor;
    event.visitorBody = visitorBody;
    if (type === 'sensorEnd') {
      this.deliverEnd(
        worldListeners,
        sensorListeners,
        visitorListeners,
        event,
        sensorBody,
        visitorBody,
      );
    } else {
      deliver(worldListeners, sensorListeners, visitorListeners, event, sensorBody, visitorBody);
    }
    // The reused event keeps no body reachable once delivered (a removed one, with its userData).
    forgetSensorBodies(event);
  }

  private emitContact(type: 'contactBegin' | 'contactEnd', shapeA: Shape, shapeB: Shape): void {
    const bodyA = shapeA.body;
    const bodyB = shapeB.body;
    const worldListeners = this.listeners.get(type);
    const listenersA = bodyA.listeners.get(type);
    const listenersB = bodyB.listeners.get(type);
    if (worldListeners === undefined && listenersA === undefined && listenersB === undefined)
      return;
    const event = this.contactEvent;
    event.bodyA = bodyA;
    event.bodyB = bodyB;
    event.shapeA = shapeA;
    event.shapeB = shapeB;
    if (type === 'contactEnd') {
      this.deliverEnd(worldListeners, listenersA, listenersB, event, bodyA, bodyB);
    } else {
      deliver(worldListeners, listenersA, listenersB, event, bodyA, bodyB);
    }
    forgetBodies(event);
  }

  /** An end: every world listener, then each body's own while the body is in the world. */
  private deliverEnd<E>(
    worldListeners: List<E>,
    listenersA: List<E>,
    listenersB: List<E>,
    event: E,
    bodyA: Body,
    bodyB: Body,
  ): void {
    callAll(worldListeners, event);
    callWhileIn(listenersA, event, bodyA, this.world);
    if (bodyB !== bodyA) callWhileIn(listenersB, event, bodyB, this.world);
  }

  private dispatchCollisions(): void {
    const manager = this.contactManager;
    const slots = this.solver.constraints.slots;
    const worldListeners = this.listeners.get('collision');
    if (worldListeners === undefined && bodyListeners.total === 0) return;
    const event = this.collisionEvent;
    for (let i = 0; i < this.solver.constraints.count; i++) {
      const slot = slots[i]!;
      const bodyA = manager.bodyA(slot);
      const bodyB = manager.bodyB(slot);
      if (
        worldListeners === undefined &&
        bodyA.listeners.total === 0 &&
        bodyB.listeners.total === 0
      ) {
        continue;
      }
      const listenersA = bodyA.listeners.get('collision');
      const listenersB = bodyB.listeners.get('collision');
      if (worldListeners === undefined && listenersA === undefined && listenersB === undefined)
        continue;
      if (bodyA.removalPending || bodyB.removalPending) continue;
      this.fillCollisionEvent(slot, event);
      if (event.normalImpulse <= 0) continue;
      deliver(worldListeners, listenersA, listenersB, event, bodyA, bodyB);
    }
    forgetBodies(event);
  }

  /** Fills the reused collision event from contact slot `slot` (also `World.forEachContact`). */
  fillCollisionEvent(slot: number, event: CollisionEventData): void {
    const manager = this.contactManager;
    const data = manager.slots.data;
    const base = slot * CONTACT_STRIDE;
    const pointCount = data[base + POINT_COUNT]!;
    let normalImpulse = 0;
    let tangentImpulse = 0;
    let approach = 0;
    for (let j = 0; j < pointCount; j++) {
      const p = base + POINTS + j * POINT_STRIDE;
      // What the step delivered (all sub-steps plus restitution), not the per-sub-step warm start.
      const pointNormal = data[p + P_STEP_NORMAL_IMPULSE]!;
      const pointTangent = data[p + P_STEP_TANGENT_IMPULSE]!;
      normalImpulse += pointNormal;
      tangentImpulse += pointTangent;
      approach = Math.max(approach, -data[p + P_RELATIVE_VELOCITY]!);
      const point = event.points[j]!;
      point.x = data[p + P_X]!;
      point.y = data[p + P_Y]!;
      point.separation = data[p + P_SEPARATION]!;
      point.normalImpulse = pointNormal;
      point.tangentImpulse = pointTangent;
    }
    event.bodyA = manager.bodyA(slot);
    event.bodyB = manager.bodyB(slot);
    event.shapeA = manager.shapeA(slot);
    event.shapeB = manager.shapeB(slot);
    event.normalX = data[base + NORMAL_X]!;
    event.normalY = data[base + NORMAL_Y]!;
    event.pointCount = pointCount;
    event.normalImpulse = normalImpulse;
    event.tangentImpulse = tangentImpulse;
    event.approachSpeed = approach;
  }

  private dispatchMoves(): void {
    const awake = this.solver.awake;
    const worldListeners = this.listeners.get('move');
    if (worldListeners === undefined && bodyListeners.total === 0) return;
    for (let i = 0; i < this.solver.awakeCount; i++) {
      const body = awake[i]!;
      if (worldListeners === undefined && body.listeners.total === 0) continue;
      const listeners = body.listeners.get('move');
      if ((worldListeners === undefined && listeners === undefined) || body.removalPending)
        continue;
      const moved =
        body.centerX !== body.center0X ||
        body.centerY !== body.center0Y ||
        body.angleValue !== body.angle0;
      if (!moved) continue;
      if (callWhileBoth(worldListeners, body, body, body))
        callWhileBoth(listeners, body, body, body);
    }
  }
}

/**
 * A reused collision or contact event keeps no body reachable once delivered (a removed one, with
 * its userData), nor between steps.
 */
export function forgetBodies(event: CollisionEventData | ContactEventData): void {
  event.shapeA = event.shapeB = null as unknown as Shape;
  event.bodyA = event.bodyB = null as unknown as Body;
}

/** The same for the reused sensor event. */
function forgetSensorBodies(event: SensorEventData): void {
  event.sensorShape = event.visitorShape = null as unknown as Shape;
  event.sensorBody = event.visitorBody = null as unknown as Body;
}

/** A begin, collision or move: world listeners, then each body's, while neither is queued out. */
function deliver<E>(
  worldListeners: List<E>,
  listenersA: List<E>,
  listenersB: List<E>,
  event: E,
  bodyA: Body,
  bodyB: Body,
): void {
  if (!callWhileBoth(worldListeners, event, bodyA, bodyB)) return;
  if (!callWhileBoth(listenersA, event, bodyA, bodyB)) return;
  if (bodyB !== bodyA) callWhileBoth(listenersB, event, bodyA, bodyB);
}

/**
 * Calls the listeners still registered while neither body is queued for removal (a listener may
 * queue one); false once one is.
 */
function callWhileBoth<E>(listeners: List<E>, event: E, bodyA: Body, bodyB: Body): boolean {
  if (listeners !== undefined) {
    for (let i = 0; i < listeners.length; i++) {
      if (bodyA.removalPending || bodyB.removalPending) return false;
      const entry = listeners[i]!;
      if (entry.active) entry.listener(event);
    }
  }
  return !(bodyA.removalPending || bodyB.removalPending);
}

/** Calls a body's own listeners while the body is in the world (not removed, nor queued out). */
function callWhileIn<E>(listeners: List<E>, event: E, body: Body, world: World): void {
  if (listeners === undefined) return;
  for (let i = 0; i < listeners.length; i++) {
    if (body.worldRef !== world || body.removalPending) return;
    const entry = listeners[i]!;
    if (entry.active) entry.listener(event);
  }
}
