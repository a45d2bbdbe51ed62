import { PhysicalError, readOnly } from '../../core/errors.ts';
import { describeValue, requirePositive, requireVector } from '../../core/validate.ts';
import type { Vec2, Vec2Like } from '../../math/vec2.ts';
import type { Body } from '../body.ts';
import { DP_X, DP_Y, V_X, V_Y, W } from '../body-state.ts';
import { Softness } from '../softness.ts';
import { JointBatch } from './joint-batch.ts';
import type { SolverMemory } from '../solver-memory.ts';
import {
  Joint,
  jointLayout,
  stateLayout,
  type JointLayout,
  type JointStateLayout,
  type JointStep,
  optionalNonNegative,
  requireBody,
  jointMax,
  requirePoint,
} from './joint.ts';
import { turnedX, turnedY } from './joint-levers.ts';
import {
  DELTA_CENTER_X,
  DELTA_CENTER_Y,
  INV_I_A,
  INV_I_B,
  INV_MASS_A,
  INV_MASS_B,
  LOCAL_ANCHOR_BX,
  LOCAL_ANCHOR_BY,
  R_BX,
  R_BY,
  STATE_A,
  STEP_ANGULAR_IMPULSE,
  STEP_IMPULSE_X,
  STEP_IMPULSE_Y,
} from './joint-record.ts';

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

// A mouse joint's record: the head (joint-record.ts; the grabbed point is B's local anchor, the
// "A" side is the fixed target, so of A's numbers only zeros), then its own numbers. The spin brake
// has no target angle: of its softness only the mass and impulse scales are used.
const TARGET_X = 25; // JOINT_HEAD; settings
const TARGET_Y = 26; // JOINT_HEAD + 1
const MAX_FORCE = 27; // JOINT_HEAD + 2
const HERTZ = 28; // JOINT_HEAD + 3
const DAMPING_RATIO = 29; // JOINT_HEAD + 4
const LINEAR_BIAS_RATE = 30; // JOINT_HEAD + 5; the pull's softness this step
const LINEAR_MASS_SCALE = 31; // JOINT_HEAD + 6
const LINEAR_IMPULSE_SCALE = 32; // JOINT_HEAD + 7
const ANGULAR_BIAS_RATE = 33; // JOINT_HEAD + 8; the spin brake's softness this step
const ANGULAR_MASS_SCALE = 34; // JOINT_HEAD + 9
const ANGULAR_IMPULSE_SCALE = 35; // JOINT_HEAD + 10
const LINEAR_IMPULSE_X = 36; // JOINT_HEAD + 11; accumulated impulses (warm-started)
const LINEAR_IMPULSE_Y = 37; // JOINT_HEAD + 12
const ANGULAR_IMPULSE = 38; // JOINT_HEAD + 13
const STRIDE = 39; // JOINT_HEAD + 14

const LAYOUT: JointLayout = /* @__PURE__ */ jointLayout(
  STRIDE,
  [
    {
      localAnchor: ['vector', LOCAL_ANCHOR_BX],
      target: ['vector', TARGET_X],
      maxForce: ['nonNegative', MAX_FORCE],
      hertz: ['positive', HERTZ],
      dampingRatio: ['nonNegative', DAMPING_RATIO],
      linearImpulse: ['vector', LINEAR_IMPULSE_X],
      angularImpulse: ['finite', ANGULAR_IMPULSE],
    },
  ],
  [[LINEAR_IMPULSE_X, LINEAR_IMPULSE_Y, ANGULAR_IMPULSE]],
);

/** @internal What a world snapshot saves of a mouse joint (see exportJointState). */
export const MOUSE_STATE: JointStateLayout = /* @__PURE__ */ stateLayout(LAYOUT, []);

