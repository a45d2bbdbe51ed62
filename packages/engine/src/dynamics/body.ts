import { PhysicalError, readOnly } from '../core/errors.ts';
import { Listeners, type ListenerCount } from '../core/listeners.ts';
import {
  MAX_SPEED,
  optionalBoolean,
  optionalObject,
  requireAngle,
  requireBoolean,
  requireObject,
  requireOneOf,
  requireVector,
} from '../core/validate.ts';
import type { Vec2, Vec2Like } from '../math/vec2.ts';
import type { World } from '../world/world.ts';
import {
  applyBodyAngularImpulse,
  applyBodyForce,
  applyBodyImpulse,
  applyBodyTorque,
  clearBodyForces,
  removeBodyForce,
} from './body-forces.ts';
import type { BodyHost } from './body-host.ts';
import { commitBodyMass, computeBodyMass } from './body-mass.ts';
import { BodyNumbers } from './body-numbers.ts';
import {
  BODY_TYPES,
  requireAngularSpeed,
  requireDamping,
  requireDynamic,
  requireGravityScale,
  requireInertia,
  requireMass,
  type BodyOptions,
  type BodyType,
} from './body-options.ts';
import { BODY_EVENT_NAMES, type BodyEvents } from './events.ts';
import type { Force, ForceOptions, TorqueOptions } from './force.ts';
import type { Joint } from './joints/joint.ts';
import { createGeometries, Shape, type ShapeOptions } from './shape.ts';

export type { BodyOptions, BodyType } from './body-options.ts';

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
export class Body<UserData = unknown> extends BodyNumbers {
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
    super();
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
    requireObject('out', out, 'an object');
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
    requireObject('out', out, 'an object');
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
    requireObject('out', out, 'an object');
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
    requireDynamic(this.type, 'mass');
    requireMass(value);
    commitBodyMass(
      this as Body,
      computeBodyMass(this as Body, this.shapeList, value, this.inertiaOverride),
    );
    this.massOverride = value;
    this.wake();
  }

  /** Moment of inertia about the centre of mass (kg m^2). Setting it overrides the computed value. */
  get inertia(): number {
    return this.inertiaValue;
  }

  set inertia(value: number) {
    requireDynamic(this.type, 'inertia');
    requireInertia(value);
    commitBodyMass(
      this as Body,
      computeBodyMass(this as Body, this.shapeList, this.massOverride, value),
    );
    this.inertiaOverride = value;
    this.wake();
  }

  /** Forgets `mass` and `inertia` set by hand and computes them from the shapes again. */
  resetMass(): void {
    commitBodyMass(this as Body, computeBodyMass(this as Body, this.shapeList, 0, 0));
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
    const mass = computeBodyMass(
      this as Body,
      this.shapeList,
      this.massOverride,
      this.inertiaOverride,
      value,
    );
    this.fixedRotationValue = value;
    commitBodyMass(this as Body, mass);
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
    const mass = computeBodyMass(this as Body, [...this.shapeList, ...added]);
    this.shapeList.push(...added);
    commitBodyMass(this as Body, mass);
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
    const mass = computeBodyMass(this as Body, remaining);
    this.host?.shapeRemoved(shape);
    this.shapeList.splice(index, 1);
    commitBodyMass(this as Body, mass);
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
    return applyBodyForce(this as Body, force, options);
  }

  /** Applies a torque (N m) for a {@link Duration}, like {@link applyForce}. */
  applyTorque(torque: number, options: TorqueOptions = {}): Force {
    return applyBodyTorque(this as Body, torque, options);
  }

  /** Removes a force or torque. Removing one that already ended is harmless. */
  removeForce(force: Force): void {
    removeBodyForce(this as Body, force);
  }

  /** Removes every force and torque. */
  clearForces(): void {
    clearBodyForces(this as Body);
  }

  /**
   * Changes the velocity at once by an impulse (N s, world), at a world point (default: the centre
   * of mass, no spin). Δv = J / m, Δω = (r x J) / I.
   */
  applyImpulse(impulse: Vec2Like, point?: Vec2Like): void {
    applyBodyImpulse(this as Body, impulse, point);
  }

  /** Changes the angular velocity at once by an angular impulse (N m s): Δω = L / I. */
  applyAngularImpulse(impulse: number): void {
    applyBodyAngularImpulse(this as Body, impulse);
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

  /** @internal Mass, centre of mass and inertia from the shapes and overrides, installed. */
  updateMassData(): void {
    commitBodyMass(this as Body, computeBodyMass(this as Body, this.shapeList));
  }

  /** One shape per geometry the options make (several for a concave polygon). */
  private createShapes(options: ShapeOptions, field: string): Shape[] {
    const geometries = createGeometries(options, field);
    return geometries.map((geometry) => new Shape(this as Body, options, field, geometry));
  }
}
