import { PhysicalError, readOnly } from '../../core/errors.ts';
import { optionalBoolean, requireNonNegative, requireRange } from '../../core/validate.ts';
import type { Vec2Like } from '../../math/vec2.ts';
import { hypot } from '../../math/hypot.ts';
import { V_X, V_Y, W } from '../body-state.ts';
import { Softness } from '../softness.ts';
import { JointBatch } from './joint-batch.ts';
import type { SolverMemory } from '../solver-memory.ts';
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
import { shiftX, shiftY, turnedX, turnedY } from './joint-levers.ts';
import {
  INV_I_A,
  INV_I_B,
  INV_MASS_A,
  INV_MASS_B,
  LOCAL_ANCHOR_AX,
  LOCAL_ANCHOR_BX,
  R_AX,
  R_BX,
  STEP_IMPULSE_X,
  STEP_IMPULSE_Y,
} from './joint-record.ts';

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
const REST = 25; // JOINT_HEAD; settings: rest length, shortest and longest length (m)
const MIN_LENGTH = 26; // JOINT_HEAD + 1
const MAX_LENGTH = 27; // JOINT_HEAD + 2
const SPRING_ENABLED = 28; // JOINT_HEAD + 3; 1 or 0: a spring, else a rigid rod
const HERTZ = 29; // JOINT_HEAD + 4
const DAMPING_RATIO = 30; // JOINT_HEAD + 5
const EXPLICIT_SPRING = 31; // JOINT_HEAD + 6; this step, 1 or 0: the spring acts as a force (see prepare)
const SPRING_OMEGA = 32; // JOINT_HEAD + 7
const LENGTH_ROW_ON = 33; // JOINT_HEAD + 8; 1 or 0: the rod, or the spring as a soft constraint
const SPRING_BIAS_RATE = 34; // JOINT_HEAD + 9
const SPRING_MASS_SCALE = 35; // JOINT_HEAD + 10
const SPRING_IMPULSE_SCALE = 36; // JOINT_HEAD + 11
const LOWER_ON = 37; // JOINT_HEAD + 12; 1 or 0: the minLength row
const UPPER_ON = 38; // JOINT_HEAD + 13; 1 or 0: the maxLength row
const IMPULSE = 39; // JOINT_HEAD + 14; accumulated impulses (warm-started)
const LOWER_IMPULSE = 40; // JOINT_HEAD + 15
const UPPER_IMPULSE = 41; // JOINT_HEAD + 16
const SPRING_SUB_STEP_IMPULSE = 42; // JOINT_HEAD + 17; the explicit spring's impulse in the sub-step
const STRIDE = 43; // JOINT_HEAD + 18

/** Below this anchor distance (m) the joint has no direction and does nothing. */
const LENGTH_EPSILON = 1e-9;

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
  override createBatch(): DistanceBatch {
    return new DistanceBatch();
  }
}

/**
 * @internal The distance joints of a world: their records, and the step's active ones solved in
 * one loop per pass (see JointBatch).
 */
export class DistanceBatch extends JointBatch {
  warmStart(s: Float64Array, memory: SolverMemory): void {
    const d = memory.jointStore.data;
    const list = memory.jointActive;
    const end = this.start + this.active;
    for (let i = this.start; i < end; i++) {
      const o = list[3 * i]!;
      const a = list[3 * i + 1]!;
      const b = list[3 * i + 2]!;
      const rAx = turnedX(s, a, d, o + R_AX);
      const rAy = turnedY(s, a, d, o + R_AX);
      const rBx = turnedX(s, b, d, o + R_BX);
      const rBy = turnedY(s, b, d, o + R_BX);
      const dx = shiftX(s, a, b, d, o) + rBx - rAx;
      const dy = shiftY(s, a, b, d, o) + rBy - rAy;
      const length = Math.sqrt(dx * dx + dy * dy);
      if (!(length > LENGTH_EPSILON)) continue;
      const axial = d[o + IMPULSE]! + d[o + LOWER_IMPULSE]! - d[o + UPPER_IMPULSE]!;
      const px = (axial * dx) / length;
      const py = (axial * dy) / length;
      s[a + V_X] -= d[o + INV_MASS_A]! * px;
      s[a + V_Y] -= d[o + INV_MASS_A]! * py;
      s[a + W] -= d[o + INV_I_A]! * (rAx * py - rAy * px);
      s[b + V_X] += d[o + INV_MASS_B]! * px;
      s[b + V_Y] += d[o + INV_MASS_B]! * py;
      s[b + W] += d[o + INV_I_B]! * (rBx * py - rBy * px);
    }
  }

