import { PhysicalError, readOnly } from '../../core/errors.ts';
import {
  describeValue,
  requireNonNegative,
  requirePositive,
  requireVector,
} from '../../core/validate.ts';
import type { Vec2, Vec2Like } from '../../math/vec2.ts';
import type { Body } from '../body.ts';
import { DP_X, DP_Y, Q_C, Q_S, V_X, V_Y, W } from '../body-state.ts';
import { Softness } from '../softness.ts';
import { FlatJointBatch } from './joint-batch.ts';
import {
  Joint,
  type JointState,
  type JointStateLayout,
  type JointStep,
  optionalNonNegative,
  requireBody,
  jointMax,
  requirePoint,
  stateNumber,
  stateVector,
  worldAnchor,
} from './joint.ts';

/** Options of a {@link MouseJoint}: what dragging a body with a finger or the mouse needs. */
export interface MouseJointOptions<UserData = unknown> {
  /** The dragged body (dynamic). */
  readonly body: Body;
  /**
   * Where to pull (world point, m). The body's point under the target at creation is the one
   * pulled: grab a body where the finger touches it.
   */
  readonly target: Vec2Like;
  /** Strongest pull (N, >= 0). Default 1000 times the body's mass: about 100 g. */
  readonly maxForce?: number;
  /** Stiffness of the pull (Hz, > 0). Default 5. */
  readonly hertz?: number;
  /** Damping ratio of the pull (>= 0; 1 is critical). Default 0.7. */
  readonly dampingRatio?: number;
  /** Anything the app wants to keep with the joint. */
  readonly userData?: UserData;
}

// Box2D v3 also damps the dragged body's spin a little (0.5 Hz, ratio 0.1), so a body grabbed
// off-centre settles instead of swinging round the finger for ever.
const ANGULAR_HERTZ = 0.5;
const ANGULAR_DAMPING_RATIO = 0.1;

/**
 * @internal A mouse joint's options checked (a PhysicalError naming the first bad one), in the
 * order its constructor reads them, with defaults: the one check, also run where no joint is built
 * (a worker world's page).
 */
export function checkMouseJointOptions(options: MouseJointOptions<unknown>) {
  if (options === null || typeof options !== 'object') {
    throw new PhysicalError(
      'options',
      `must be an object of joint options, got ${describeValue(options)}.`,
    );
  }
  requireBody('body', options.body);
  if (options.body.type !== 'dynamic') {
    throw new PhysicalError('body', `must be a dynamic body, got a ${options.body.type} one.`);
  }
  return {
    target: requirePoint('target', options.target),
    maxForce: optionalNonNegative('maxForce', options.maxForce, 1000 * options.body.mass),
    hertz:
      options.hertz === undefined ? 5 : requirePositive('hertz', options.hertz, jointMax('hertz')),
    dampingRatio: optionalNonNegative('dampingRatio', options.dampingRatio, 0.7),
  };
}

/** @internal What a world snapshot saves of a mouse joint (see Joint.exportState). */
export const MOUSE_STATE: JointStateLayout = {
  fields: {
    localAnchor: 'vector',
    target: 'vector',
    maxForce: 'nonNegative',
    hertz: 'positive',
    dampingRatio: 'nonNegative',
    linearImpulse: 'vector',
    angularImpulse: 'finite',
  },
  ordered: [],
};

/**
 * Pulls a point of one body toward a target with a damped spring of bounded force (Box2D v3's
 * mouse joint, Catto): soft, so a dragged body cannot be forced through a wall, and bounded, so it
 * cannot fling a heavy stack. `bodyA` and `bodyB` are both the dragged body.
 */
