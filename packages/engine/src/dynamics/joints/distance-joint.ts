import { PhysicalError, readOnly } from '../../core/errors.ts';
import { optionalBoolean, requireNonNegative, requireRange } from '../../core/validate.ts';
import type { Vec2Like } from '../../math/vec2.ts';
import { hypot } from '../../math/hypot.ts';
import { Softness } from '../softness.ts';
import { JointBatch } from './joint-batch.ts';
import { KIND_DISTANCE } from './joint-pass-codes.ts';
import {
  DAMPING_RATIO,
  EXPLICIT_SPRING,
  HERTZ,
  IMPULSE,
  LENGTH_ROW_ON,
  LOWER_IMPULSE,
  LOWER_ON,
  MAX_LENGTH,
  MIN_LENGTH,
  REST,
  SPRING_BIAS_RATE,
  SPRING_ENABLED,
  SPRING_OMEGA,
  SPRING_SUB_STEP_IMPULSE,
  STRIDE,
  UPPER_IMPULSE,
  UPPER_ON,
} from './distance-joint-layout.ts';
import {
  checkCollideConnected,
  jointLayout,
  stateLayout,
  type JointLayout,
  type JointOptions,
  type JointStateLayout,
  type JointStep,
  optionalNonNegative,
  requireBodies,
  requireOrdered,
  jointMax,
  requirePoint,
} from './joint.ts';
import { TwoBodyJoint } from './two-body-joint.ts';
import { LOCAL_ANCHOR_AX, LOCAL_ANCHOR_BX } from './joint-record.ts';

/**
 * Options of a {@link DistanceJoint}: a rod between two points (rigid), or a spring of given
 * frequency and damping; with minLength and maxLength the length stays within a range (a rope is
 * a spring of 0 Hz with a maxLength).
 */
export interface DistanceJointOptions<UserData = unknown> extends JointOptions<UserData> {
  /** Point on body A (world, m). */
  readonly anchorA: Vec2Like;
  /** Point on body B (world, m). */
  readonly anchorB: Vec2Like;
  /** Rest length (m, >= 0). Default: the anchors' distance now. */
  readonly length?: number;
  /** Shortest length (m, >= 0). Default none (0). */
  readonly minLength?: number;
  /** Longest length (m). Default none. */
  readonly maxLength?: number;
  /** A spring instead of a rigid rod. Default false. */
  readonly enableSpring?: boolean;
  /** Spring frequency (Hz, >= 0); 0 means no spring force (only the length range holds). Default 0. */
  readonly hertz?: number;
  /** Spring damping ratio (>= 0; 1 is critical). Default 0. */
  readonly dampingRatio?: number;
}

/**
 * @internal A distance joint's options checked (a PhysicalError naming the first bad one), in the
 * order its constructor reads them, with defaults: the one check, also run where no joint is built
 * (a worker world's page).
 */
export function checkDistanceJointOptions(options: DistanceJointOptions<unknown>) {
  requireBodies(options);
  const anchorA = requirePoint('anchorA', options.anchorA);
  const anchorB = requirePoint('anchorB', options.anchorB);
  checkCollideConnected(options);
  const distance = hypot(anchorB.x - anchorA.x, anchorB.y - anchorA.y);
  const length = optionalNonNegative('length', options.length, distance);
  const minLength = optionalNonNegative('minLength', options.minLength, 0);
  const maxLength =
    options.maxLength === undefined
      ? Infinity
      : requireNonNegative('maxLength', options.maxLength, jointMax('maxLength'));
  requireOrdered('minLength', minLength, 'maxLength', maxLength);
  requireInRange(length, minLength, maxLength);
  return {
    anchorA,
    anchorB,
    length,
    minLength,
    maxLength,
    enableSpring: optionalBoolean('enableSpring', options.enableSpring, false),
    hertz: optionalNonNegative('hertz', options.hertz, 0),
    dampingRatio: optionalNonNegative('dampingRatio', options.dampingRatio, 0),
  };
}

// A distance joint's record: the head (joint-record.ts), then its own numbers. The joint has no
// angular row: its step angular impulse stays 0, as prepareBodies cleared it.
const LAYOUT: JointLayout = /* @__PURE__ */ jointLayout(
  STRIDE,
  [
    {
      localAnchorA: ['vector', LOCAL_ANCHOR_AX],
      localAnchorB: ['vector', LOCAL_ANCHOR_BX],
      length: ['nonNegative', REST],
      minLength: ['nonNegative', MIN_LENGTH],
      maxLength: ['nonNegativeOrInfinity', MAX_LENGTH],
      enableSpring: ['boolean', SPRING_ENABLED],
      hertz: ['nonNegative', HERTZ],
      dampingRatio: ['nonNegative', DAMPING_RATIO],
      impulse: ['finite', IMPULSE],
      lowerImpulse: ['nonNegative', LOWER_IMPULSE],
      upperImpulse: ['nonNegative', UPPER_IMPULSE],
    },
  ],
  [[IMPULSE, LOWER_IMPULSE, UPPER_IMPULSE]],
);

/** @internal What a world snapshot saves of a distance joint (see exportJointState). */
export const DISTANCE_STATE: JointStateLayout = /* @__PURE__ */ stateLayout(LAYOUT, [
  ['minLength', 'length'],
  ['length', 'maxLength'],
]);

const scratch = /* @__PURE__ */ new Softness();

/**
 * Keeps two points at a distance, rigidly or as a damped spring, within an optional length range.
 * Box2D v3's distance joint (Catto): one row along the line between the anchors, recomputed each
 * pass from the current anchors; the rigid row softened by the joint softness, the spring by its
 * own, the range limits one-sided and speculative like contacts.
 */