  solve(s: Float64Array, memory: SolverMemory, step: JointStep, useBias: boolean): void {
    const d = memory.jointStore.data;
    const list = memory.jointActive;
    const end = this.start + this.active;
    const soft = step.softness;
    for (let i = this.start; i < end; i++) {
      const o = list[3 * i]!;
      const a = list[3 * i + 1]!;
      const b = list[3 * i + 2]!;
      const mA = d[o + INV_MASS_A]!;
      const iA = d[o + INV_I_A]!;
      const mB = d[o + INV_MASS_B]!;
      const iB = d[o + INV_I_B]!;
      let vAx = s[a + V_X]!;
      let vAy = s[a + V_Y]!;
      let wA = s[a + W]!;
      let vBx = s[b + V_X]!;
      let vBy = s[b + V_Y]!;
      let wB = s[b + W]!;
      const rAx = turnedX(s, a, d, o + R_AX);
      const rAy = turnedY(s, a, d, o + R_AX);
      const rBx = turnedX(s, b, d, o + R_BX);
      const rBy = turnedY(s, b, d, o + R_BX);
      const dx = shiftX(s, a, b, d, o) + rBx - rAx;
      const dy = shiftY(s, a, b, d, o) + rBy - rAy;
      const length = Math.sqrt(dx * dx + dy * dy);
      // Coincident anchors have no direction to push along.
      if (length > LENGTH_EPSILON) {
        const nx = dx / length;
        const ny = dy / length;
        const crA = rAx * ny - rAy * nx;
        const crB = rBx * ny - rBy * nx;
        const k = mA + mB + iA * crA * crA + iB * crB * crB;
        const axialMass = k > 0 ? 1 / k : 0;

        // The rows along n, one after another, each on the velocities the one before left: the
        // explicit spring's force (row 0), the rod or the soft spring (1), length >= minLength (2,
        // pushes apart only) and length <= maxLength (3, pulls together only: a rope). Each gives
        // the impulse `push` on B along n (on A the opposite), applied in one place.
        const explicit = d[o + EXPLICIT_SPRING] === 1;
        for (let row = 0; row < 4; row++) {
          if (
            row === 0
              ? !explicit || !useBias
              : row === 1
                ? explicit || d[o + LENGTH_ROW_ON] !== 1
                : d[o + (row === 2 ? LOWER_ON : UPPER_ON)] !== 1
          ) {
            continue;
          }
          const cdot =
            (vBx - wB * rBy - vAx + wA * rAy) * nx + (vBy + wB * rBx - vAy - wA * rAx) * ny;
          let push: number;
          if (row === 0) {
            // Spring force -k C - c Cdot over the sub-step (C = length - rest), with k and c for
            // the effective mass; the damping part implicit, so no damping ratio can reverse the
            // motion.
            const omega = d[o + SPRING_OMEGA]!;
            const damping = 2 * d[o + DAMPING_RATIO]! * omega;
            push =
              (-axialMass * step.h * (omega * omega * (length - d[o + REST]!) + damping * cdot)) /
              (1 + damping * step.h);
            d[o + SPRING_SUB_STEP_IMPULSE] = push;
          } else if (row === 1) {
            // C = length - rest.
            let bias = 0;
            let massScale = 1;
            let impulseScale = 0;
            if (d[o + SPRING_ENABLED] === 1) {
              bias = d[o + SPRING_BIAS_RATE]! * (length - d[o + REST]!);
              massScale = d[o + SPRING_MASS_SCALE]!;
              impulseScale = d[o + SPRING_IMPULSE_SCALE]!;
            } else if (useBias) {
              bias = soft.biasRate * (length - d[o + REST]!);
              massScale = soft.massScale;
              impulseScale = soft.impulseScale;
            }
            push = -massScale * axialMass * (cdot + bias) - impulseScale * d[o + IMPULSE]!;
            d[o + IMPULSE] += push;
          } else {
            // Lower: C = length - minLength >= 0; upper: C = maxLength - length >= 0, the same
            // row with the sign turned. Speculative like contacts: a gap may close within the
            // sub-step.
            const lower = row === 2;
            const c = lower ? length - d[o + MIN_LENGTH]! : d[o + MAX_LENGTH]! - length;
            let bias = 0;
            let massScale = 1;
            let impulseScale = 0;
            if (c > 0) bias = c * step.inverseH;
            else if (useBias) {
              bias = soft.biasRate * c;
              massScale = soft.massScale;
              impulseScale = soft.impulseScale;
            }
            const at = lower ? LOWER_IMPULSE : UPPER_IMPULSE;
            const old = d[o + at]!;
            const impulse =
              -massScale * axialMass * ((lower ? cdot : -cdot) + bias) - impulseScale * old;
            const accumulated = Math.max(old + impulse, 0);
            d[o + at] = accumulated;
            push = lower ? accumulated - old : -(accumulated - old);
          }
          const px = push * nx;
          const py = push * ny;
          vAx -= mA * px;
          vAy -= mA * py;
          wA -= iA * (rAx * py - rAy * px);
          vBx += mB * px;
          vBy += mB * py;
          wB += iB * (rBx * py - rBy * px);
        }

        if (!useBias) {
          const axial =
            d[o + IMPULSE]! +
            d[o + SPRING_SUB_STEP_IMPULSE]! +
            d[o + LOWER_IMPULSE]! -
            d[o + UPPER_IMPULSE]!;
          d[o + STEP_IMPULSE_X] += axial * nx;
          d[o + STEP_IMPULSE_Y] += axial * ny;
        }
      }

      s[a + V_X] = vAx;
      s[a + V_Y] = vAy;
      s[a + W] = wA;
      s[b + V_X] = vBx;
      s[b + V_Y] = vBy;
      s[b + W] = wB;
    }
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