export class MouseJoint<UserData = unknown> extends Joint<UserData> {
  get type(): 'mouse' {
    return 'mouse';
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set type(_value: never) {
    readOnly('type', 'a joint keeps its kind');
  }
  /** @internal Grabbed point in the body's frame (relative to the origin, m). */
  localAnchorX = -0;
  /** @internal */
  localAnchorY = -0;
  private targetX: number;
  private targetY: number;
  private force: number;
  private springHertz: number;
  private springDampingRatio: number;
  private readonly targetView: Vec2 = { x: 0, y: 0 };
  private rBx = -0;
  private rBy = -0;
  private deltaCenterX = -0;
  private deltaCenterY = -0;
  private readonly linearSoftness = new Softness();
  private readonly angularSoftness = new Softness();
  private linearImpulseX = -0;
  private linearImpulseY = -0;
  private angularImpulse = -0;

  constructor(options: MouseJointOptions<UserData>) {
    const checked = checkMouseJointOptions(options);
    const target = checked.target;
    super(
      { bodyA: options.body, bodyB: options.body, ...optionalUserData(options) },
      options.body,
      options.body,
    );
    this.targetX = target.x;
    this.targetY = target.y;
    const local = this.bodyB.getLocalPoint(target);
    this.localAnchorX = local.x;
    this.localAnchorY = local.y;
    this.force = checked.maxForce;
    this.springHertz = checked.hertz;
    this.springDampingRatio = checked.dampingRatio;
  }

  /** @internal The target. */
  protected writeAnchorA(out: Vec2): void {
    out.x = this.targetX;
    out.y = this.targetY;
  }

  /** @internal The pulled point of the body. */
  protected writeAnchorB(out: Vec2): void {
    worldAnchor(this.bodyB, this.localAnchorX, this.localAnchorY, out);
  }

  /** The dragged body. */
  get body(): Body {
    return this.bodyB;
  }

  /** Where the body is pulled (world point, m); a reused view. Setting it wakes the body. */
  get target(): Readonly<Vec2> {
    this.targetView.x = this.targetX;
    this.targetView.y = this.targetY;
    return this.targetView;
  }

  set target(value: Vec2Like) {
    requireVector('target', value);
    this.targetX = value.x;
    this.targetY = value.y;
    this.bodyB.wake();
  }

  /** Strongest pull (N). Setting it wakes the body. */
  get maxForce(): number {
    return this.force;
  }

  set maxForce(value: number) {
    this.force = requireNonNegative('maxForce', value, jointMax('maxForce'));
    this.bodyB.wake();
  }

  /** Stiffness of the pull (Hz, > 0). */
  get hertz(): number {
    return this.springHertz;
  }

  set hertz(value: number) {
    this.springHertz = requirePositive('hertz', value, jointMax('hertz'));
    this.bodyB.wake();
  }

  /** Damping ratio of the pull. */
  get dampingRatio(): number {
    return this.springDampingRatio;
  }

  set dampingRatio(value: number) {
    this.springDampingRatio = requireNonNegative('dampingRatio', value, jointMax('dampingRatio'));
    this.bodyB.wake();
  }

  /** @internal */
  protected exportOwnState(): JointState {
    return {
      localAnchor: [this.localAnchorX, this.localAnchorY],
      target: [this.targetX, this.targetY],
      maxForce: this.force,
      hertz: this.springHertz,
      dampingRatio: this.springDampingRatio,
      linearImpulse: [this.linearImpulseX, this.linearImpulseY],
      angularImpulse: this.angularImpulse,
    };
  }

  /** @internal */
  protected importOwnState(state: JointState): void {
    const anchor = stateVector(state, 'localAnchor');
    const target = stateVector(state, 'target');
    const impulse = stateVector(state, 'linearImpulse');
    this.localAnchorX = anchor[0]!;
    this.localAnchorY = anchor[1]!;
    this.targetX = target[0]!;
    this.targetY = target[1]!;
    this.force = stateNumber(state, 'maxForce');
    this.springHertz = stateNumber(state, 'hertz');
    this.springDampingRatio = stateNumber(state, 'dampingRatio');
    this.linearImpulseX = impulse[0]!;
    this.linearImpulseY = impulse[1]!;
    this.angularImpulse = stateNumber(state, 'angularImpulse');
  }

  /** @internal */
  resetImpulses(): void {
    this.linearImpulseX = 0;
    this.linearImpulseY = 0;
    this.angularImpulse = 0;
  }

  /** @internal */
  prepare(step: JointStep): void {
    this.prepareBodies(step);
    // One body: the "A" side is the fixed target.
    this.stateA = 0;
    this.invMassA = 0;
    this.invInertiaA = 0;
    const b = this.bodyB;
    const t = b.transform;
    const lx = this.localAnchorX - b.localCenterX;
    const ly = this.localAnchorY - b.localCenterY;
    this.rBx = t.c * lx - t.s * ly;
    this.rBy = t.s * lx + t.c * ly;
    this.deltaCenterX = b.centerX - this.targetX;
    this.deltaCenterY = b.centerY - this.targetY;
    this.linearSoftness.set(this.springHertz, this.springDampingRatio, step.h);
    this.angularSoftness.set(ANGULAR_HERTZ, ANGULAR_DAMPING_RATIO, step.h);
  }

  /** @internal */
  override createBatch(): MouseBatch {
    return new MouseBatch();
  }

  /** @internal Writes this step's solver numbers into a batch's slot at `o`. */
  loadBatch(d: Float64Array, o: number): void {
    d[o + R_BX] = this.rBx;
    d[o + R_BY] = this.rBy;
    d[o + DELTA_CENTER_X] = this.deltaCenterX;
    d[o + DELTA_CENTER_Y] = this.deltaCenterY;
    d[o + INV_MASS_B] = this.invMassB;
    d[o + INV_I_B] = this.invInertiaB;
    d[o + MAX_FORCE] = this.force;
    d[o + LINEAR_BIAS_RATE] = this.linearSoftness.biasRate;
    d[o + LINEAR_MASS_SCALE] = this.linearSoftness.massScale;
    d[o + LINEAR_IMPULSE_SCALE] = this.linearSoftness.impulseScale;
    d[o + ANGULAR_MASS_SCALE] = this.angularSoftness.massScale;
    d[o + ANGULAR_IMPULSE_SCALE] = this.angularSoftness.impulseScale;
    d[o + LINEAR_IMPULSE_X] = this.linearImpulseX;
    d[o + LINEAR_IMPULSE_Y] = this.linearImpulseY;
    d[o + ANGULAR_IMPULSE] = this.angularImpulse;
    d[o + STEP_IMPULSE_X] = this.stepImpulseX;
    d[o + STEP_IMPULSE_Y] = this.stepImpulseY;
    d[o + STEP_ANGULAR_IMPULSE] = this.stepAngularImpulse;
  }

  /** @internal Takes the step's impulses back from the batch's slot at `o`. */
  storeBatch(d: Float64Array, o: number): void {
    this.linearImpulseX = d[o + LINEAR_IMPULSE_X]!;
    this.linearImpulseY = d[o + LINEAR_IMPULSE_Y]!;
    this.angularImpulse = d[o + ANGULAR_IMPULSE]!;
    this.stepImpulseX = d[o + STEP_IMPULSE_X]!;
    this.stepImpulseY = d[o + STEP_IMPULSE_Y]!;
    this.stepAngularImpulse = d[o + STEP_ANGULAR_IMPULSE]!;
  }
}

// The mouse joints of a step in flat arrays (MouseBatch), doubles per joint. The "A" side is the
// fixed target, so only the dragged body's numbers are kept. The spin brake has no target angle:
// of its softness only massScale and impulseScale are used.
const R_BX = 0; // lever from the centre to the grabbed point at the step's start (m)
const R_BY = 1;
const DELTA_CENTER_X = 2; // centre of the body minus the target at the step's start (m)
const DELTA_CENTER_Y = 3;
const INV_MASS_B = 4;
const INV_I_B = 5;
const MAX_FORCE = 6;
const LINEAR_BIAS_RATE = 7;
const LINEAR_MASS_SCALE = 8;
const LINEAR_IMPULSE_SCALE = 9;
const ANGULAR_MASS_SCALE = 10;
const ANGULAR_IMPULSE_SCALE = 11;
const LINEAR_IMPULSE_X = 12; // accumulated impulses (warm-started)
const LINEAR_IMPULSE_Y = 13;
const ANGULAR_IMPULSE = 14;
const STEP_IMPULSE_X = 15; // summed over the step's relax passes, for the reaction
const STEP_IMPULSE_Y = 16;
const STEP_ANGULAR_IMPULSE = 17;
const STRIDE = 18;

/**
 * @internal The mouse joints of a step: their numbers in one Float64Array and their bodies' state
 * offsets in an Int32Array, solved in one loop per pass (see JointBatch).
 */
export class MouseBatch extends FlatJointBatch<MouseJoint> {
  constructor() {
    super(STRIDE);
  }

