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

// A body's numbers as a handle's accessors: each reads or writes the body's stride in the body
// memory (body-memory.ts), the world's while the body is in one, so `Body` (which extends this)
// holds no number of its own. Every member is internal (stripped from the published types).

/**
 * The numbers behind a {@link Body}: its pose, velocities, mass properties, settings, flags and
 * sleep clock, read and written where the world's passes read them. Every member is internal.
 */
export class BodyNumbers {
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
}
