import { PhysicalError, readOnly } from '../core/errors.ts';
import { Listeners, type ListenerCount } from '../core/listeners.ts';
import {
  describeValue,
  MAX_ANGULAR_SPEED,
  MAX_DAMPING,
  MAX_FORCE,
  MAX_GRAVITY_SCALE,
  MAX_INERTIA,
  MAX_MASS,
  MAX_SPEED,
  MIN_INERTIA,
  MIN_MASS,
  optionalBoolean,
  optionalObject,
  requireAngle,
  requireBoolean,
  requireNonNegative,
  requireOneOf,
  requireRange,
  requireVector,
} from '../core/validate.ts';
import { computeCapsuleMass } from '../geometry/capsule.ts';
import { computeCircleMass } from '../geometry/circle.ts';
import { MassData } from '../geometry/mass-data.ts';
import { computePolygonMass } from '../geometry/polygon-mass.ts';
import type { BodyStore } from './body-memory.ts';
import {
  BODY_STRIDE,
  createLocalBodyStore,
  B_ANGLE,
  B_ANGLE0,
  B_ANGULAR_DAMPING,
  B_CENTER0_X,
  B_CENTER0_Y,
  B_CENTER_X,
  B_CENTER_Y,
  B_DRAG,
  B_FORCE_X,
  B_FORCE_Y,
  B_GRAVITY_SCALE,
  B_INERTIA,
  B_INERTIA_OVERRIDE,
  B_INV_INERTIA,
  B_INV_MASS,
  B_LINEAR_DAMPING,
  B_LOCAL_CENTER_X,
  B_LOCAL_CENTER_Y,
  B_MASS,
  B_MASS_OVERRIDE,
  B_MAX_EXTENT,
  B_MIN_EXTENT,
  B_ORIGIN_REACH,
  B_SLEEP_TIME,
  B_TORQUE,
  B_VX,
  B_VY,
  B_W,
  B_AWAKE,
  B_FLAGS,
  FLAG_FIXED_ROTATION,
  FLAG_ALLOW_SLEEP,
  FLAG_BULLET,
} from './body-memory.ts';
import { BodyTransform } from './body-transform.ts';
import type { Vec2, Vec2Like } from '../math/vec2.ts';
import type { World } from '../world/world.ts';
import type { BodyHost } from './body-host.ts';
import { BODY_EVENT_NAMES, type BodyEvents } from './events.ts';
import { Force, validateDuration, type ForceOptions, type TorqueOptions } from './force.ts';
import type { Joint } from './joints/joint.ts';
import { createGeometries, Shape, type ShapeOptions } from './shape.ts';
import { hypot } from '../math/hypot.ts';

/**
 * - `'dynamic'`: moved by forces and collisions; needs a positive mass.
 * - `'static'`: never moves (walls, the ground); infinite mass.
 * - `'kinematic'`: moves only by the velocity you give it; pushes dynamic bodies, is not pushed.
 */
export type BodyType = 'dynamic' | 'static' | 'kinematic';

/** Describes a body. Every field is optional; units are SI (m, kg, s, rad). */
export interface BodyOptions<UserData = unknown> {
  /** Default `'dynamic'`. */
  readonly type?: BodyType;
  /** Position of the body origin in world coordinates (m). Default (0, 0). */
  readonly position?: Vec2Like;
  /** Rotation (rad). Positive turns +x towards +y: clockwise on a y-down screen. Default 0. */
  readonly angle?: number;
  /** Velocity of the centre of mass (m/s). Default (0, 0). */
  readonly linearVelocity?: Vec2Like;
  /** Angular velocity (rad/s). Default 0. */
  readonly angularVelocity?: number;
  /** The body's shapes; several make a compound body. */
  readonly shapes?: readonly ShapeOptions[];
  /**
   * Overrides the mass computed from the shapes' density (kg, > 0). The centre of mass stays
   * where the shapes put it; the moment of inertia scales with the mass unless also given.
   */
  readonly mass?: number;
  /** Overrides the moment of inertia about the centre of mass (kg m^2, > 0). */
  readonly inertia?: number;
  /** Multiplies the world's gravity for this body. Default 1; 0 makes it float. */
  readonly gravityScale?: number;
  /** Linear damping (1/s): dv/dt = -c v. Default 0. Use it for "slows down by itself", not for air. */
  readonly linearDamping?: number;
  /** Angular damping (1/s). Default 0. */
  readonly angularDamping?: number;
  /**
   * The thesis's drag: a force against the motion, F = -drag * |v| * v (N s^2/m^2), as air exerts
   * on a moving object. Default 0.
   */
  readonly drag?: number;
  /** Prevents rotation (infinite moment of inertia). Default false. */
  readonly fixedRotation?: boolean;
  /**
   * A bullet: continuous collision also against moving (dynamic and kinematic) bodies, not only
   * static ones, so a fast projectile cannot pass through a thin moving body. Costs a sweep test
   * per step while fast. Default false.
   */
  readonly bullet?: boolean;
  /** Lets the body fall asleep when it comes to rest. Default true. */
  readonly allowSleep?: boolean;
  /** Starts asleep (it wakes on contact, force or any change). Default false. */
  readonly asleep?: boolean;
  /** The thesis's `onMove`: called after each step in which the body moved. */
  readonly onMove?: BodyEvents['move'];
  /** The thesis's `onCollision`: called after each step in which the body was in a collision. */
  readonly onCollision?: BodyEvents['collision'];
  /** Anything the app wants to keep with the body (a colour, a game object). */
  readonly userData?: UserData;
}