  warmStart(s: Float64Array): void {
    const d = this.data;
    const states = this.states;
    for (let i = 0; i < this.count; i++) {
      const o = i * STRIDE;
      const b = states[2 * i + 1]!;
      const mB = d[o + INV_MASS_B]!;
      const iB = d[o + INV_I_B]!;
      const rBx = s[b + Q_C]! * d[o + R_BX]! - s[b + Q_S]! * d[o + R_BY]!;
      const rBy = s[b + Q_S]! * d[o + R_BX]! + s[b + Q_C]! * d[o + R_BY]!;
      const px = d[o + LINEAR_IMPULSE_X]!;
      const py = d[o + LINEAR_IMPULSE_Y]!;
      s[b + V_X] += mB * px;
      s[b + V_Y] += mB * py;
      s[b + W] += iB * (rBx * py - rBy * px + d[o + ANGULAR_IMPULSE]!);
    }
  }

  solve(s: Float64Array, step: JointStep, useBias: boolean): void {
    const d = this.data;
    const states = this.states;
    for (let i = 0; i < this.count; i++) {
      const o = i * STRIDE;
      const b = states[2 * i + 1]!;
      const mB = d[o + INV_MASS_B]!;
      const iB = d[o + INV_I_B]!;
      let vBx = s[b + V_X]!;
      let vBy = s[b + V_Y]!;
      let wB = s[b + W]!;

      // A soft brake on the spin, with no target angle.
      {
        let impulse = iB > 0 ? -wB / iB : 0;
        impulse =
          d[o + ANGULAR_MASS_SCALE]! * impulse -
          d[o + ANGULAR_IMPULSE_SCALE]! * d[o + ANGULAR_IMPULSE]!;
        d[o + ANGULAR_IMPULSE] += impulse;
        wB += iB * impulse;
      }

      // The spring to the target; always soft, in both passes (it is a spring, not a rigid link).
      {
        const biasRate = d[o + LINEAR_BIAS_RATE]!;
        const massScale = d[o + LINEAR_MASS_SCALE]!;
        const impulseScale = d[o + LINEAR_IMPULSE_SCALE]!;
        const qc = s[b + Q_C]!;
        const qs = s[b + Q_S]!;
        const rBx = qc * d[o + R_BX]! - qs * d[o + R_BY]!;
        const rBy = qs * d[o + R_BX]! + qc * d[o + R_BY]!;
        const cdotX = vBx - wB * rBy;
        const cdotY = vBy + wB * rBx;
        const sepX = s[b + DP_X]! + rBx + d[o + DELTA_CENTER_X]!;
        const sepY = s[b + DP_Y]! + rBy + d[o + DELTA_CENTER_Y]!;
        const k11 = mB + rBy * rBy * iB;
        const k12 = -rBy * rBx * iB;
        const k22 = mB + rBx * rBx * iB;
        const bX = cdotX + biasRate * sepX;
        const bY = cdotY + biasRate * sepY;
        let det = k11 * k22 - k12 * k12;
        if (det !== 0) det = 1 / det;
        const solvedX = det * (k22 * bX - k12 * bY);
        const solvedY = det * (k11 * bY - k12 * bX);
        const oldX = d[o + LINEAR_IMPULSE_X]!;
        const oldY = d[o + LINEAR_IMPULSE_Y]!;
        let accX = oldX - massScale * solvedX - impulseScale * oldX;
        let accY = oldY - massScale * solvedY - impulseScale * oldY;
        const maxImpulse = d[o + MAX_FORCE]! * step.h;
        const magnitude = Math.sqrt(accX * accX + accY * accY);
        if (magnitude > maxImpulse) {
          const scale = maxImpulse / magnitude;
          accX *= scale;
          accY *= scale;
        }
        d[o + LINEAR_IMPULSE_X] = accX;
        d[o + LINEAR_IMPULSE_Y] = accY;
        const px = accX - oldX;
        const py = accY - oldY;
        vBx += mB * px;
        vBy += mB * py;
        wB += iB * (rBx * py - rBy * px);
      }

      s[b + V_X] = vBx;
      s[b + V_Y] = vBy;
      s[b + W] = wB;

      if (!useBias) {
        d[o + STEP_IMPULSE_X] += d[o + LINEAR_IMPULSE_X]!;
        d[o + STEP_IMPULSE_Y] += d[o + LINEAR_IMPULSE_Y]!;
        d[o + STEP_ANGULAR_IMPULSE] += d[o + ANGULAR_IMPULSE]!;
      }
    }
  }
}

function optionalUserData<UserData>(options: MouseJointOptions<UserData>): { userData?: UserData } {
  return options.userData === undefined ? {} : { userData: options.userData };
}
