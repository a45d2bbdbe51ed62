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
  requirePositive,
  requireRange,
  requireVector,
} from '../../core/validate.ts';
import type { Vec2, Vec2Like } from '../../math/vec2.ts';
import type { World } from '../../world/world.ts';
import type { Body } from '../body.ts';
import { STATE_STRIDE } from '../body-state.ts';
import type { Softness } from '../softness.ts';
import {
  INV_I_A,
  INV_I_B,
  INV_MASS_A,
  INV_MASS_B,
  LOCAL_ANCHOR_AX,
  LOCAL_ANCHOR_AY,
  LOCAL_ANCHOR_BX,
  LOCAL_ANCHOR_BY,
  REACTION_ANGULAR,
  REACTION_X,
  REACTION_Y,
  REFERENCE_ANGLE,
  STATE_A,
  STATE_B,
  STEP_ANGULAR_IMPULSE,
  STEP_IMPULSE_X,
  STEP_IMPULSE_Y,
  SUB_STEP_DURATION,
} from './joint-record.ts';
import { JointStore } from './joint-store.ts';
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

/**
 * @internal Where a saved value lives in a joint's record (joint-record.ts): its check and its
 * offset (a vector: two numbers from there; a switch: 1 or 0).
 */
export type SavedFields = Readonly<Record<string, readonly [JointValueKind, number]>>;

/** @internal A kind's record: its size, what a snapshot saves of it, its warm-started impulses. */
export interface JointLayout {
  readonly stride: number;
  readonly saved: SavedFields;
  /** Offsets of the accumulated impulses, cleared when the joint is moved by hand or created. */
  readonly impulses: readonly number[];
}

/**
 * @internal A kind's layout from its parts: saved fields in the order given, impulses likewise.
 * (Built by a call, marked pure where a kind calls it, so a bundle that only checks joint options
 * drops it: spreads at a module's top level would count as side effects.)
 */
export function jointLayout(
  stride: number,
  saved: readonly SavedFields[],
  impulses: readonly (readonly number[])[],
): JointLayout {
  return { stride, saved: Object.assign({}, ...saved) as SavedFields, impulses: impulses.flat() };
}

/** @internal A snapshot's layout of a kind's saved values (its checks, from the one table). */
export function stateLayout(
  layout: Pick<JointLayout, 'saved'>,
  ordered: readonly (readonly [string, string])[],
): JointStateLayout {
  const saved = layout.saved;
  const fields: Record<string, JointValueKind> = {};
  for (const key of Object.keys(saved)) fields[key] = saved[key]![0];
  return { fields, ordered };
}

