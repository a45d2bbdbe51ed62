import { readOnly } from '../../core/errors.ts';
import type { Vec2Like } from '../../math/vec2.ts';
import { DELTA_ANGLE, V_X, V_Y, W } from '../body-state.ts';
import { Softness } from '../softness.ts';
import { JointBatch } from './joint-batch.ts';
import type { SolverMemory } from '../solver-memory.ts';
import {
  FRAME_SAVED,
  checkCollideConnected,
  jointLayout,
  stateLayout,
  type JointLayout,
  type JointOptions,
  type JointStateLayout,
  type JointStep,
  optionalNonNegative,
  requireBodies,
  requirePoint,
} from './joint.ts';
import { TwoBodyJoint } from './two-body-joint.ts';
import { turnedX, turnedY } from './joint-levers.ts';
import {
  INV_I_A,
  INV_I_B,
  INV_MASS_A,
  INV_MASS_B,
  JOINT_ANGLE_0,
  REFERENCE_ANGLE,
  R_AX,
  R_BX,
  STEP_ANGULAR_IMPULSE,
  STEP_IMPULSE_X,
  STEP_IMPULSE_Y,
} from './joint-record.ts';
import { solveSoftPoint } from './soft-point.ts';

/** Options of a {@link WeldJoint}: glues two bodies together, rigidly or springily. */
export interface WeldJointOptions<UserData = unknown> extends JointOptions<UserData> {
  /** The point where the bodies are glued (world, m). */
  readonly anchor: Vec2Like;
  /** Stiffness of the position hold (Hz, >= 0); 0 is rigid. Default 0. */
  readonly linearHertz?: number;
  /** Stiffness of the angle hold (Hz, >= 0); 0 is rigid. Default 0. */
  readonly angularHertz?: number;
  /** Damping ratio of the soft holds (>= 0). Default 1. */
  readonly dampingRatio?: number;
}

/**
 * @internal A weld joint's options checked (a PhysicalError naming the first bad one), in the
 * order its constructor reads them, with defaults: the one check, also run where no joint is built
 * (a worker world's page).
 */
export function checkWeldJointOptions(options: WeldJointOptions<unknown>) {
  requireBodies(options);
  const anchor = requirePoint('anchor', options.anchor);
  checkCollideConnected(options);
  return {
    anchor,
    linearHertz: optionalNonNegative('linearHertz', options.linearHertz, 0),
    angularHertz: optionalNonNegative('angularHertz', options.angularHertz, 0),
    dampingRatio: optionalNonNegative('dampingRatio', options.dampingRatio, 1),
  };
}

// A weld joint's record: the head (joint-record.ts), then its own numbers.
const LINEAR_HERTZ = 25; // JOINT_HEAD; settings
const ANGULAR_HERTZ = 26; // JOINT_HEAD + 1
const DAMPING_RATIO = 27; // JOINT_HEAD + 2
const AXIAL_MASS = 28; // JOINT_HEAD + 3; this step: 1 / (1/IA + 1/IB)
// 1: the position hold has its own softness (bias rate, mass scale and impulse scale next), in
// both passes; 0: rigid. The order is what solveSoftPoint reads.
const LINEAR_SPRINGY = 29; // JOINT_HEAD + 4
const LINEAR_BIAS_RATE = 30; // JOINT_HEAD + 5; then its mass scale and impulse scale
const ANGULAR_SPRINGY = 33; // JOINT_HEAD + 8; the same for the angle hold
const ANGULAR_BIAS_RATE = 34; // JOINT_HEAD + 9
const ANGULAR_MASS_SCALE = 35; // JOINT_HEAD + 10
const ANGULAR_IMPULSE_SCALE = 36; // JOINT_HEAD + 11
const LINEAR_IMPULSE_X = 37; // JOINT_HEAD + 12; accumulated impulses (warm-started)
const LINEAR_IMPULSE_Y = 38; // JOINT_HEAD + 13
const ANGULAR_IMPULSE = 39; // JOINT_HEAD + 14
const STRIDE = 40; // JOINT_HEAD + 15

const LAYOUT: JointLayout = /* @__PURE__ */ jointLayout(
  STRIDE,
  [
    FRAME_SAVED,
    {
      linearHertz: ['nonNegative', LINEAR_HERTZ],
      angularHertz: ['nonNegative', ANGULAR_HERTZ],
      dampingRatio: ['nonNegative', DAMPING_RATIO],
      linearImpulse: ['vector', LINEAR_IMPULSE_X],
      angularImpulse: ['finite', ANGULAR_IMPULSE],
    },
  ],
  [[LINEAR_IMPULSE_X, LINEAR_IMPULSE_Y, ANGULAR_IMPULSE]],
);

/** @internal What a world snapshot saves of a weld joint (see exportJointState). */
export const WELD_STATE: JointStateLayout = /* @__PURE__ */ stateLayout(LAYOUT, []);

const scratch = /* @__PURE__ */ new Softness();

/**
 * Holds body B at a fixed position and angle relative to body A: rigid, or a spring in position
 * and/or angle (a soft weld makes a springy diving board). Box2D v3's weld joint (Catto): an
 * angular row, then a 2x2 point block; a rigid part corrects its error with the joint softness in
 * the biased pass only, a soft part with its own softness in both passes.
 */
