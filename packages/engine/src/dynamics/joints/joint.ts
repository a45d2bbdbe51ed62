import type { JointBatch } from './joint-batch.ts';
import { PhysicalError, readOnly } from '../../core/errors.ts';
import {
  describeValue,
  MAX_ANGLE,
  MAX_COORDINATE,
  MAX_DAMPING_RATIO,
  MAX_FORCE,
  MAX_HERTZ,
  MAX_SPEED,
  optionalBoolean,
  requireNonNegative,
  requireRange,
  requireVector,
} from '../../core/validate.ts';
import type { Vec2, Vec2Like } from '../../math/vec2.ts';
import type { World } from '../../world/world.ts';
import type { Body } from '../body.ts';
import { STATE_STRIDE } from '../body-state.ts';
import type { Softness } from '../softness.ts';
import type { PinChains, PinJoint } from './pin-chains.ts';

/** The kinds of joint. */
export type JointType = 'revolute' | 'prismatic' | 'distance' | 'weld' | 'mouse';

/** Options every two-body joint takes. */
export interface JointOptions<UserData = unknown> {
  /** First body. */
  readonly bodyA: Body;
  /** Second body; the reaction force is the joint's force on this body. */
  readonly bodyB: Body;
  /** Let the two joined bodies collide with each other. Default false. */
  readonly collideConnected?: boolean;
  /** Anything the app wants to keep with the joint (a colour, a game object). */
  readonly userData?: UserData;
}

/** @internal What a joint needs from the step to prepare and solve itself. */
export interface JointStep {
  /** Sub-step duration (s) and its inverse. */
  h: number;
  inverseH: number;
  /** Step duration (s). */
  dt: number;
  /** Softness of the rigid joints' position correction this step. */
  readonly softness: Softness;
  /**
   * Fastest a joint's position correction may ask its bodies to move (m/s): the world's
   * maxLinearSpeed, which no body exceeds anyway. A joint torn metres (or, restored from a
   * damaged snapshot, 4e10 m) open would otherwise ask for biasRate times that gap, an impulse no
   * speed limit can realise, that grows its warm start and spills into every contact.
   */
  maxBiasSpeed: number;
}

/**
 * @internal How a saved joint value is checked when a world snapshot is loaded: a switch, a
 * number (finite; at least zero; above zero; at least zero or Infinity) or a vector of two finite
 * numbers (any; of length 1).
 */
export type JointValueKind =
  | 'boolean'
  | 'finite'
  | 'nonNegative'
  | 'positive'
  | 'nonNegativeOrInfinity'
  | 'vector'
  | 'unitVector';

/** @internal A joint's saved numbers and switches, by name (world snapshots). */
export type JointState = Record<string, number | boolean | readonly number[]>;

/**
 * @internal What a snapshot saves of one kind of joint: each value's name and check, and the
 * pairs of values that must be ordered (first <= second), like a limit's lower and upper end.
 */
export interface JointStateLayout {
  readonly fields: Readonly<Record<string, JointValueKind>>;
  readonly ordered: readonly (readonly [string, string])[];
}

/** @internal Saved for every kind of joint: what the last step left (see {@link Joint.exportState}). */
export const JOINT_STATE: JointStateLayout = {
  fields: { reactionForce: 'vector', reactionTorque: 'finite', subStepDuration: 'positive' },
  ordered: [],
};

/** @internal A checked number of a joint state. */
export function stateNumber(state: JointState, key: string): number {
  return state[key] as number;
}

/** @internal A checked switch of a joint state. */
export function stateBoolean(state: JointState, key: string): boolean {
  return state[key] as boolean;
}

/** @internal A checked vector of a joint state. */
export function stateVector(state: JointState, key: string): readonly number[] {
  return state[key] as readonly number[];
}

/** @internal The two body-frame anchors (m) that revolute, prismatic, distance and weld joints keep. */
export interface LocalAnchors {
  localAnchorAX: number;
  localAnchorAY: number;
  localAnchorBX: number;
  localAnchorBY: number;
}

/** @internal Restores a joint's `localAnchorA` and `localAnchorB` from a saved state. */
export function importLocalAnchors(state: JointState, joint: LocalAnchors): void {
  const anchorA = stateVector(state, 'localAnchorA');
  const anchorB = stateVector(state, 'localAnchorB');
  joint.localAnchorAX = anchorA[0]!;
  joint.localAnchorAY = anchorA[1]!;
  joint.localAnchorBX = anchorB[0]!;
  joint.localAnchorBY = anchorB[1]!;
}