export class DistanceJoint<UserData = unknown> extends TwoBodyJoint<UserData> {
  get type(): 'distance' {
    return 'distance';
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set type(_value: never) {
    readOnly('type', 'a joint keeps its kind');
  }

  constructor(options: DistanceJointOptions<UserData>) {
    const checked = checkDistanceJointOptions(options);
    super(options, options.bodyA, options.bodyB, STRIDE);
    this.setAnchors(checked.anchorA, checked.anchorB);
    this.write(REST, checked.length);
    this.write(MIN_LENGTH, checked.minLength);
    this.write(MAX_LENGTH, checked.maxLength);
    this.write(SPRING_ENABLED, checked.enableSpring ? 1 : 0);
    this.write(HERTZ, checked.hertz);
    this.write(DAMPING_RATIO, checked.dampingRatio);
  }

  /** @internal */
  protected get layout(): JointLayout {
    return LAYOUT;
  }

  /** Distance between the anchors now (m). */
  get currentLength(): number {
    const a = this.anchorA;
    const ax = a.x;
    const ay = a.y;
    const b = this.anchorB;
    return hypot(b.x - ax, b.y - ay);
  }

  /** Rest length (m), within [minLength, maxLength]. Setting it wakes the bodies. */
  get length(): number {
    return this.value(REST);
  }

  set length(value: number) {
    requireNonNegative('length', value, jointMax('length'));
    requireInRange(value, this.value(MIN_LENGTH), this.value(MAX_LENGTH));
    this.write(REST, value);
    this.wakeBodies();
  }

  /** Shortest length (m). */
  get minLength(): number {
    return this.value(MIN_LENGTH);
  }

  /** Longest length (m); Infinity when there is none. */
  get maxLength(): number {
    return this.value(MAX_LENGTH);
  }

  /** Sets the length range (m; maxLength may be Infinity for none); wakes the bodies. */
  setLengthRange(minLength: number, maxLength: number): void {
    requireNonNegative('minLength', minLength, jointMax('minLength'));
    if (maxLength !== Infinity) requireNonNegative('maxLength', maxLength, jointMax('maxLength'));
    requireOrdered('minLength', minLength, 'maxLength', maxLength);
    requireInRange(this.value(REST), minLength, maxLength);
    this.write(MIN_LENGTH, minLength);
    this.write(MAX_LENGTH, maxLength);
    this.wakeBodies();
  }

  /** Whether the joint is a spring (else a rigid rod). Changing it wakes the bodies. */
  get enableSpring(): boolean {
    return this.flag(SPRING_ENABLED);
  }

  set enableSpring(value: boolean) {
    this.setSwitch('enableSpring', SPRING_ENABLED, value, IMPULSE, 1);
  }

  /** Spring frequency (Hz). Setting it wakes the bodies. */
  get hertz(): number {
    return this.value(HERTZ);
  }

  set hertz(value: number) {
    this.setNumber('hertz', HERTZ, value, 'nonNegative');
  }

  /** Spring damping ratio. Setting it wakes the bodies. */
  get dampingRatio(): number {
    return this.value(DAMPING_RATIO);
  }

  set dampingRatio(value: number) {
    this.setNumber('dampingRatio', DAMPING_RATIO, value, 'nonNegative');
  }

  /** @internal */
  prepare(step: JointStep): void {
    this.prepareFrame(step);
    const d = this.store.data;
    const o = this.base;
    const springEnabled = d[o + SPRING_ENABLED] === 1;
    const hertz = d[o + HERTZ]!;
    scratch.set(hertz, d[o + DAMPING_RATIO]!, step.h);
    scratch.store(d, o + SPRING_BIAS_RATE);
    if (springEnabled && hertz === 0) d[o + IMPULSE] = 0;
    const omega = 2 * Math.PI * hertz;
    d[o + SPRING_OMEGA] = omega;
    // A spring slow enough for the sub-step (omega h <= 1) acts as a force, integrated by
    // semi-implicit Euler like gravity: symplectic, so an undamped spring keeps its energy. A soft
    // constraint (Box2D's spring) is implicit Euler and loses about 15 % of the amplitude per
    // period at 1 Hz. Stiffer springs stay soft constraints, which are stable at any stiffness.
    const explicit = springEnabled && hertz > 0 && omega * step.h <= 1;
    d[o + EXPLICIT_SPRING] = explicit ? 1 : 0;
    // An explicit spring is a force of this sub-step, not a constraint impulse to warm start.
    if (explicit) d[o + IMPULSE] = 0;
    d[o + SPRING_SUB_STEP_IMPULSE] = 0;
    const min = d[o + MIN_LENGTH]!;
    const max = d[o + MAX_LENGTH]!;
    if (min === 0) d[o + LOWER_IMPULSE] = 0;
    if (max === Infinity) d[o + UPPER_IMPULSE] = 0;
    d[o + LENGTH_ROW_ON] = !springEnabled || hertz > 0 ? 1 : 0;
    d[o + LOWER_ON] = springEnabled && min > 0 ? 1 : 0;
    d[o + UPPER_ON] = springEnabled && max !== Infinity ? 1 : 0;
  }

  /** @internal */
  override createBatch(): JointBatch {
    return new JointBatch(KIND_DISTANCE);
  }
}

function requireInRange(length: number, min: number, max: number): void {
  requireRange('length', length, -jointMax('length'), jointMax('length'));
  if (length < min || length > max) {
    throw new PhysicalError(
      'length',
      `must lie between minLength (${min}) and maxLength (${max}), got ${length}.`,
    );
  }
}