export class WeldJoint<UserData = unknown> extends TwoBodyJoint<UserData> {
  get type(): 'weld' {
    return 'weld';
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set type(_value: never) {
    readOnly('type', 'a joint keeps its kind');
  }

  constructor(options: WeldJointOptions<UserData>) {
    const checked = checkWeldJointOptions(options);
    super(options, options.bodyA, options.bodyB, STRIDE);
    this.setAnchors(checked.anchor, checked.anchor);
    this.write(REFERENCE_ANGLE, this.bodyB.angle - this.bodyA.angle);
    this.write(LINEAR_HERTZ, checked.linearHertz);
    this.write(ANGULAR_HERTZ, checked.angularHertz);
    this.write(DAMPING_RATIO, checked.dampingRatio);
  }

  /** @internal */
  protected get layout(): JointLayout {
    return LAYOUT;
  }

  /** Stiffness of the position hold (Hz); 0 is rigid. Setting it wakes the bodies. */
  get linearHertz(): number {
    return this.value(LINEAR_HERTZ);
  }

  set linearHertz(value: number) {
    this.setNumber('linearHertz', LINEAR_HERTZ, value, 'nonNegative');
  }

  /** Stiffness of the angle hold (Hz); 0 is rigid. Setting it wakes the bodies. */
  get angularHertz(): number {
    return this.value(ANGULAR_HERTZ);
  }

  set angularHertz(value: number) {
    this.setNumber('angularHertz', ANGULAR_HERTZ, value, 'nonNegative');
  }

  /** Damping ratio of the soft holds. Setting it wakes the bodies. */
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
    const k = d[o + INV_I_A]! + d[o + INV_I_B]!;
    d[o + AXIAL_MASS] = k > 0 ? 1 / k : 0;
    // A hold of 0 Hz is rigid (Softness.set gives it no spring, whatever the damping ratio).
    scratch.set(d[o + LINEAR_HERTZ]!, d[o + DAMPING_RATIO]!, step.h);
    d[o + LINEAR_SPRINGY] = d[o + LINEAR_HERTZ]! > 0 ? 1 : 0;
    scratch.store(d, o + LINEAR_BIAS_RATE);
    scratch.set(d[o + ANGULAR_HERTZ]!, d[o + DAMPING_RATIO]!, step.h);
    d[o + ANGULAR_SPRINGY] = d[o + ANGULAR_HERTZ]! > 0 ? 1 : 0;
    scratch.store(d, o + ANGULAR_BIAS_RATE);
  }

  /** @internal */
  override createBatch(): WeldBatch {
    return new WeldBatch();
  }
}

/**
 * @internal The weld joints of a world: their records, and the step's active ones solved in one
 * loop per pass (see JointBatch).
 */
export class WeldBatch extends JointBatch {
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
      const px = d[o + LINEAR_IMPULSE_X]!;
      const py = d[o + LINEAR_IMPULSE_Y]!;
      const angular = d[o + ANGULAR_IMPULSE]!;
      s[a + V_X] -= d[o + INV_MASS_A]! * px;
      s[a + V_Y] -= d[o + INV_MASS_A]! * py;
      s[a + W] -= d[o + INV_I_A]! * (rAx * py - rAy * px + angular);
      s[b + V_X] += d[o + INV_MASS_B]! * px;
      s[b + V_Y] += d[o + INV_MASS_B]! * py;
      s[b + W] += d[o + INV_I_B]! * (rBx * py - rBy * px + angular);
    }
  }

  solve(s: Float64Array, memory: SolverMemory, step: JointStep, useBias: boolean): void {
    const d = memory.jointStore.data;
    const list = memory.jointActive;
    const end = this.start + this.active;
    const rigid = step.softness;
    for (let i = this.start; i < end; i++) {
      const o = list[3 * i]!;
      const a = list[3 * i + 1]!;
      const b = list[3 * i + 2]!;
      const iA = d[o + INV_I_A]!;
      const iB = d[o + INV_I_B]!;
      let wA = s[a + W]!;
      let wB = s[b + W]!;

      // Angle.
      {
        let bias = 0;
        let massScale = 1;
        let impulseScale = 0;
        const springy = d[o + ANGULAR_SPRINGY] === 1;
        if (useBias || springy) {
          const c = d[o + JOINT_ANGLE_0]! + s[b + DELTA_ANGLE]! - s[a + DELTA_ANGLE]!;
          if (springy) {
            bias = d[o + ANGULAR_BIAS_RATE]! * c;
            massScale = d[o + ANGULAR_MASS_SCALE]!;
            impulseScale = d[o + ANGULAR_IMPULSE_SCALE]!;
          } else {
            bias = rigid.biasRate * c;
            massScale = rigid.massScale;
            impulseScale = rigid.impulseScale;
          }
        }
        const impulse =
          -d[o + AXIAL_MASS]! * massScale * (wB - wA + bias) -
          impulseScale * d[o + ANGULAR_IMPULSE]!;
        d[o + ANGULAR_IMPULSE] += impulse;
        wA -= iA * impulse;
        wB += iB * impulse;
      }

      // Position of the anchor: rigid, or springy with its own softness in both passes.
      s[a + W] = wA;
      s[b + W] = wB;
      solveSoftPoint(s, a, b, d, o, LINEAR_IMPULSE_X, LINEAR_SPRINGY, useBias, step, false);

      if (!useBias) {
        d[o + STEP_IMPULSE_X] += d[o + LINEAR_IMPULSE_X]!;
        d[o + STEP_IMPULSE_Y] += d[o + LINEAR_IMPULSE_Y]!;
        d[o + STEP_ANGULAR_IMPULSE] += d[o + ANGULAR_IMPULSE]!;
      }
    }
  }
}