/**
 * A constraint between two bodies (or, for a {@link MouseJoint}, between a body and a point).
 * Build one with {@link revoluteJoint}, {@link prismaticJoint}, {@link distanceJoint},
 * {@link weldJoint} or {@link mouseJoint}, then `world.addJoint(joint)`.
 *
 * Joints are solved with Box2D v3's soft step (Erin Catto, "Solver2D", 2024; Box2D v3's joint
 * solvers): prepared once per step, warm-started, solved with soft position correction before the
 * contacts and relaxed without it after the positions move.
 */
export abstract class Joint<UserData = unknown> {
  /** What kind of joint this is. */
  abstract readonly type: JointType;
  /** @internal Behind {@link bodyA}. */
  bodyAValue: Body;
  /** First body (for a mouse joint, the dragged body, like {@link bodyB}). */
  get bodyA(): Body {
    return this.bodyAValue;
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set bodyA(_value: never) {
    readOnly('bodyA', 'a joint keeps its bodies (remove it and add a new one)');
  }
  /** @internal Behind {@link bodyB}. */
  bodyBValue: Body;
  /** Second body: the reaction force and torque act on it. */
  get bodyB(): Body {
    return this.bodyBValue;
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set bodyB(_value: never) {
    readOnly('bodyB', 'a joint keeps its bodies (remove it and add a new one)');
  }
  /** @internal Behind {@link collideConnected}. */
  collideConnectedValue: boolean;
  /** Whether the two bodies may collide with each other. */
  get collideConnected(): boolean {
    return this.collideConnectedValue;
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set collideConnected(_value: never) {
    readOnly('collideConnected', 'fixed when the joint is made');
  }
  /** Anything the app keeps with the joint. */
  userData: UserData | undefined;

  /** @internal The world holding the joint, or null. */
  worldRef: World | null = null;
  /** @internal Index in the world's joint list. */
  worldIndex = -1;
  /** @internal A removal was requested during a step. */
  removalPending = false;
  /** @internal State offsets (solverIndex * STATE_STRIDE) of the two bodies this step. */
  stateA = 0;
  /** @internal */
  stateB = 0;
  /** @internal Inverse masses as the solver sees them (0 for static, sleeping, kinematic). */
  invMassA = -0;
  /** @internal */
  invInertiaA = -0;
  /** @internal */
  invMassB = -0;
  /** @internal */
  invInertiaB = -0;
  /** @internal Impulses on body B summed over the sub-steps of the step (N s, N m s). */
  stepImpulseX = -0;
  /** @internal */
  stepImpulseY = -0;
  /** @internal */
  stepAngularImpulse = -0;
  /** @internal Reaction of the last step (N, N m). */
  reactionX = -0;
  /** @internal */
  reactionY = -0;
  /** @internal */
  reactionAngular = -0;
  /** @internal Sub-step duration of the last step (s), to turn a sub-step impulse into a force. */
  subStepDuration = 1 / 240;
  private readonly reactionView: Vec2 = { x: 0, y: 0 };
  private readonly anchorViewA: Vec2 = { x: 0, y: 0 };
  private readonly anchorViewB: Vec2 = { x: 0, y: 0 };

  constructor(options: JointOptions<UserData>, bodyA: Body, bodyB: Body) {
    this.bodyAValue = bodyA;
    this.bodyBValue = bodyB;
    this.collideConnectedValue = optionalBoolean(
      'collideConnected',
      options.collideConnected,
      false,
    );
    this.userData = options.userData;
  }

  /** The world this joint is in, or null (null at once when its removal is queued in a listener). */
  get world(): World | null {
    return this.removalPending ? null : this.worldRef;
  }

  /**
   * Force the joint exerted on body B (N, world coordinates), averaged over the last step; body A
   * felt the opposite. A reused view: read it, do not keep it. For a rope or rod this is its tension.
   */
  get reactionForce(): Readonly<Vec2> {
    this.reactionView.x = this.reactionX;
    this.reactionView.y = this.reactionY;
    return this.reactionView;
  }

  /** Torque the joint exerted on body B (N m), averaged over the last step. */
  get reactionTorque(): number {
    return this.reactionAngular;
  }

  /**
   * The joint's point on body A in world coordinates (m), from the body's current pose: where a
   * renderer draws the joint. For a {@link MouseJoint}, the target. A reused view, like
   * `body.position`: read it, do not keep it.
   */
  get anchorA(): Readonly<Vec2> {
    this.writeAnchorA(this.anchorViewA);
    return this.anchorViewA;
  }

  /**
   * The joint's point on body B in world coordinates (m), from the body's current pose. A rigid
   * joint holds it on {@link anchorA}, up to its softness. A reused view: read it, do not keep it.
   */
  get anchorB(): Readonly<Vec2> {
    this.writeAnchorB(this.anchorViewB);
    return this.anchorViewB;
  }

  /** @internal Writes the world point of {@link anchorA} into `out`. */
  protected abstract writeAnchorA(out: Vec2): void;
  /** @internal Writes the world point of {@link anchorB} into `out`. */
  protected abstract writeAnchorB(out: Vec2): void;

  /** Wakes both bodies (a setting changed). */
  protected wakeBodies(): void {
    this.bodyA.wake();
    this.bodyB.wake();
  }

  /** @internal Looks up the bodies' solver slots and masses for this step, clears the step's sums. */
  prepareBodies(step: JointStep): void {
    this.subStepDuration = step.h;
    const a = this.bodyA;
    const b = this.bodyB;
    this.stateA = a.solverIndex * STATE_STRIDE;
    this.stateB = b.solverIndex * STATE_STRIDE;
    this.invMassA = a.solverIndex === 0 ? 0 : a.invMass;
    this.invInertiaA = a.solverIndex === 0 ? 0 : a.invInertia;
    this.invMassB = b.solverIndex === 0 ? 0 : b.invMass;
    this.invInertiaB = b.solverIndex === 0 ? 0 : b.invInertia;
    this.stepImpulseX = 0;
    this.stepImpulseY = 0;
    this.stepAngularImpulse = 0;
  }

  /** @internal Turns the step's summed impulses into average forces. */
  finishStep(dt: number): void {
    this.reactionX = this.stepImpulseX / dt;
    this.reactionY = this.stepImpulseY / dt;
    this.reactionAngular = this.stepAngularImpulse / dt;
  }

  /** @internal Clears what the joint carries between steps (on leaving a world). */
  resetReaction(): void {
    this.reactionX = 0;
    this.reactionY = 0;
    this.reactionAngular = 0;
  }

  /**
   * @internal Everything about the joint that decides later steps, by the names of its kind's
   * layout plus {@link JOINT_STATE} (world snapshots): frames, settings, and the accumulated
   * impulses the next step warm-starts from. What prepare() recomputes every step is left out.
   */
  exportState(): JointState {
    const state = this.exportOwnState();
    state['reactionForce'] = [this.reactionX, this.reactionY];
    state['reactionTorque'] = this.reactionAngular;
    state['subStepDuration'] = this.subStepDuration;
    return state;
  }

  /** @internal Puts back what {@link exportState} saved; the values were checked by the loader. */
  importState(state: JointState): void {
    this.importOwnState(state);
    const reaction = stateVector(state, 'reactionForce');
    this.reactionX = reaction[0]!;
    this.reactionY = reaction[1]!;
    this.reactionAngular = stateNumber(state, 'reactionTorque');
    this.subStepDuration = stateNumber(state, 'subStepDuration');
  }

  /** @internal The kind's own part of {@link exportState}. */
  protected abstract exportOwnState(): JointState;
  /** @internal The kind's own part of {@link importState}. */
  protected abstract importOwnState(state: JointState): void;

  /** @internal Anchors, effective masses and softness for this step. */
  abstract prepare(step: JointStep): void;
  /**
   * @internal The kind's batch (its joints' solver numbers of a step in flat arrays, warm-started
   * and solved in one loop per pass), made once per world by the first joint of the kind.
   */
  abstract createBatch(): JointBatch;
  /** @internal Forgets accumulated impulses (the joint was moved by hand or just created). */
  abstract resetImpulses(): void;

  /** @internal This joint as a pin for the exact chain solve (pin-chains.ts), if it is one. */
  pinJoint(): PinJoint | null {
    return null;
  }

  /** @internal The chain solve, made once by the first pin joint a world solves. */
  createChains(): PinChains | null {
    return null;
  }
}

/**
 * True when a joint between `a` and `b` forbids their collision (collideConnected false). Loops
 * over the shorter joint list: bodies carry few joints.
 */
export function jointPreventsCollision(a: Body, b: Body): boolean {
  const list = a.jointList.length <= b.jointList.length ? a.jointList : b.jointList;
  for (let i = 0; i < list.length; i++) {
    const joint = list[i]!;
    if (joint.collideConnected) continue;
    if ((joint.bodyA === a && joint.bodyB === b) || (joint.bodyA === b && joint.bodyB === a)) {
      return true;
    }
  }
  return false;
}

/** @internal Writes the world point of a body-local point (m) into `out`, without allocating. */
export function worldAnchor(body: Body, localX: number, localY: number, out: Vec2): void {
  const { c, s, x, y } = body.transform;
  out.x = c * localX - s * localY + x;
  out.y = s * localX + c * localY + y;
}

// ---------------------------------------------------------------- validation helpers

/**
 * @internal Checks the two bodies of a joint. Two bodies that cannot move may be joined (Box2D
 * allows it, and a grid pinned by several static bodies does it): such a joint never acts.
 */
export function requireBodies(options: JointOptions<unknown>): void {
  if (options === null || typeof options !== 'object') {
    throw new PhysicalError(
      'options',
      `must be an object of joint options, got ${describeValue(options)}.`,
    );
  }
  requireBody('bodyA', options.bodyA);
  requireBody('bodyB', options.bodyB);
  if (options.bodyA === options.bodyB) {
    throw new PhysicalError('bodyB', 'must be a different body from bodyA.');
  }
}

/** @internal */
export function requireBody(field: string, body: Body): void {
  if (body === null || typeof body !== 'object' || !('shapeList' in body)) {
    throw new PhysicalError(field, `must be a Body, got ${describeValue(body)}.`);
  }
}

/** @internal A world point (m), validated. */
export function requirePoint(field: string, point: Vec2Like | undefined): Vec2Like {
  if (point === undefined)
    throw new PhysicalError(field, 'is required: a world point { x, y } in metres.');
  requireVector(field, point);
  return point;
}

/**
 * @internal The largest magnitude of a joint setting, by its name: the engine's documented ranges
 * (stiffness in Hz, damping ratios, forces and torques, speeds, lengths and limits).
 */
export function jointMax(field: string): number {
  return JOINT_MAX[field] ?? MAX_COORDINATE;
}

/** @internal */
export const JOINT_MAX: Readonly<Record<string, number>> = {
  hertz: MAX_HERTZ,
  linearHertz: MAX_HERTZ,
  angularHertz: MAX_HERTZ,
  dampingRatio: MAX_DAMPING_RATIO,
  maxForce: MAX_FORCE,
  maxMotorForce: MAX_FORCE,
  maxMotorTorque: MAX_FORCE,
  motorSpeed: MAX_SPEED,
  lowerAngle: MAX_ANGLE,
  upperAngle: MAX_ANGLE,
};

/** @internal An optional non-negative number with a default. */
export function optionalNonNegative(
  field: string,
  value: number | undefined,
  fallback: number,
): number {
  return value === undefined ? fallback : requireNonNegative(field, value, jointMax(field));
}

/** @internal An optional finite number with a default. */
export function optionalFinite(field: string, value: number | undefined, fallback: number): number {
  return value === undefined
    ? fallback
    : requireRange(field, value, -jointMax(field), jointMax(field));
}

/** @internal Throws unless lower <= upper. */
export function requireOrdered(
  lowerField: string,
  lower: number,
  upperField: string,
  upper: number,
  changed: 'lower' | 'upper' = 'lower',
): void {
  if (lower <= upper) return;
  // The error names the bound the user changed (`slide.upper = -5` names upper, not lower).
  if (changed === 'upper') {
    throw new PhysicalError(
      upperField,
      `must not be below ${lowerField} (${lower}), got ${upper}.`,
    );
  }
  throw new PhysicalError(lowerField, `must not exceed ${upperField} (${upper}), got ${lower}.`);
}
