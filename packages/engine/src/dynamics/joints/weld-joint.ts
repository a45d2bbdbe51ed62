import { readOnly } from '../../core/errors.ts';
import type { Vec2Like } from '../../math/vec2.ts';
import { Softness } from '../softness.ts';
import { JointBatch } from './joint-batch.ts';
import { KIND_WELD } from './joint-pass-codes.ts';
import {
  ANGULAR_HERTZ,
  ANGULAR_IMPULSE,
  ANGULAR_SPRINGY,
  ANGULAR_BIAS_RATE,
  AXIAL_MASS,
  DAMPING_RATIO,
  LINEAR_BIAS_RATE,
  LINEAR_HERTZ,
  LINEAR_IMPULSE_X,
  LINEAR_IMPULSE_Y,
  LINEAR_SPRINGY,
  STRIDE,
} from './weld-joint-layout.ts';
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
import { INV_I_A, INV_I_B, REFERENCE_ANGLE } from './joint-record.ts';

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
  override createBatch(): JointBatch {
    return new JointBatch(KIND_WELD);
  }
}
