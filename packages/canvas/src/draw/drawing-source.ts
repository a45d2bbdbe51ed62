import type { Body, ContactView, Joint, Vec2Like } from '@physical/engine';
import type { Pose } from '../draw/pose.ts';

/**
 * What a collision arrow needs of a collision: the engine's `CollisionEvent` (reused, with
 * `pointCount` valid points) or a worker world's collision event (exactly its points).
 */
export interface CollisionLike {
  readonly normalX: number;
  readonly normalY: number;
  /** Total normal impulse of the step (N s). */
  readonly normalImpulse: number;
  readonly approachSpeed: number;
  readonly points: readonly { readonly x: number; readonly y: number }[];
  readonly pointCount?: number;
}

/**
 * What `<physical-canvas>` draws of a joint: an engine `Joint` is one, and so is a worker
 * world's page copy of a joint.
 */
export type DrawnJoint = Pick<Joint, 'type' | 'bodyA' | 'bodyB' | 'anchorA' | 'anchorB'>;

/**
 * What `<physical-canvas>` needs from a world to run and draw it. A `World` of
 * `@physical/engine` is one; so is a world that lives elsewhere (a worker) and keeps page copies
 * of its bodies: such a source adds {@link RemoteDrawing} as `remote`.
 */
export interface DrawingSource {
  /** The bodies to draw, in drawing order (the engine's `world.bodies`). */
  readonly bodies: readonly Body[];
  /** The joints to draw. */
  readonly joints: readonly DrawnJoint[];
  /** Bodies awake: 0 lets the element stop asking for frames. */
  readonly awakeBodyCount: number;
  /** Advances time by `dt` seconds (the element calls it at its fixed step). */
  step(dt: number): void;
  /** The body under a world point (m), for dragging and pointer events. */
  bodyAt(point: Vec2Like): Body | null;
  /** Visits the contacts (for the `contacts` and `normals` overlays). */
  forEachContact(visitor: (contact: ContactView) => void): void;
  /** Listens to changes that need a frame; returns the remover. */
  on(type: 'wake' | 'bodyAdded' | 'bodyRemoved', listener: () => void): () => void;
  /**
   * Listens to each step's collisions (for `collision-arrows`; asked for only while they are
   * on); returns the remover.
   */
  on(type: 'collision', listener: (event: CollisionLike) => void): () => void;
  /** Present when the bodies' poses come from elsewhere (see {@link RemoteDrawing}). */
  readonly remote?: RemoteDrawing;
}

/**
 * A source whose bodies are stepped elsewhere: it supplies the poses to draw (interpolated
 * between its last two states) and takes the element's pointer drags. The bodies in `bodies` are
 * page copies whose own pose may lag; only `poseOf` is drawn.
 */
export interface RemoteDrawing {
  /** The pose to draw `body` at, `alpha` of the way from its previous to its current state. */
  poseOf(body: Body, index: number, alpha: number, out: Pose): Pose;
  /** A pointer pressed `body` at (x, y) and pulls that point to (toX, toY); false refuses. */
  grab(pointerId: number, body: Body, x: number, y: number, toX: number, toY: number): boolean;
  /** The pointer moved the pulled point to (x, y). */
  moveGrab(pointerId: number, x: number, y: number): void;
  /** The pointer let go, throwing with velocity (vx, vy) when `isThrow`. */
  releaseGrab(pointerId: number, vx: number, vy: number, isThrow: boolean): void;
  /**
   * Steps asked for whose results have not come back yet. While it is
   * {@link MAX_REMOTE_STEPS_IN_FLIGHT} or more, the element takes no new steps and drops that
   * time: a source that cannot keep up slows the simulation down, as a slow page world does,
   * instead of queueing steps without bound (and lagging further behind every frame).
   */
  stepsInFlight?(): number;
}

/**
 * Most steps a {@link RemoteDrawing} source may have in flight before the element waits for it:
 * two, so one late result does not cost a step, and a tap shows within about three frames.
 */
export const MAX_REMOTE_STEPS_IN_FLIGHT = 4;
