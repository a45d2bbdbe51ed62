// @physical/worker's public API. Everything not listed here is internal.

export { WorkerWorld } from './worker-world.ts';
export type {
  WorkerBodyState,
  WorkerLike,
  WorkerRayCastHit,
  WorkerWorldOptions,
} from './worker-world.ts';
export { serveWorld } from './serve-world.ts';
export type { WorkerEndpoint } from './serve-world.ts';
export { buildBody } from './definitions.ts';
export { buildJoint } from './build-joint.ts';
export type { PageJoint } from './page-joint.ts';
export type { BodyDefinition, Crossing, JointDefinition, WithIds } from './definitions.ts';
export type { BodyId, ForceId, JointId } from './ids.ts';
export type {
  WorkerCollisionEvent,
  WorkerContactEvent,
  WorkerContactPoint,
  WorkerEvent,
  WorkerMoveEvent,
  WorkerSensorEvent,
  WorkerWorldEvents,
} from './events.ts';
export type { BodyProperty } from './protocol.ts';
export { worldStateHash } from './state-hash.ts';
export type { OffscreenView } from './offscreen-renderer.ts';