const BODY_TYPES: readonly BodyType[] = ['dynamic', 'static', 'kinematic'];

/** A body's mass properties, computed before they are installed. */
interface MassResult {
  mass: number;
  inertia: number;
  centerX: number;
  centerY: number;
}

function requireMass(value: number): number {
  return requireRange('mass', value, MIN_MASS, MAX_MASS, 'kg');
}

function requireInertia(value: number): number {
  return requireRange('inertia', value, MIN_INERTIA, MAX_INERTIA, 'kg m^2');
}

function requireAngularSpeed(value: number): number {
  return requireRange('angularVelocity', value, -MAX_ANGULAR_SPEED, MAX_ANGULAR_SPEED, 'rad/s');
}

function requireGravityScale(value: number): number {
  return requireRange('gravityScale', value, -MAX_GRAVITY_SCALE, MAX_GRAVITY_SCALE);
}

function requireDamping(field: string, value: number): number {
  return requireNonNegative(field, value, MAX_DAMPING);
}
const scratchMass = new MassData();

/**
 * @internal Listeners on every body of every world together: while 0, a step's event dispatch
 * skips its per-contact and per-body loops (they would find no body listener).
 */
export const bodyListeners: ListenerCount = { total: 0 };

/**
 * A rigid body: the thesis's RigidBody2D. Build one, then `world.add(body)`; or use the helpers
 * {@link particle}, {@link box}, {@link capsule}, {@link regularPolygon}, {@link polygon} and
 * {@link wall}.
 *
 * Coordinates are SI in a y-down world by default (x right, y down, like the screen).
 */
