import type { BodyId } from './ids.ts';

/** A point of a {@link WorkerCollisionEvent}. */
export interface WorkerContactPoint {
  readonly x: number;
  readonly y: number;
  readonly separation: number;
  readonly normalImpulse: number;
  readonly tangentImpulse: number;
}

/** A collision of the last step, as the engine's `CollisionEvent` with body ids. */
export interface WorkerCollisionEvent {
  readonly type: 'collision';
  readonly bodyA: BodyId;
  readonly bodyB: BodyId;
  readonly normalX: number;
  readonly normalY: number;
  readonly points: readonly WorkerContactPoint[];
  readonly normalImpulse: number;
  readonly tangentImpulse: number;
  readonly approachSpeed: number;
}

/** Two bodies' shapes started or stopped touching. */
export interface WorkerContactEvent {
  readonly type: 'contactBegin' | 'contactEnd';
  readonly bodyA: BodyId;
  readonly bodyB: BodyId;
}

/** A body's shape started or stopped overlapping a sensor. */
export interface WorkerSensorEvent {
  readonly type: 'sensorBegin' | 'sensorEnd';
  readonly sensorBody: BodyId;
  readonly visitorBody: BodyId;
}

/** A body moved in the last step. */
export interface WorkerMoveEvent {
  readonly type: 'move';
  readonly body: BodyId;
}

/** Any event of a step. */
export type WorkerEvent =
  WorkerCollisionEvent | WorkerContactEvent | WorkerSensorEvent | WorkerMoveEvent;

/** Events of a {@link WorkerWorld}: name to listener. */
export interface WorkerWorldEvents {
  collision: (event: WorkerCollisionEvent) => void;
  contactBegin: (event: WorkerContactEvent) => void;
  contactEnd: (event: WorkerContactEvent) => void;
  sensorBegin: (event: WorkerSensorEvent) => void;
  sensorEnd: (event: WorkerSensorEvent) => void;
  move: (event: WorkerMoveEvent) => void;
  /** A step's frame arrived and was applied (its poses are the current ones). */
  frame: (step: number) => void;
  /** The worker failed (a crash, an uncaught error, a message that did not clone). */
  error: (error: Error) => void;
  /** A body left the world (page side: `remove`). For `<physical-canvas>`. */
  bodyRemoved: () => void;
  /** A body joined the world. For `<physical-canvas>`. */
  bodyAdded: () => void;
  /** Something woke or changed: a canvas that went idle draws again. */
  wake: () => void;
}