/** @internal The two anchors and the reference angle, as revolute, prismatic and weld save them. */
export const FRAME_SAVED: SavedFields = {
  localAnchorA: ['vector', LOCAL_ANCHOR_AX],
  localAnchorB: ['vector', LOCAL_ANCHOR_BX],
  referenceAngle: ['finite', REFERENCE_ANGLE],
};

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

  /** @internal Behind {@link worldRef}. */
  private worldValue: World | null = null;
  /**
   * @internal The world holding the joint, or null. Set to null when the joint leaves its world:
   * its record then moves out of the world's store into one of its own.
   */
  get worldRef(): World | null {
    return this.worldValue;
  }
  /** @internal */
  set worldRef(value: World | null) {
    this.worldValue = value;
    if (value === null && !this.store.local) this.store.release(this, this.layout.stride);
  }
  /** @internal Index in the world's joint list. */
  worldIndex = -1;
  /** @internal A removal was requested during a step. */
  removalPending = false;
  /** @internal The store holding this joint's record (joint-record.ts), and the record's offset. */
  store: JointStore;
  /** @internal */
  base = 0;
  private readonly reactionView: Vec2 = { x: 0, y: 0 };
  private readonly anchorViewA: Vec2 = { x: 0, y: 0 };
  private readonly anchorViewB: Vec2 = { x: 0, y: 0 };

  constructor(options: JointOptions<UserData>, bodyA: Body, bodyB: Body, stride: number) {
    this.bodyAValue = bodyA;
    this.bodyBValue = bodyB;
    this.collideConnectedValue = checkCollideConnected(options);
    this.userData = options.userData;
    this.store = JointStore.own(stride);
    this.store.data[SUB_STEP_DURATION] = 1 / 240;
  }

  /** @internal The kind's record layout. */
  protected abstract get layout(): JointLayout;

  /** The world this joint is in, or null (null at once when its removal is queued in a listener). */
  get world(): World | null {
    return this.removalPending ? null : this.worldRef;
  }

  /**
   * Force the joint exerted on body B (N, world coordinates), averaged over the last step; body A
   * felt the opposite. A reused view: read it, do not keep it. For a rope or rod this is its tension.
   */
  get reactionForce(): Readonly<Vec2> {
    this.reactionView.x = this.value(REACTION_X);
    this.reactionView.y = this.value(REACTION_Y);
    return this.reactionView;
  }

  /** Torque the joint exerted on body B (N m), averaged over the last step. */
  get reactionTorque(): number {
    return this.value(REACTION_ANGULAR);
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

  /** @internal Writes the world point of {@link anchorA} into `out` (A's local anchor). */
  protected writeAnchorA(out: Vec2): void {
    worldAnchor(this.bodyA, this.value(LOCAL_ANCHOR_AX), this.value(LOCAL_ANCHOR_AY), out);
  }

  /** @internal Writes the world point of {@link anchorB} into `out` (B's local anchor). */
  protected writeAnchorB(out: Vec2): void {
    worldAnchor(this.bodyB, this.value(LOCAL_ANCHOR_BX), this.value(LOCAL_ANCHOR_BY), out);
  }

  // ---------------------------------------------------------------- the record, for the kinds

  /** @internal A number of the record. */
  protected value(offset: number): number {
    return this.store.data[this.base + offset]!;
  }

  /** @internal A switch of the record (1 or 0). */
  protected flag(offset: number): boolean {
    return this.store.data[this.base + offset] === 1;
  }

  /** @internal Writes a number of the record (checked by the caller). */
  protected write(offset: number, value: number): void {
    this.store.data[this.base + offset] = value;
  }

  /**
   * @internal The setter of a setting named `field`: checked against the setting's range
   * ({@link jointMax}; `sign` says whether it may be negative or zero), then the bodies wake.
   */
  protected setNumber(
    field: string,
    offset: number,
    value: number,
    sign: 'any' | 'nonNegative' | 'positive',
  ): void {
    const max = jointMax(field);
    this.store.data[this.base + offset] =
      sign === 'any'
        ? requireRange(field, value, -max, max)
        : sign === 'positive'
          ? requirePositive(field, value, max)
          : requireNonNegative(field, value, max);
    this.wakeBodies();
  }

  /** Wakes both bodies (a setting changed). */
  protected wakeBodies(): void {
    this.bodyA.wake();
    if (this.bodyB !== this.bodyA) this.bodyB.wake();
  }

  // ---------------------------------------------------------------- the step

  /** @internal State offsets (solverIndex * STATE_STRIDE) of the two bodies this step. */
  get stateA(): number {
    return this.value(STATE_A);
  }
  /** @internal */
  get stateB(): number {
    return this.value(STATE_B);
  }
  /** @internal Inverse masses as the solver sees them (0 for static, sleeping, kinematic). */
  get invMassA(): number {
    return this.value(INV_MASS_A);
  }
  /** @internal */
  get invMassB(): number {
    return this.value(INV_MASS_B);
  }
  /** @internal A chain may stiffen it for the step (see PinChains.stiffen). */
  get invInertiaA(): number {
    return this.value(INV_I_A);
  }
  /** @internal */
  set invInertiaA(value: number) {
    this.write(INV_I_A, value);
  }
  /** @internal */
  get invInertiaB(): number {
    return this.value(INV_I_B);
  }
  /** @internal */
  set invInertiaB(value: number) {
    this.write(INV_I_B, value);
  }

  /** @internal Sub-step duration of the last step (s), to turn a sub-step impulse into a force. */
  get subStepDuration(): number {
    return this.value(SUB_STEP_DURATION);
  }

  /** @internal Looks up the bodies' solver slots and masses for this step, clears the step's sums. */
  prepareBodies(step: JointStep): void {
    const d = this.store.data;
    const o = this.base;
    d[o + SUB_STEP_DURATION] = step.h;
    const a = this.bodyA;
    const b = this.bodyB;
    d[o + STATE_A] = a.solverIndex * STATE_STRIDE;
    d[o + STATE_B] = b.solverIndex * STATE_STRIDE;
    d[o + INV_MASS_A] = a.solverIndex === 0 ? 0 : a.invMass;
    d[o + INV_I_A] = a.solverIndex === 0 ? 0 : a.invInertia;
    d[o + INV_MASS_B] = b.solverIndex === 0 ? 0 : b.invMass;
    d[o + INV_I_B] = b.solverIndex === 0 ? 0 : b.invInertia;
    d[o + STEP_IMPULSE_X] = 0;
    d[o + STEP_IMPULSE_Y] = 0;
    d[o + STEP_ANGULAR_IMPULSE] = 0;
  }

  /** @internal Clears what the joint carries between steps (on leaving a world). */
  resetReaction(): void {
    this.write(REACTION_X, 0);
    this.write(REACTION_Y, 0);
    this.write(REACTION_ANGULAR, 0);
  }

  /** @internal Forgets accumulated impulses (the joint was moved by hand or just created). */
  resetImpulses(): void {
    const impulses = this.layout.impulses;
    for (let i = 0; i < impulses.length; i++) this.write(impulses[i]!, 0);
  }

  /** @internal Where a snapshot's values of this kind live in the record (joint-state.ts). */
  get savedFields(): SavedFields {
    return this.layout.saved;
  }

  /** @internal Anchors, effective masses and softness for this step. */
  abstract prepare(step: JointStep): void;
  /**
   * @internal The kind's batch (its joints' records and the step's active ones, warm-started and
   * solved in one loop per pass), made once per world by the first joint of the kind.
   */
  abstract createBatch(): JointBatch;

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

/** @internal The options every joint has, checked: whether the joined bodies collide. */
export function checkCollideConnected(options: JointOptions<unknown>): boolean {
  return optionalBoolean('collideConnected', options.collideConnected, false);
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