export class Body<UserData = unknown> {
  /** @internal The type behind {@link type}. */
  typeValue: BodyType;
  /** Dynamic, static or kinematic; fixed at creation. */
  get type(): BodyType {
    return this.typeValue;
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set type(_value: never) {
    readOnly('type', 'a body keeps the type it was made with (make a new body)');
  }

  /** Anything the app keeps with the body. */
  userData: UserData | undefined;

  // ---- Internal state. Fields marked @internal are stripped from the published types. ----
  // The body's numbers (pose, velocities, mass properties, settings, flags, sleep) are not
  // fields: they live in the body memory (body-memory.ts), in the world's solver memory while the
  // body is in a world, and the accessors below read and write them there. They start as -0, as
  // the fields they replace did; every zero an app can read is written as +0 before it can see
  // it (test/api/zeros-read-as-positive-zero). The remaining fields start as a value of their
  // final kind where declared, so V8 gives every body the same hidden class from the start.
  /**
   * @internal Where the body's numbers live (body-memory.ts): the world's body memory while in a
   * world, else a store of its own. Read `store.data` at each access: the world's view is
   * replaced when its memory moves.
   */
  store: BodyStore = createLocalBodyStore();
  /** @internal The body's first index in `store.data` (world index times BODY_STRIDE). */
  base = 0;
  /** @internal Transform of the body origin: a view of the body's numbers. */
  readonly transform: BodyTransform = new BodyTransform(this.store, 0);
  /** @internal Unwrapped rotation (rad). */
  get angleValue(): number {
    return this.store.data[this.base + B_ANGLE]!;
  }
  /** @internal */
  set angleValue(value: number) {
    this.store.data[this.base + B_ANGLE] = value;
  }
  /** @internal Centre of mass, world (m). */
  get centerX(): number {
    return this.store.data[this.base + B_CENTER_X]!;
  }
  /** @internal */
  set centerX(value: number) {
    this.store.data[this.base + B_CENTER_X] = value;
  }
  /** @internal */
  get centerY(): number {
    return this.store.data[this.base + B_CENTER_Y]!;
  }
  /** @internal */
  set centerY(value: number) {
    this.store.data[this.base + B_CENTER_Y] = value;
  }
  /** @internal Centre of mass, body-local (m). */
  get localCenterX(): number {
    return this.store.data[this.base + B_LOCAL_CENTER_X]!;
  }
  /** @internal */
  set localCenterX(value: number) {
    this.store.data[this.base + B_LOCAL_CENTER_X] = value;
  }
  /** @internal */
  get localCenterY(): number {
    return this.store.data[this.base + B_LOCAL_CENTER_Y]!;
  }
  /** @internal */
  set localCenterY(value: number) {
    this.store.data[this.base + B_LOCAL_CENTER_Y] = value;
  }
  /** @internal Centre of mass and angle at the start of the step, for continuous collision. */
  get center0X(): number {
    return this.store.data[this.base + B_CENTER0_X]!;
  }
  /** @internal */
  set center0X(value: number) {
    this.store.data[this.base + B_CENTER0_X] = value;
  }
  /** @internal */
  get center0Y(): number {
    return this.store.data[this.base + B_CENTER0_Y]!;
  }
  /** @internal */
  set center0Y(value: number) {
    this.store.data[this.base + B_CENTER0_Y] = value;
  }
  /** @internal */
  get angle0(): number {
    return this.store.data[this.base + B_ANGLE0]!;
  }
  /** @internal */
  set angle0(value: number) {
    this.store.data[this.base + B_ANGLE0] = value;
  }
  /** @internal Velocity of the centre of mass (m/s) and angular velocity (rad/s). */
  get velocityX(): number {
    return this.store.data[this.base + B_VX]!;
  }
  /** @internal */
  set velocityX(value: number) {
    this.store.data[this.base + B_VX] = value;
  }
  /** @internal */
  get velocityY(): number {
    return this.store.data[this.base + B_VY]!;
  }
  /** @internal */
  set velocityY(value: number) {
    this.store.data[this.base + B_VY] = value;
  }
  /** @internal */
  get angularVelocityValue(): number {
    return this.store.data[this.base + B_W]!;
  }
  /** @internal */
  set angularVelocityValue(value: number) {
    this.store.data[this.base + B_W] = value;
  }
  /** @internal Mass properties. */
  get massValue(): number {
    return this.store.data[this.base + B_MASS]!;
  }
  /** @internal */
  set massValue(value: number) {
    this.store.data[this.base + B_MASS] = value;
  }
  /** @internal */
  get invMass(): number {
    return this.store.data[this.base + B_INV_MASS]!;
  }
  /** @internal */
  set invMass(value: number) {
    this.store.data[this.base + B_INV_MASS] = value;
  }
  /** @internal */
  get inertiaValue(): number {
    return this.store.data[this.base + B_INERTIA]!;
  }
  /** @internal */
  set inertiaValue(value: number) {
    this.store.data[this.base + B_INERTIA] = value;
  }
  /** @internal */
  get invInertia(): number {
    return this.store.data[this.base + B_INV_INERTIA]!;
  }
  /** @internal */
  set invInertia(value: number) {
    this.store.data[this.base + B_INV_INERTIA] = value;
  }
  /** @internal */
  get massOverride(): number {
    return this.store.data[this.base + B_MASS_OVERRIDE]!;
  }
  /** @internal */
  set massOverride(value: number) {
    this.store.data[this.base + B_MASS_OVERRIDE] = value;
  }
  /** @internal */
  get inertiaOverride(): number {
    return this.store.data[this.base + B_INERTIA_OVERRIDE]!;
  }
  /** @internal */
  set inertiaOverride(value: number) {
    this.store.data[this.base + B_INERTIA_OVERRIDE] = value;
  }
  /** @internal Force and torque to apply this step (N, N m), gathered from `forces`. */
  get forceX(): number {
    return this.store.data[this.base + B_FORCE_X]!;
  }
  /** @internal */
  set forceX(value: number) {
    this.store.data[this.base + B_FORCE_X] = value;
  }
  /** @internal */
  get forceY(): number {
    return this.store.data[this.base + B_FORCE_Y]!;
  }
  /** @internal */
  set forceY(value: number) {
    this.store.data[this.base + B_FORCE_Y] = value;
  }
  /** @internal */
  get torqueValue(): number {
    return this.store.data[this.base + B_TORQUE]!;
  }
  /** @internal */
  set torqueValue(value: number) {
    this.store.data[this.base + B_TORQUE] = value;
  }
  /** @internal */
  get gravityScaleValue(): number {
    return this.store.data[this.base + B_GRAVITY_SCALE]!;
  }
  /** @internal */
  set gravityScaleValue(value: number) {
    this.store.data[this.base + B_GRAVITY_SCALE] = value;
  }
  /** @internal */
  get linearDampingValue(): number {
    return this.store.data[this.base + B_LINEAR_DAMPING]!;
  }
  /** @internal */
  set linearDampingValue(value: number) {
    this.store.data[this.base + B_LINEAR_DAMPING] = value;
  }
  /** @internal */
  get angularDampingValue(): number {
    return this.store.data[this.base + B_ANGULAR_DAMPING]!;
  }
  /** @internal */
  set angularDampingValue(value: number) {
    this.store.data[this.base + B_ANGULAR_DAMPING] = value;
  }
  /** @internal */
  get dragValue(): number {
    return this.store.data[this.base + B_DRAG]!;
  }
  /** @internal */
  set dragValue(value: number) {
    this.store.data[this.base + B_DRAG] = value;
  }
  /** @internal */
  get sleepTime(): number {
    return this.store.data[this.base + B_SLEEP_TIME]!;
  }
  /** @internal */
  set sleepTime(value: number) {
    this.store.data[this.base + B_SLEEP_TIME] = value;
  }
  /** @internal Largest and smallest distance from the centre of mass to the surface (m). */
  get maxExtent(): number {
    return this.store.data[this.base + B_MAX_EXTENT]!;
  }
  /** @internal */
  set maxExtent(value: number) {
    this.store.data[this.base + B_MAX_EXTENT] = value;
  }
  /** @internal */
  get minExtent(): number {
    return this.store.data[this.base + B_MIN_EXTENT]!;
  }
  /** @internal */
  set minExtent(value: number) {
    this.store.data[this.base + B_MIN_EXTENT] = value;
  }
  /** @internal Largest distance from the body origin to the surface (m), for manifold reuse. */
  get originReach(): number {
    return this.store.data[this.base + B_ORIGIN_REACH]!;
  }
  /** @internal */
  set originReach(value: number) {
    this.store.data[this.base + B_ORIGIN_REACH] = value;
  }
  /** @internal */
  get fixedRotationValue(): boolean {
    return (this.store.data[this.base + B_FLAGS]! & FLAG_FIXED_ROTATION) !== 0;
  }
  /** @internal */
  set fixedRotationValue(value: boolean) {
    const d = this.store.data;
    const i = this.base + B_FLAGS;
    d[i] = value ? d[i]! | FLAG_FIXED_ROTATION : d[i]! & ~FLAG_FIXED_ROTATION;
  }
  /** @internal */
  get allowSleepValue(): boolean {
    return (this.store.data[this.base + B_FLAGS]! & FLAG_ALLOW_SLEEP) !== 0;
  }
  /** @internal */
  set allowSleepValue(value: boolean) {
    const d = this.store.data;
    const i = this.base + B_FLAGS;
    d[i] = value ? d[i]! | FLAG_ALLOW_SLEEP : d[i]! & ~FLAG_ALLOW_SLEEP;
  }
  /** @internal */
  get bulletValue(): boolean {
    return (this.store.data[this.base + B_FLAGS]! & FLAG_BULLET) !== 0;
  }
  /** @internal */
  set bulletValue(value: boolean) {
    const d = this.store.data;
    const i = this.base + B_FLAGS;
    d[i] = value ? d[i]! | FLAG_BULLET : d[i]! & ~FLAG_BULLET;
  }
  /** @internal Awake (static bodies never are). */
  get awake(): boolean {
    return this.store.data[this.base + B_AWAKE] !== 0;
  }
  /** @internal */
  set awake(value: boolean) {
    this.store.data[this.base + B_AWAKE] = value ? 1 : 0;
  }
  /** @internal */
  readonly shapeList: Shape[] = [];
  /** @internal */
  readonly forceList: Force[] = [];
  /** @internal Joints attached to this body that are in the world. */
  readonly jointList: Joint[] = [];
  /** @internal The world holding the body, or null. */
  worldRef: World | null = null;
  /** @internal Index in the world's body array. */
  worldIndex = -1;
  /** @internal World-local id, stable while in the world. */
  id = -1;
  /** @internal Index in the solver's state arrays this step; 0 (the identity state) when not solved. */
  solverIndex = 0;
  /** @internal Stamp of the last island search that visited the body. */
  islandStamp = 0;
  /** @internal A removal was requested during a step; no more events. */
  removalPending = false;
  /** @internal */
  readonly listeners: Listeners<BodyEvents> = new Listeners<BodyEvents>(
    BODY_EVENT_NAMES,
    bodyListeners,
  );

  private readonly positionView: Vec2 = { x: 0, y: 0 };
  private readonly velocityView: Vec2 = { x: 0, y: 0 };
  private readonly centerView: Vec2 = { x: 0, y: 0 };

  constructor(options: BodyOptions<UserData> = {}) {
    optionalObject('options', options, 'an object of body options');
    const type = requireOneOf('type', options.type ?? 'dynamic', BODY_TYPES);
    this.typeValue = type;
    const position = options.position ?? { x: 0, y: 0 };
    requireVector('position', position);
    this.angleValue = requireAngle('angle', options.angle ?? 0);
    this.transform.set(position.x, position.y, this.angleValue);
    const velocity = options.linearVelocity ?? { x: 0, y: 0 };
    requireVector('linearVelocity', velocity, MAX_SPEED);
    const angularVelocity = requireAngularSpeed(options.angularVelocity ?? 0);
    this.gravityScaleValue = requireGravityScale(options.gravityScale ?? 1);
    this.linearDampingValue = requireDamping('linearDamping', options.linearDamping ?? 0);
    this.angularDampingValue = requireDamping('angularDamping', options.angularDamping ?? 0);
    this.dragValue = requireDamping('drag', options.drag ?? 0);
    this.fixedRotationValue = optionalBoolean('fixedRotation', options.fixedRotation, false);
    this.allowSleepValue = optionalBoolean('allowSleep', options.allowSleep, true);
    this.bulletValue = optionalBoolean('bullet', options.bullet, false);
    this.awake = type !== 'static' && !optionalBoolean('asleep', options.asleep, false);
    if (options.mass !== undefined) this.massOverride = requireMass(options.mass);
    if (options.inertia !== undefined) this.inertiaOverride = requireInertia(options.inertia);
    if (options.onMove !== undefined) this.listeners.on('move', options.onMove);
    if (options.onCollision !== undefined) this.listeners.on('collision', options.onCollision);
    this.userData = options.userData;

    const shapes = options.shapes ?? [];
    if (!Array.isArray(shapes)) {
      throw new PhysicalError('shapes', 'must be an array of shape descriptions.');
    }
    for (let i = 0; i < shapes.length; i++) {
      this.shapeList.push(...this.createShapes(shapes[i] as ShapeOptions, `shapes[${i}]`));
    }
    this.updateMassData();
    if (type !== 'static') {
      this.velocityX = velocity.x;
      this.velocityY = velocity.y;
      this.angularVelocityValue = this.fixedRotationValue ? 0 : angularVelocity;
    } else this.velocityX = this.velocityY = this.angularVelocityValue = 0; // +0, not -0
  }

  // ---------------------------------------------------------------- pose and velocity

  /** The world this body is in, or null (null at once when its removal is queued in a listener). */
  get world(): World | null {
    return this.removalPending ? null : this.worldRef;
  }

  /**
   * Position of the body origin in world coordinates (m). The returned object is a view the body
   * reuses: read it, do not keep or modify it. Setting it teleports the body and wakes it.
   */
  get position(): Readonly<Vec2> {
    this.positionView.x = this.transform.x;
    this.positionView.y = this.transform.y;
    return this.positionView;
  }

  set position(value: Vec2Like) {
    requireVector('position', value);
    this.transform.x = value.x;
    this.transform.y = value.y;
    this.syncCenter();
    this.host?.bodyMoved(this);
  }

  /** Rotation (rad), unwrapped (it keeps counting past 2 pi). Setting it wakes the body. */
  get angle(): number {
    return this.angleValue;
  }

  set angle(value: number) {
    this.angleValue = requireAngle('angle', value);
    this.transform.set(this.transform.x, this.transform.y, value);
    this.syncCenter();
    this.host?.bodyMoved(this);
  }

  /** Centre of mass in world coordinates (m); a reused view, like {@link position}. */
  get centerOfMass(): Readonly<Vec2> {
    this.centerView.x = this.centerX;
    this.centerView.y = this.centerY;
    return this.centerView;
  }

  /** Velocity of the centre of mass (m/s); a reused view. Setting it wakes the body. */
  get linearVelocity(): Readonly<Vec2> {
    this.velocityView.x = this.velocityX;
    this.velocityView.y = this.velocityY;
    return this.velocityView;
  }

  set linearVelocity(value: Vec2Like) {
    requireVector('linearVelocity', value, MAX_SPEED);
    if (this.type === 'static') return;
    this.velocityX = value.x;
    this.velocityY = value.y;
    this.wake();
  }

  /** Angular velocity (rad/s). Setting it wakes the body. */
  get angularVelocity(): number {
    return this.angularVelocityValue;
  }

  set angularVelocity(value: number) {
    requireAngularSpeed(value);
    if (this.type === 'static' || this.fixedRotationValue) return;
    this.angularVelocityValue = value;
    this.wake();
  }

  /** Kinetic energy, translational plus rotational (J). */
  get kineticEnergy(): number {
    const v2 = this.velocityX * this.velocityX + this.velocityY * this.velocityY;
    const w = this.angularVelocityValue;
    return 0.5 * this.massValue * v2 + 0.5 * this.inertiaValue * w * w;
  }

  /** Converts a body-local point to world coordinates (m). */
  getWorldPoint(local: Vec2Like, out: Vec2 = { x: 0, y: 0 }): Vec2 {
    requireVector('local', local);
    const { c, s, x, y } = this.transform;
    const lx = local.x;
    const ly = local.y;
    out.x = c * lx - s * ly + x;
    out.y = s * lx + c * ly + y;
    return out;
  }

  /** Converts a world point to body-local coordinates (m). */
  getLocalPoint(world: Vec2Like, out: Vec2 = { x: 0, y: 0 }): Vec2 {
    requireVector('world', world);
    const { c, s, x, y } = this.transform;
    const dx = world.x - x;
    const dy = world.y - y;
    out.x = c * dx + s * dy;
    out.y = -s * dx + c * dy;
    return out;
  }

  /** Velocity of the body's material at a world point (m/s): v + w x r. */
  getVelocityAt(world: Vec2Like, out: Vec2 = { x: 0, y: 0 }): Vec2 {
    requireVector('world', world);
    const w = this.angularVelocityValue;
    out.x = this.velocityX - w * (world.y - this.centerY);
    out.y = this.velocityY + w * (world.x - this.centerX);
    return out;
  }

  // ---------------------------------------------------------------- mass

  /** Mass (kg); 0 for static and kinematic bodies. Setting it overrides the shapes' density. */
  get mass(): number {
    return this.massValue;
  }

  set mass(value: number) {
    this.requireDynamic('mass');
    requireMass(value);
    this.commitMass(this.computeMass(this.shapeList, value, this.inertiaOverride));
    this.massOverride = value;
    this.wake();
  }

  /** Moment of inertia about the centre of mass (kg m^2). Setting it overrides the computed value. */
  get inertia(): number {
    return this.inertiaValue;
  }

  set inertia(value: number) {
    this.requireDynamic('inertia');
    requireInertia(value);
    this.commitMass(this.computeMass(this.shapeList, this.massOverride, value));
    this.inertiaOverride = value;
    this.wake();
  }

  /** Forgets `mass` and `inertia` set by hand and computes them from the shapes again. */
  resetMass(): void {
    this.commitMass(this.computeMass(this.shapeList, 0, 0));
    this.massOverride = 0;
    this.inertiaOverride = 0;
    this.wake();
  }

  /** Centre of mass in body-local coordinates (m); a new object. */
  get localCenterOfMass(): Vec2 {
    return { x: this.localCenterX, y: this.localCenterY };
  }

  // ---------------------------------------------------------------- settings

  /** Multiplies the world's gravity for this body. */
  get gravityScale(): number {
    return this.gravityScaleValue;
  }

  set gravityScale(value: number) {
    this.gravityScaleValue = requireGravityScale(value);
    this.wake();
  }

  /** Linear damping (1/s). */
  get linearDamping(): number {
    return this.linearDampingValue;
  }

  set linearDamping(value: number) {
    this.linearDampingValue = requireDamping('linearDamping', value);
  }

  /** Angular damping (1/s). */
  get angularDamping(): number {
    return this.angularDampingValue;
  }

  set angularDamping(value: number) {
    this.angularDampingValue = requireDamping('angularDamping', value);
  }

  /** Quadratic drag coefficient (N s^2/m^2): F = -drag |v| v. */
  get drag(): number {
    return this.dragValue;
  }

  set drag(value: number) {
    this.dragValue = requireDamping('drag', value);
  }

  /** True when the body cannot rotate. */
  get fixedRotation(): boolean {
    return this.fixedRotationValue;
  }

  set fixedRotation(value: boolean) {
    requireBoolean('fixedRotation', value);
    const mass = this.computeMass(this.shapeList, this.massOverride, this.inertiaOverride, value);
    this.fixedRotationValue = value;
    this.commitMass(mass);
    if (value) this.angularVelocityValue = 0;
    this.wake();
  }

  /** A bullet sweeps against moving bodies too (see {@link BodyOptions.bullet}). */
  get bullet(): boolean {
    return this.bulletValue;
  }

  set bullet(value: boolean) {
    this.bulletValue = requireBoolean('bullet', value);
  }

  /** Whether the body may fall asleep when it rests. Turning it off wakes the body. */
  get allowSleep(): boolean {
    return this.allowSleepValue;
  }

  set allowSleep(value: boolean) {
    this.allowSleepValue = requireBoolean('allowSleep', value);
    if (!value) this.wake();
  }

  /** True unless the body sleeps (static bodies never count as awake). */
  get isAwake(): boolean {
    return this.awake;
  }

  /** Wakes the body and everything resting on it. Harmless on an awake or static body. */
  wake(): void {
    if (this.type === 'static') return;
    const host = this.host;
    if (host !== null) host.wakeBody(this);
    else {
      this.awake = true;
      this.sleepTime = 0;
    }
  }

  /** Puts the body to sleep now (it stops until something wakes it). */
  sleep(): void {
    if (this.type === 'static') return;
    const host = this.host;
    if (host !== null) host.sleepBody(this);
    else this.awake = false;
  }

  // ---------------------------------------------------------------- shapes

  /** The body's shapes; a concave polygon shows as its convex parts, one shape each. */
  get shapes(): readonly Shape[] {
    return this.shapeList;
  }

  /**
   * Adds a shape (compound bodies); the mass is computed again. A concave polygon adds one shape
   * per convex part: this returns the first, and {@link shapes} lists them all.
   */
  addShape(options: ShapeOptions): Shape {
    this.host?.requireUnlocked('addShape');
    const added = this.createShapes(options, 'shape');
    // Check, then change: the new mass is computed (and may be refused) before the shape joins.
    const mass = this.computeMass([...this.shapeList, ...added]);
    this.shapeList.push(...added);
    this.commitMass(mass);
    for (const shape of added) this.host?.shapeAdded(shape);
    this.wake();
    return added[0]!;
  }

  /** Removes one of the body's shapes; the mass is computed again. */
  removeShape(shape: Shape): void {
    this.host?.requireUnlocked('removeShape');
    const index = this.shapeList.indexOf(shape);
    if (index < 0) throw new PhysicalError('shape', 'is not a shape of this body.');
    const remaining = this.shapeList.filter((s) => s !== shape);
    const mass = this.computeMass(remaining);
    this.host?.shapeRemoved(shape);
    this.shapeList.splice(index, 1);
    this.commitMass(mass);
    this.wake();
  }

  /** The joints attached to this body (in its world). */
  get joints(): readonly Joint[] {
    return this.jointList;
  }

  // ---------------------------------------------------------------- forces

  /** Forces and torques currently acting (those with a duration not yet used up). */
  get forces(): readonly Force[] {
    return this.forceList;
  }

  /**
   * Applies a force (N, world coordinates) for a {@link Duration}: `'instant'` (one step, the
   * default), `'constant'` (until removed) or a number of seconds. Returns the {@link Force}, which
   * can be changed or removed later. Wakes the body.
   *
   * @example
   * const push = body.applyForce({ x: 10, y: 0 }, { duration: 'constant' });
   * // later
   * push.remove();
   */
  applyForce(force: Vec2Like, options: ForceOptions = {}): Force {
    this.requireDynamic('applyForce');
    requireVector('force', force, MAX_FORCE);
    optionalObject(
      'options',
      options,
      "an object { duration?, point? }, for example { duration: 'constant' }",
    );
    const duration = validateDuration(options.duration ?? 'instant');
    if (options.point !== undefined) requireVector('point', options.point);
    const result = new Force(force.x, force.y, 0, duration);
    if (options.point !== undefined) {
      // Attach the point to the body so it turns with it.
      const local = this.getLocalPoint(options.point);
      result.localPointX = local.x;
      result.localPointY = local.y;
      result.hasPoint = true;
    }
    this.attachForce(result);
    return result;
  }

  /** Applies a torque (N m) for a {@link Duration}, like {@link applyForce}. */
  applyTorque(torque: number, options: TorqueOptions = {}): Force {
    this.requireDynamic('applyTorque');
    requireRange('torque', torque, -MAX_FORCE, MAX_FORCE, 'N m');
    optionalObject(
      'options',
      options,
      "an object { duration? }, for example { duration: 'constant' }",
    );
    const result = new Force(0, 0, torque, validateDuration(options.duration ?? 'instant'));
    this.attachForce(result);
    return result;
  }

  /** Removes a force or torque. Removing one that already ended is harmless. */
  removeForce(force: Force): void {
    if (!(force instanceof Force)) {
      throw new PhysicalError('force', `must be a Force, got ${describeValue(force)}.`);
    }
    const index = this.forceList.indexOf(force);
    if (index < 0) return;
    this.forceList.splice(index, 1);
    force.onRemove = null;
    force.onChange = null;
  }

  /** Removes every force and torque. */
  clearForces(): void {
    for (const force of this.forceList) {
      force.onRemove = null;
      force.onChange = null;
    }
    this.forceList.length = 0;
  }

  /**
   * Changes the velocity at once by an impulse (N s, world), at a world point (default: the centre
   * of mass, no spin). Δv = J / m, Δω = (r x J) / I.
   */
  applyImpulse(impulse: Vec2Like, point?: Vec2Like): void {
    this.requireDynamic('applyImpulse');
    requireVector('impulse', impulse, MAX_FORCE);
    if (point !== undefined) requireVector('point', point);
    this.velocityX += this.invMass * impulse.x;
    this.velocityY += this.invMass * impulse.y;
    if (point !== undefined) {
      const rx = point.x - this.centerX;
      const ry = point.y - this.centerY;
      this.angularVelocityValue += this.invInertia * (rx * impulse.y - ry * impulse.x);
    }
    this.wake();
  }

  /** Changes the angular velocity at once by an angular impulse (N m s): Δω = L / I. */
  applyAngularImpulse(impulse: number): void {
    this.requireDynamic('applyAngularImpulse');
    requireRange('impulse', impulse, -MAX_FORCE, MAX_FORCE, 'N m s');
    this.angularVelocityValue += this.invInertia * impulse;
    this.wake();
  }

  // ---------------------------------------------------------------- events

  /**
   * Listens to an event of this body: `'move'` (the thesis's onMove), `'collision'` (onCollision),
   * `'contactBegin'`, `'contactEnd'`. Returns a function that removes the listener.
   */
  on<K extends keyof BodyEvents>(type: K, listener: BodyEvents[K]): () => void {
    return this.listeners.on(type, listener);
  }

  /** Removes a listener added with {@link on}. */
  off<K extends keyof BodyEvents>(type: K, listener: BodyEvents[K]): void {
    this.listeners.off(type, listener);
  }

  // ---------------------------------------------------------------- internals

  /** @internal The world, seen through the narrow interface bodies and shapes report to. */
  get host(): BodyHost | null {
    return this.worldRef;
  }

  /**
   * @internal Moves the body's numbers to index `index` of `store` (copying them there) and
   * reads them there from now on: the one copy made when a body joins a world, and when a
   * world's bodies shift down after a removal.
   */
  moveTo(store: BodyStore, index: number): void {
    const base = index * BODY_STRIDE;
    if (store === this.store) {
      if (base !== this.base) store.data.copyWithin(base, this.base, this.base + BODY_STRIDE);
    } else {
      const from = this.store.data;
      const to = store.data;
      for (let i = 0; i < BODY_STRIDE; i++) to[base + i] = from[this.base + i]!;
    }
    this.store = store;
    this.base = base;
    this.transform.store = store;
    this.transform.base = base;
  }

  /** @internal The body leaves its world's memory: its numbers move to a store of its own. */
  detachMemory(): void {
    this.moveTo(createLocalBodyStore(), 0);
  }

  /** @internal Recomputes the centre of mass in world coordinates from the transform. */
  syncCenter(): void {
    const { c, s, x, y } = this.transform;
    this.centerX = c * this.localCenterX - s * this.localCenterY + x;
    this.centerY = s * this.localCenterX + c * this.localCenterY + y;
  }

  /** @internal Mass, centre of mass and inertia from the shapes and overrides, installed. */
  updateMassData(): void {
    this.commitMass(this.computeMass(this.shapeList));
  }

  /**
   * Mass, centre of mass and inertia of a list of shapes (parallel-axis theorem to combine them
   * about the common centre), then the overrides; throws, changing nothing, when a dynamic body
   * would get no valid mass. Callers compute first and commit only a valid result.
   */
  private computeMass(
    shapes: readonly Shape[],
    massOverride: number = this.massOverride,
    inertiaOverride: number = this.inertiaOverride,
    fixedRotation: boolean = this.fixedRotationValue,
  ): MassResult {
    const result: MassResult = { mass: 0, inertia: 0, centerX: 0, centerY: 0 };
    if (this.type !== 'dynamic') return result;
    let mass = 0;
    let cx = 0;
    let cy = 0;
    let inertiaAtOrigin = 0;
    for (let i = 0; i < shapes.length; i++) {
      const shape = shapes[i]!;
      const g = shape.geometry;
      if (g.kind === 'segment') {
        throw new PhysicalError(
          `shapes[${i}]`,
          'a segment has no area and so no mass: put walls on a static or kinematic body.',
        );
      }
      if (shape.density <= 0 && massOverride === 0) {
        throw new PhysicalError(
          `shapes[${i}].density`,
          `must be greater than zero on a dynamic body, got ${shape.density} (or set the body's mass).`,
        );
      }
      const data =
        g.kind === 'circle'
          ? computeCircleMass(g, shape.density, scratchMass)
          : g.kind === 'capsule'
            ? computeCapsuleMass(g, shape.density, scratchMass)
            : computePolygonMass(g, shape.density, scratchMass);
      mass += data.mass;
      cx += data.mass * data.centerX;
      cy += data.mass * data.centerY;
      inertiaAtOrigin +=
        data.rotationalInertia +
        data.mass * (data.centerX * data.centerX + data.centerY * data.centerY);
    }
    if (mass > 0) {
      cx /= mass;
      cy /= mass;
    }
    let inertia = inertiaAtOrigin - mass * (cx * cx + cy * cy);
    if (massOverride > 0) {
      // Same shape, different density: inertia scales with mass. A point mass has none.
      inertia = mass > 0 ? (inertia * massOverride) / mass : 0;
      mass = massOverride;
    }
    if (!(mass > 0)) {
      throw new PhysicalError(
        'mass',
        'a dynamic body needs a positive mass: give it a shape with density > 0, or set `mass`.',
      );
    }
    if (mass < MIN_MASS || mass > MAX_MASS || !Number.isFinite(cx) || !Number.isFinite(cy)) {
      throw new PhysicalError(
        'mass',
        `must be from ${MIN_MASS} to ${MAX_MASS} kg; the shapes and density give ${mass}. ` +
          'Change the density or the sizes, or set `mass`.',
      );
    }
    if (inertiaOverride > 0) inertia = inertiaOverride;
    result.mass = mass;
    result.centerX = cx;
    result.centerY = cy;
    // Below the smallest inertia the rotation would be numerically free: treat it as none.
    if (!fixedRotation && inertia >= MIN_INERTIA && Number.isFinite(inertia)) {
      result.inertia = inertia;
    }
    return result;
  }

  /** Installs a mass computed by {@link computeMass} for the current shapes and settings. */
  private commitMass(data: MassResult): void {
    this.massValue = data.mass;
    this.invMass = data.mass > 0 ? 1 / data.mass : 0;
    this.inertiaValue = data.inertia;
    this.invInertia = data.inertia > 0 ? 1 / data.inertia : 0;
    this.localCenterX = data.centerX;
    this.localCenterY = data.centerY;
    this.syncCenter();
    this.computeExtents();
  }

  /** Largest and smallest reach of the shapes from the centre of mass, for sleep and continuous collision. */
  private computeExtents(): void {
    let maxExtent = 0;
    let minExtent = Infinity;
    const cx = this.localCenterX;
    const cy = this.localCenterY;
    for (const shape of this.shapeList) {
      const g = shape.geometry;
      if (g.kind === 'circle') {
        const d = hypot(g.centerX - cx, g.centerY - cy);
        maxExtent = Math.max(maxExtent, d + g.radius);
        minExtent = Math.min(minExtent, g.radius);
      } else if (g.kind === 'polygon') {
        let inner = Infinity;
        for (let i = 0; i < g.count; i++) {
          const vx = g.vertices[2 * i]!;
          const vy = g.vertices[2 * i + 1]!;
          maxExtent = Math.max(maxExtent, hypot(vx - cx, vy - cy) + g.radius);
          // Distance from the centroid to each edge: the polygon's inradius bound.
          const d =
            (vx - g.centroidX) * g.normals[2 * i]! + (vy - g.centroidY) * g.normals[2 * i + 1]!;
          inner = Math.min(inner, d);
        }
        minExtent = Math.min(minExtent, inner + g.radius);
      } else if (g.kind === 'capsule') {
        maxExtent = Math.max(
          maxExtent,
          hypot(g.x1 - cx, g.y1 - cy) + g.radius,
          hypot(g.x2 - cx, g.y2 - cy) + g.radius,
        );
        minExtent = Math.min(minExtent, g.radius);
      } else {
        maxExtent = Math.max(maxExtent, hypot(g.x1 - cx, g.y1 - cy), hypot(g.x2 - cx, g.y2 - cy));
        minExtent = 0;
      }
    }
    this.maxExtent = maxExtent;
    this.minExtent = minExtent === Infinity ? 0 : minExtent;
    this.originReach = maxExtent + hypot(cx, cy);
  }

  /** One shape per geometry the options make (several for a concave polygon). */
  private createShapes(options: ShapeOptions, field: string): Shape[] {
    const geometries = createGeometries(options, field);
    return geometries.map((geometry) => new Shape(this as Body, options, field, geometry));
  }

  private attachForce(force: Force): void {
    force.onRemove = (f) => this.removeForce(f);
    force.onChange = () => this.wake();
    this.forceList.push(force);
    this.wake();
  }

  private requireDynamic(what: string): void {
    if (this.type !== 'dynamic') {
      throw new PhysicalError(
        what,
        `acts only on dynamic bodies; this body is ${this.type}. A static body never moves; move a kinematic body by setting its velocity.`,
      );
    }
  }
}
