import { PhysicalError, readOnly } from '../../core/errors.ts';
import { describeValue, requirePositive, requireVector } from '../../core/validate.ts';
import type { Vec2, Vec2Like } from '../../math/vec2.ts';
import type { Body } from '../body.ts';
import { Softness } from '../softness.ts';
import { JointBatch } from './joint-batch.ts';
import { KIND_MOUSE } from './joint-pass-codes.ts';
import {
  ANGULAR_BIAS_RATE,
  ANGULAR_IMPULSE,
  DAMPING_RATIO,
  HERTZ,
  LINEAR_BIAS_RATE,
  LINEAR_IMPULSE_X,
  LINEAR_IMPULSE_Y,
  MAX_FORCE,
  STRIDE,
  TARGET_X,
  TARGET_Y,
} from './mouse-joint-layout.ts';
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
import {
  DELTA_CENTER_X,
  DELTA_CENTER_Y,
  INV_I_A,
  INV_MASS_A,
  LOCAL_ANCHOR_BX,
  LOCAL_ANCHOR_BY,
  R_BX,
  R_BY,
  STATE_A,
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
  override createBatch(): JointBatch {
    return new JointBatch(KIND_MOUSE);
  }
}

function optionalUserData<UserData>(options: MouseJointOptions<UserData>): { userData?: UserData } {
  return options.userData === undefined ? {} : { userData: options.userData };
}