const scratch = /* @__PURE__ */ new Softness();

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
  private readonly targetView: Vec2 = { x: 0, y: 0 };

  constructor(options: MouseJointOptions<UserData>) {
    const checked = checkMouseJointOptions(options);
    const target = checked.target;
    super(
      { bodyA: options.body, bodyB: options.body, ...optionalUserData(options) },
      options.body,
      options.body,
      STRIDE,
    );
    this.write(TARGET_X, target.x);
    this.write(TARGET_Y, target.y);
    const local = this.bodyB.getLocalPoint(target);
    this.write(LOCAL_ANCHOR_BX, local.x);
    this.write(LOCAL_ANCHOR_BY, local.y);
    this.write(MAX_FORCE, checked.maxForce);
    this.write(HERTZ, checked.hertz);
    this.write(DAMPING_RATIO, checked.dampingRatio);
  }

  /** @internal */
  protected get layout(): JointLayout {
    return LAYOUT;
  }

  /** @internal The target. */
  protected override writeAnchorA(out: Vec2): void {
    out.x = this.value(TARGET_X);
    out.y = this.value(TARGET_Y);
  }

  /** The dragged body. */
  get body(): Body {
    return this.bodyB;
  }

  /** Where the body is pulled (world point, m); a reused view. Setting it wakes the body. */
  get target(): Readonly<Vec2> {
    this.writeAnchorA(this.targetView);
    return this.targetView;
  }

  set target(value: Vec2Like) {
    requireVector('target', value);
    this.write(TARGET_X, value.x);
    this.write(TARGET_Y, value.y);
    this.bodyB.wake();
  }

  /** Strongest pull (N). Setting it wakes the body. */
  get maxForce(): number {
    return this.value(MAX_FORCE);
  }

  set maxForce(value: number) {
    this.setNumber('maxForce', MAX_FORCE, value, 'nonNegative');
  }

  /** Stiffness of the pull (Hz, > 0). */
  get hertz(): number {
    return this.value(HERTZ);
  }

  set hertz(value: number) {
    this.setNumber('hertz', HERTZ, value, 'positive');
  }

  /** Damping ratio of the pull. */
  get dampingRatio(): number {
    return this.value(DAMPING_RATIO);
  }

  set dampingRatio(value: number) {
    this.setNumber('dampingRatio', DAMPING_RATIO, value, 'nonNegative');
  }

  /** @internal */
  prepare(step: JointStep): void {
    this.prepareBodies(step);
    const d = this.store.data;
    const o = this.base;
    // One body: the "A" side is the fixed target.
    d[o + STATE_A] = 0;
    d[o + INV_MASS_A] = 0;
    d[o + INV_I_A] = 0;
    const b = this.bodyB;
    const t = b.transform;
    const lx = d[o + LOCAL_ANCHOR_BX]! - b.localCenterX;
    const ly = d[o + LOCAL_ANCHOR_BY]! - b.localCenterY;
    d[o + R_BX] = t.c * lx - t.s * ly;
    d[o + R_BY] = t.s * lx + t.c * ly;
    d[o + DELTA_CENTER_X] = b.centerX - d[o + TARGET_X]!;
    d[o + DELTA_CENTER_Y] = b.centerY - d[o + TARGET_Y]!;
    scratch.set(d[o + HERTZ]!, d[o + DAMPING_RATIO]!, step.h).store(d, o + LINEAR_BIAS_RATE);
    // Box2D v3 also damps the dragged body's spin a little (0.5 Hz, ratio 0.1), so a body grabbed
    // off-centre settles instead of swinging round the finger for ever.
    scratch.set(0.5, 0.1, step.h).store(d, o + ANGULAR_BIAS_RATE);
  }

  /** @internal */
  override createBatch(): MouseBatch {
    return new MouseBatch();
  }
}

/**
 * @internal The mouse joints of a world: their records, and the step's active ones solved in one
 * loop per pass (see JointBatch).
 */
export class MouseBatch extends JointBatch {
  warmStart(s: Float64Array, memory: SolverMemory): void {
    const d = memory.jointStore.data;
    const list = memory.jointActive;
    const end = this.start + this.active;
    for (let i = this.start; i < end; i++) {
      const o = list[3 * i]!;
      const b = list[3 * i + 2]!;
      const mB = d[o + INV_MASS_B]!;
      const iB = d[o + INV_I_B]!;
      const rBx = turnedX(s, b, d, o + R_BX);
      const rBy = turnedY(s, b, d, o + R_BX);
      const px = d[o + LINEAR_IMPULSE_X]!;
      const py = d[o + LINEAR_IMPULSE_Y]!;
      s[b + V_X] += mB * px;
      s[b + V_Y] += mB * py;
      s[b + W] += iB * (rBx * py - rBy * px + d[o + ANGULAR_IMPULSE]!);
    }
  }

  solve(s: Float64Array, memory: SolverMemory, step: JointStep, useBias: boolean): void {
    const d = memory.jointStore.data;
    const list = memory.jointActive;
    const end = this.start + this.active;
    for (let i = this.start; i < end; i++) {
      const o = list[3 * i]!;
      const b = list[3 * i + 2]!;
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
        const rBx = turnedX(s, b, d, o + R_BX);
        const rBy = turnedY(s, b, d, o + R_BX);
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
