import type { Vec2Like, WorldOptions, WorldSettingName } from '@physical/engine';
import type { BodyDefinition, JointDefinition } from './definitions.ts';
import type { OffscreenView } from './offscreen-renderer.ts';

// The messages between a WorkerWorld (page) and serveWorld (worker). One ordered channel: the
// worker applies changes and steps in exactly the order the page made them, so the worker's
// world goes through the same calls as a World on the page would.

/** Events the page can listen to; the worker records only those listened to. */
export type StreamedEvent =
  'collision' | 'contactBegin' | 'contactEnd' | 'sensorBegin' | 'sensorEnd' | 'move';

/** A body operation that takes the body's id and plain arguments. */
export type BodyOperation =
  | {
      readonly op: 'applyForce';
      readonly force: Vec2Like;
      readonly duration?: unknown;
      readonly point?: Vec2Like;
      readonly forceId: number;
    }
  | {
      readonly op: 'applyTorque';
      readonly torque: number;
      readonly duration?: unknown;
      readonly forceId: number;
    }
  | { readonly op: 'removeForce'; readonly forceId: number }
  | { readonly op: 'clearForces' }
  | { readonly op: 'applyImpulse'; readonly impulse: Vec2Like; readonly point?: Vec2Like }
  | { readonly op: 'applyAngularImpulse'; readonly impulse: number }
  | { readonly op: 'set'; readonly property: BodyProperty; readonly value: unknown }
  | { readonly op: 'wake' }
  | { readonly op: 'sleep' };

/** Body properties a page may set. */
export type BodyProperty =
  | 'position'
  | 'angle'
  | 'linearVelocity'
  | 'angularVelocity'
  | 'gravityScale'
  | 'linearDamping'
  | 'angularDamping'
  | 'drag'
  | 'fixedRotation'
  | 'bullet'
  | 'allowSleep'
  | 'mass'
  | 'inertia';

// The run-time list `WorkerWorld.set` checks. Typed as a record over BodyProperty, so the compiler
// refuses a property missing from it or one it does not name: the union stays the one source.
const SETTABLE: { readonly [P in BodyProperty]: true } = {
  position: true,
  angle: true,
  linearVelocity: true,
  angularVelocity: true,
  gravityScale: true,
  linearDamping: true,
  angularDamping: true,
  drag: true,
  fixedRotation: true,
  bullet: true,
  allowSleep: true,
  mass: true,
  inertia: true,
};

/** @internal The body properties a page may set, checked at run time by `WorkerWorld.set`. */
export const BODY_PROPERTIES = Object.keys(SETTABLE) as readonly BodyProperty[];

/** World settings a page may change while it runs. */
export type WorldSetting = WorldSettingName;

/** A query answered by the worker's world. */
export type Query =
  | { readonly kind: 'bodyAt'; readonly point: Vec2Like }
  | { readonly kind: 'rayCast'; readonly from: Vec2Like; readonly to: Vec2Like }
  | {
      readonly kind: 'bodiesInAABB';
      readonly box: { minX: number; minY: number; maxX: number; maxY: number };
    }
  | { readonly kind: 'hash' }
  | { readonly kind: 'body'; readonly id: number };

/** Page to worker. */
export type ToWorker =
  | {
      readonly type: 'init';
      readonly options: WorldOptions;
      /** Shared pose memory when the page is cross-origin isolated. */
      readonly shared: SharedArrayBuffer | null;
      /** Draw in the worker into this canvas (transferred). */
      readonly offscreen: OffscreenView | null;
    }
  | { readonly type: 'add'; readonly id: number; readonly definition: BodyDefinition }
  | { readonly type: 'remove'; readonly id: number }
  | { readonly type: 'addJoint'; readonly id: number; readonly definition: JointDefinition }
  | { readonly type: 'removeJoint'; readonly id: number }
  | { readonly type: 'body'; readonly id: number; readonly operation: BodyOperation }
  | { readonly type: 'setting'; readonly name: WorldSetting; readonly value: unknown }
  | { readonly type: 'step'; readonly dt: number; readonly count: number }
  | { readonly type: 'listen'; readonly events: readonly StreamedEvent[] }
  | { readonly type: 'query'; readonly queryId: number; readonly query: Query }
  | {
      readonly type: 'grab';
      readonly pointerId: number;
      readonly id: number;
      readonly x: number;
      readonly y: number;
      readonly toX: number;
      readonly toY: number;
    }
  | {
      readonly type: 'grabMove';
      readonly pointerId: number;
      readonly x: number;
      readonly y: number;
    }
  | {
      readonly type: 'grabEnd';
      readonly pointerId: number;
      readonly vx: number;
      readonly vy: number;
      readonly isThrow: boolean;
    }
  | { readonly type: 'close' };

/** Worker to page. */
export type FromWorker =
  | {
      readonly type: 'frame';
      /** Steps taken so far. */
      readonly step: number;
      /** Awake bodies after the step. */
      readonly awake: number;
      /** Poses (see pose-stream.ts), or null when they are in shared memory. */
      readonly poses: Float32Array | null;
      /** The step's events, flattened (see event-batch.ts); null when none. */
      readonly events: readonly unknown[] | null;
    }
  | { readonly type: 'reply'; readonly queryId: number; readonly value: unknown }
  | {
      readonly type: 'failure';
      readonly message: string;
      readonly field: string | null;
      /** The query the worker failed to answer, or null. */
      readonly queryId: number | null;
      /** Steps asked for that the worker did not take (they send no frame). */
      readonly lostSteps: number;
    };
