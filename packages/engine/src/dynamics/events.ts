import type { Body } from './body.ts';
import type { Joint } from './joints/joint.ts';
import type { Shape } from './shape.ts';

/** One point of a collision: where the two shapes touch and what the solver did there. */
export interface ContactPoint {
  /** World position (m), midway between the two surfaces. */
  readonly x: number;
  readonly y: number;
  /** Signed distance between the surfaces (m), negative when overlapping. */
  readonly separation: number;
  /** Normal impulse applied this step at this point (N s), along the event's normal, on body B. */
  readonly normalImpulse: number;
  /** Friction impulse applied this step at this point (N s), along the tangent (normal turned by -90 degrees). */
  readonly tangentImpulse: number;
}

/**
 * A collision: the thesis's `onCollision`, emitted after every step in which the solver pushed two
 * shapes apart. Body B received `normalImpulse * normal` (plus friction) and body A the exact
 * opposite: Newton's third law, as the Reactions screen draws it.
 *
 * The event object is reused for the next event (no allocation per event): read what you need in
 * the listener, and copy it if you keep it.
 */
export interface CollisionEvent {
  readonly bodyA: Body;
  readonly bodyB: Body;
  readonly shapeA: Shape;
  readonly shapeB: Shape;
  /** Unit normal in world coordinates, pointing from A to B. */
  readonly normalX: number;
  readonly normalY: number;
  /** Number of valid entries in `points` (1 or 2). */
  readonly pointCount: number;
  /** Contact points; only the first `pointCount` are valid. */
  readonly points: readonly ContactPoint[];
  /** Total normal impulse of this step (N s), >= 0. Divide by the step's dt for an average force (N). */
  readonly normalImpulse: number;
  /** Total friction impulse of this step (N s). */
  readonly tangentImpulse: number;
  /** Speed at which the shapes approached along the normal before the step (m/s), >= 0 when closing. */
  readonly approachSpeed: number;
}

/** A pair of shapes in contact, as {@link World.forEachContact} shows it (same fields as a collision). */
export type ContactView = CollisionEvent;

/** Two shapes started or stopped touching. Reused like {@link CollisionEvent}. */
export interface ContactEvent {
  readonly bodyA: Body;
  readonly bodyB: Body;
  readonly shapeA: Shape;
  readonly shapeB: Shape;
}

/**
 * A shape started or stopped overlapping a sensor. Sent to the world and to both bodies. Reused
 * like {@link CollisionEvent}.
 */
export interface SensorEvent {
  /** The sensor shape and its body. */
  readonly sensorShape: Shape;
  readonly sensorBody: Body;
  /** The shape that entered or left the sensor, and its body. */
  readonly visitorShape: Shape;
  readonly visitorBody: Body;
}

/** Events of a body (and, for every body, of the world): name to listener. */
export interface BodyEvents {
  /** The body moved during the step (the thesis's `onMove`). */
  move: (body: Body) => void;
  /** The body took part in a collision this step (the thesis's `onCollision`). */
  collision: (event: CollisionEvent) => void;
  /** One of the body's shapes started touching another shape. */
  contactBegin: (event: ContactEvent) => void;
  /** One of the body's shapes stopped touching another shape (or one of them was removed). */
  contactEnd: (event: ContactEvent) => void;
  /** A shape started overlapping a sensor shape (the body is the sensor's or the visitor's). */
  sensorBegin: (event: SensorEvent) => void;
  /** A shape stopped overlapping a sensor shape, or one of them left the world. */
  sensorEnd: (event: SensorEvent) => void;
}

/** @internal The names of {@link BodyEvents}, checked by `body.on`. */
export const BODY_EVENT_NAMES: readonly (keyof BodyEvents)[] = [
  'move',
  'collision',
  'contactBegin',
  'contactEnd',
  'sensorBegin',
  'sensorEnd',
];

/** Events only a world has. */
export interface WorldOnlyEvents {
  /** A body joined the world (after `add`, or at the end of the step it was added in). */
  bodyAdded: (body: Body) => void;
  /** A body left the world. */
  bodyRemoved: (body: Body) => void;
  /** A joint left the world (removeJoint, or one of its bodies was removed). */
  jointRemoved: (joint: Joint) => void;
  /** A sleeping body woke up (a renderer that stopped drawing a sleeping world starts again). */
  wake: (body: Body) => void;
}

/** @internal The names of a world's events, checked by `world.on`. */
export const WORLD_EVENT_NAMES: readonly (keyof BodyEvents | keyof WorldOnlyEvents)[] = [
  ...BODY_EVENT_NAMES,
  'bodyAdded',
  'bodyRemoved',
  'jointRemoved',
  'wake',
];

/** Mutable point behind {@link ContactPoint}. */
export class ContactPointData implements ContactPoint {
  x = 0;
  y = 0;
  separation = 0;
  normalImpulse = 0;
  tangentImpulse = 0;
}

/** Mutable, reused event object behind {@link CollisionEvent}. */
export class CollisionEventData implements CollisionEvent {
  bodyA!: Body;
  bodyB!: Body;
  shapeA!: Shape;
  shapeB!: Shape;
  normalX = 0;
  normalY = 0;
  pointCount = 0;
  readonly points: readonly [ContactPointData, ContactPointData] = [
    new ContactPointData(),
    new ContactPointData(),
  ];
  normalImpulse = 0;
  tangentImpulse = 0;
  approachSpeed = 0;
}

/** Mutable, reused event object behind {@link ContactEvent}. */
export class ContactEventData implements ContactEvent {
  bodyA!: Body;
  bodyB!: Body;
  shapeA!: Shape;
  shapeB!: Shape;
}

/** Mutable, reused event object behind {@link SensorEvent}. */
export class SensorEventData implements SensorEvent {
  sensorShape!: Shape;
  sensorBody!: Body;
  visitorShape!: Shape;
  visitorBody!: Body;
}
