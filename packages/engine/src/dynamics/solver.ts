import { releaseFrom } from '../core/release.ts';
import type { Body } from './body.ts';
import type { BodyBounds } from './body-bounds.ts';
import {
  BodyStates,
  DELTA_ANGLE,
  DP_X,
  DP_Y,
  Q_C,
  Q_S,
  STATE_STRIDE,
  TABLE_CENTER_X,
  TABLE_CENTER_Y,
  TABLE_INV_I,
  TABLE_INV_MASS,
  TABLE_SLOT,
  TABLE_STRIDE,
  V_X,
  V_Y,
  W,
} from './body-state.ts';
import { CONTACT_STRIDE } from './contact-data.ts';
import {
  CONSTRAINT_STRIDE,
  ContactConstraints,
  refreshCirclePairs,
  ShockPropagation,
} from './contact-solver.ts';
import { ContinuousSolver } from './continuous.ts';
import { JointSolver } from './joints/joint-solver.ts';
import {
  BODY_TABLE,
  CIRCLE_PAIRS,
  CONSTRAINT_BODIES,
  CONSTRAINT_DATA,
  CONSTRAINT_ORDER,
  CONSTRAINT_SLOTS,
  CONTACT_BODIES,
  CONTACT_DATA,
  SolverMemory,
  STATES,
} from './solver-memory.ts';
import { Softness } from './softness.ts';
import { SolverBatches } from './solver-batches.ts';

/** World settings the solver reads each step. */
export interface SolverSettings {
  gravityX: number;
  gravityY: number;
  subSteps: number;
  contactHertz: number;
  contactDampingRatio: number;
  maxContactPushSpeed: number;
  restitutionThreshold: number;
  maxLinearSpeed: number;
}

/**
 * Integrates and solves the awake bodies for one step with Box2D v3's soft step:
 *
 *   prepare contacts (once per step, anchors and masses fixed for the step)
 *   for each sub-step h = dt / n:
 *     integrate velocities (semi-implicit Euler: forces, gravity, damping, drag)
 *     point particle pairs' normals along their centres
 *     warm start, solve joints then contacts with soft position correction
 *     integrate positions (x += h v, using the new v: semi-implicit Euler)
 *     relax joints then contacts (solve again without the position correction's bias); impacts bounce here,
 *       at the moment of contact (see contact-solver.ts)
 *   store impulses, write the new poses back to the bodies
 *
 * Why this rather than Baumgarte or split impulses: sub-stepping makes the contact stiffness
 * independent of mass ratios and step size (Catto, "Solver2D", 2024), stacks come to rest without
 * jitter, and there is no separate position pass to tune. The relax pass removes the velocity the
 * soft push added, so position correction does not turn into bounce.
 */
export class Solver {
  /** The states' and constraints' numbers, shared with the WebAssembly kernel. */
  readonly memory: SolverMemory = new SolverMemory(CONSTRAINT_STRIDE, CONTACT_STRIDE, TABLE_STRIDE);
  readonly states: BodyStates = new BodyStates(this.memory);
  /**
   * What the velocity integration needs of each awake body, copied once per step so the sub-step
   * loops read numbers instead of body objects; entry i belongs to awake[i] (see PARAM_*).
   */
  private params: Float64Array = new Float64Array(PARAM_STRIDE * 64);
  readonly constraints: ContactConstraints = new ContactConstraints(this.memory);
  /** The joints, solved before the contacts in each pass (as Box2D v3 orders them). */
  readonly joints: JointSolver = new JointSolver();
  /**
   * Awake non-static bodies of this step, in world order (body.solverIndex = position + 1); only
   * the first `awakeCount` entries are valid. Per-step lists keep a count instead of truncating,
   * because `array.length = 0` frees the backing store and the next pushes would allocate again.
   */
  readonly awake: Body[] = [];
  awakeCount = 0;
  /**
   * Dynamic bodies of the last finalizeBodies that need a sweep test (the first `fastCount`), and
   * the bullets among such bodies (the first `fastBulletCount`), in awake order.
   */
  readonly fastBodies: Body[] = [];
  fastCount = 0;
  readonly fastBullets: Body[] = [];
  fastBulletCount = 0;
  /** The ground-up sweep under heavy bodies resting on light ones (contact-solver.ts). */
  private readonly shock = new ShockPropagation();
  /** Batches of islands for a step whose constraints outgrow the cache (solver-batches.ts). */
  private readonly batches = new SolverBatches();
  private readonly contactSoftness = new Softness();
  private readonly staticSoftness = new Softness();

  /**
   * Drops the references the per-step lists hold to the last step's bodies and joints (a removed
   * body must not stay reachable): overwritten with null in place, no allocation. Only the step
   * reads these lists.
   */
  releaseReferences(): void {
    releaseFrom(this.awake, 0);
    this.awakeCount = 0;
    releaseFrom(this.fastBodies, 0);
    this.fastCount = 0;
    releaseFrom(this.fastBullets, 0);
    this.fastBulletCount = 0;
    this.joints.releaseReferences();
  }

  /**
   * Frees the room sized for many more bodies and contacts than the world now has (`contacts`
   * live contact slots, kept); the next steps grow it again as needed.
   */
  shrink(contacts: number): void {
    this.releaseReferences();
    this.awake.length = 0;
    this.fastBodies.length = 0;
    this.fastBullets.length = 0;
    if (this.params.length > PARAM_STRIDE * 64) this.params = new Float64Array(PARAM_STRIDE * 64);
    this.memory.shrink(contacts);
  }

  /**
   * Makes room for a step of `bodies` bodies and `contacts` contacts in one move of the solver
   * memory, before the narrow phase reads the contact slots.
   */
  reserve(bodies: number, contacts: number): void {
    this.memory.reserveStep((bodies + 1) * STATE_STRIDE, bodies, contacts);
  }

  /**
   * Collects the awake bodies, gathers their forces for this step and loads their states. Must run
   * before {@link solve}; `bodies` is every body of the world.
   */
  gatherBodies(bodies: readonly Body[], dt: number): void {
    const awake = this.awake;
    // One pass over the bodies: each body object is read once per step here and once in
    // finalizeBodies, which is what a scene of many bodies pays for in cache misses.
    // Room for the states and the body table (by world index, for preparing contacts, see
    // body-state.ts) first: reserving one replaces every view of the memory.
    this.memory.reserveBodyTable(bodies.length);
    const s = this.states.reserve(bodies.length);
    const table = this.memory.bodyTable;
    if (this.params.length < bodies.length * PARAM_STRIDE) {
      let size = this.params.length;
      while (size < bodies.length * PARAM_STRIDE) size *= 2;
      this.params = new Float64Array(size);
    }
    const params = this.params;
    let count = 0;
    for (let n = 0; n < bodies.length; n++) {
      const body = bodies[n]!;
      body.solverIndex = 0;
      const t = n * TABLE_STRIDE;
      table[t + TABLE_CENTER_X] = body.centerX;
      table[t + TABLE_CENTER_Y] = body.centerY;
      if (!body.awake || body.type === 'static') {
        table[t + TABLE_SLOT] = 0;
        table[t + TABLE_INV_MASS] = 0;
        table[t + TABLE_INV_I] = 0;
        continue;
      }
      const i = count++;
      table[t + TABLE_SLOT] = count;
      table[t + TABLE_INV_MASS] = body.invMass;
      table[t + TABLE_INV_I] = body.invInertia;
      if (i < awake.length) awake[i] = body;
      else awake.push(body);
      body.solverIndex = count;
      const k = (i + 1) * STATE_STRIDE;
      s[k + V_X] = body.velocityX;
      s[k + V_Y] = body.velocityY;
      s[k + W] = body.angularVelocityValue;
      s[k + DELTA_ANGLE] = 0;
      s[k + DP_X] = 0;
      s[k + DP_Y] = 0;
      s[k + Q_C] = 1;
      s[k + Q_S] = 0;
      body.center0X = body.centerX;
      body.center0Y = body.centerY;
      body.angle0 = body.angleValue;
      gatherForces(body, dt);
      const q = i * PARAM_STRIDE;
      params[q + INV_MASS] = body.invMass;
      params[q + INV_INERTIA] = body.invInertia;
      params[q + GRAVITY_SCALE] = body.gravityScaleValue;
      params[q + DRAG] = body.dragValue;
      params[q + FORCE_X] = body.forceX;
      params[q + FORCE_Y] = body.forceY;
      params[q + TORQUE] = body.torqueValue;
      params[q + LINEAR_DAMPING] = body.linearDampingValue;
      params[q + ANGULAR_DAMPING] = body.angularDampingValue;
    }
    this.awakeCount = count;
  }

  /**
   * Solves the step for the gathered bodies and the first `contactCount` contact slots of the
   * solver memory (the touching ones become constraints; see contact-data.ts).
   */
  solve(contactCount: number, settings: SolverSettings, dt: number): void {
    const constraints = this.constraints;
    // Room first: growing the memory replaces every view of it, `s` included.
    constraints.reserve(contactCount);
    const memory = this.memory;
    const subSteps = settings.subSteps;
    const h = dt / subSteps;

    // A contact spring stiffer than a quarter of the sub-step rate would be under-resolved.
    const contactHertz = Math.min(settings.contactHertz, (0.25 * subSteps) / dt);
    this.contactSoftness.set(contactHertz, settings.contactDampingRatio, h);
    this.staticSoftness.set(2 * contactHertz, settings.contactDampingRatio, h);
    const kernel = memory.kernel;
    // Joints first (they do not depend on the contacts): whether the step may run in batches of
    // islands decides how the contacts are prepared.
    const joints = this.joints;
    joints.prepare(dt, subSteps, contactHertz, this.awakeCount);
    const batches = this.batches;
    const batchable = joints.activeCount === 0 && batches.wants(contactCount);
    // With batches in view, contacts are only classified here and each batch fills its
    // constraints just before its sub-steps, while they stay in cache.
    let filled = true;
    const o = memory.offsets;
    if (batchable) {
      constraints.count = kernel.classify(
        o[CONTACT_DATA]!,
        o[CONTACT_BODIES]!,
        o[BODY_TABLE]!,
        o[CONSTRAINT_BODIES]!,
        o[CONSTRAINT_SLOTS]!,
        o[CIRCLE_PAIRS]!,
        contactCount,
      );
      filled = false;
    } else {
      const soft = this.contactSoftness;
      const hard = this.staticSoftness;
      constraints.count = kernel.prepare(
        o[CONTACT_DATA]!,
        o[CONTACT_BODIES]!,
        o[BODY_TABLE]!,
        o[STATES]!,
        o[CONSTRAINT_DATA]!,
        o[CONSTRAINT_BODIES]!,
        o[CONSTRAINT_SLOTS]!,
        o[CIRCLE_PAIRS]!,
        contactCount,
        soft.biasRate,
        soft.massScale,
        soft.impulseScale,
        hard.biasRate,
        hard.massScale,
        hard.impulseScale,
        soft.hertz,
        soft.zeta,
        soft.h,
        dt,
      );
    }
    constraints.circlePairCount = kernel.circlePairCount.value;
    constraints.heavyOnLightCount = kernel.heavyOnLightCount.value;
    scrambleOrder(constraints.order, constraints.count);
    const shock = this.shock;
    // The heavy-on-light sweep reads the prepared constraints.
    if (!filled && constraints.heavyOnLightCount > 0) {
      this.fill(0, constraints.count, dt);
      filled = true;
    }
    shock.prepare(
      constraints,
      this.awakeCount,
      this.staticSoftness.biasRate,
      settings.gravityX,
      settings.gravityY,
    );

    // Many islands whose constraints outgrow the cache run batch by batch (solver-batches.ts);
    // joints, heavy-on-light sweeps and particle pairs span the whole step's lists, so a step
    // with any of them runs whole.
    if (
      batchable &&
      shock.count === 0 &&
      constraints.circlePairCount === 0 &&
      batches.build(constraints.order, constraints.count, constraints.bodies, this.awakeCount)
    ) {
      const orderStart = batches.orderStart;
      const bodyStart = batches.bodyStart;
      for (let k = 0; k < batches.count; k++) {
        if (!filled) this.fill(orderStart[k]!, orderStart[k + 1]!, dt);
        this.subSteps(
          settings,
          h,
          orderStart[k]!,
          orderStart[k + 1]!,
          batches.bodies,
          bodyStart[k]!,
          bodyStart[k + 1]!,
        );
      }
    } else {
      if (!filled) this.fill(0, constraints.count, dt);
      this.subSteps(settings, h, 0, constraints.count, null, 0, this.awakeCount);
    }
    joints.finish();
  }

  /**
   * Fills the classified constraints at positions `from` to `to` of the visiting order (the
   * WebAssembly kernel's prepare, second half); each depends only on its own contact.
   */
  private fill(from: number, to: number, dt: number): void {
    const o = this.memory.offsets;
    const soft = this.contactSoftness;
    const hard = this.staticSoftness;
    this.memory.kernel.prepareListed(
      o[CONTACT_DATA]!,
      o[CONTACT_BODIES]!,
      o[BODY_TABLE]!,
      o[STATES]!,
      o[CONSTRAINT_DATA]!,
      o[CONSTRAINT_BODIES]!,
      o[CONSTRAINT_SLOTS]!,
      o[CONSTRAINT_ORDER]! + 4 * from,
      to - from,
      soft.biasRate,
      soft.massScale,
      soft.impulseScale,
      hard.biasRate,
      hard.massScale,
      hard.impulseScale,
      soft.hertz,
      soft.zeta,
      soft.h,
      dt,
    );
  }

  /**
   * The sub-steps of a step, for the constraints at positions `from` to `to` of the visiting
   * order and the awake bodies `bodyList[bodyFrom .. bodyTo)` (with `bodyList` null, the awake
   * indices bodyFrom .. bodyTo themselves): the whole step, or one batch of islands. Then stores
   * those constraints' impulses in their contacts' slots.
   */
  private subSteps(
    settings: SolverSettings,
    h: number,
    from: number,
    to: number,
    bodyList: Int32Array | null,
    bodyFrom: number,
    bodyTo: number,
  ): void {
    const constraints = this.constraints;
    const memory = this.memory;
    const kernel = memory.kernel;
    const s = this.states.data;
    const joints = this.joints;
    const shock = this.shock;
    const shockBiasRate = this.staticSoftness.biasRate;
    const inverseH = 1 / h;
    const threshold = settings.restitutionThreshold;
    const maxPushSpeed = settings.maxContactPushSpeed;
    const count = to - from;
    for (let step = 0; step < settings.subSteps; step++) {
      integrateVelocities(this.params, bodyList, bodyFrom, bodyTo, s, settings, h);
      refreshCirclePairs(constraints, s);
      joints.warmStart(s);
      // Offsets in bytes: the order holds 4-byte indices.
      const order = memory.offsets[CONSTRAINT_ORDER]! + 4 * from;
      kernel.warmStart(
        memory.offsets[CONSTRAINT_DATA]!,
        memory.offsets[CONSTRAINT_BODIES]!,
        order,
        memory.offsets[STATES]!,
        count,
      );
      joints.solve(s, true);
      kernel.solve(
        memory.offsets[CONSTRAINT_DATA]!,
        memory.offsets[CONSTRAINT_BODIES]!,
        order,
        memory.offsets[STATES]!,
        count,
        inverseH,
        maxPushSpeed,
        threshold,
        1,
      );
      if (shock.count > 0) {
        shock.solve(constraints, s, inverseH, shockBiasRate, maxPushSpeed, threshold, true);
      }
      joints.solveChains(s, true);
      integratePositions(bodyList, bodyFrom, bodyTo, s, h);
      joints.solveChains(s, false, true);
      refreshCirclePairs(constraints, s);
      joints.solve(s, false);
      kernel.solve(
        memory.offsets[CONSTRAINT_DATA]!,
        memory.offsets[CONSTRAINT_BODIES]!,
        order,
        memory.offsets[STATES]!,
        count,
        inverseH,
        maxPushSpeed,
        threshold,
        0,
      );
      if (shock.count > 0) {
        shock.solve(constraints, s, inverseH, shockBiasRate, maxPushSpeed, threshold, false);
      }
      joints.solveChains(s, false);
    }
    // Each constraint's impulses go to its own contact slot: a batch stores its own while they
    // are still in cache (the order of the stores changes nothing).
    kernel.storeImpulses(
      memory.offsets[CONSTRAINT_DATA]!,
      memory.offsets[CONSTRAINT_SLOTS]!,
      memory.offsets[CONTACT_DATA]!,
      memory.offsets[CONSTRAINT_ORDER]! + 4 * from,
      count,
    );
  }

  /**
   * Writes velocities and poses back to the bodies, updates their sleep timers and moves their
   * shapes' broad-phase boxes (`bounds`, predicting a next step of `boundsDt`). With `continuous`,
   * dynamic bodies that moved far enough to need a sweep test are listed in `fastBodies` and
   * `fastBullets` instead, their boxes left to the sweep. One pass, so each body object is
   * fetched once (Box2D v3's "b2FinalizeBodiesTask" does the same).
   */
  finalizeBodies(dt: number, bounds: BodyBounds, boundsDt: number, continuous: boolean): void {
    const awake = this.awake;
    const s = this.states.data;
    let fastCount = 0;
    let fastBulletCount = 0;
    const fastBodies = this.fastBodies;
    const fastBullets = this.fastBullets;
    bounds.dt = boundsDt;
    for (let i = 0; i < this.awakeCount; i++) {
      const body = awake[i]!;
      const k = (i + 1) * STATE_STRIDE;
      const vx = s[k + V_X]!;
      const vy = s[k + V_Y]!;
      const w = s[k + W]!;
      const dpx = s[k + DP_X]!;
      const dpy = s[k + DP_Y]!;
      body.velocityX = vx;
      body.velocityY = vy;
      body.angularVelocityValue = w;
      body.centerX += dpx;
      body.centerY += dpy;
      const angle = body.angleValue + s[k + DELTA_ANGLE]!;
      body.angleValue = angle;
      // The angle is the exact sum of h w; the transform follows it, so rotation never drifts
      // from the integrated angle.
      body.transform.setFromCenter(
        body.centerX,
        body.centerY,
        angle,
        body.localCenterX,
        body.localCenterY,
      );
      if (continuous && body.type === 'dynamic' && ContinuousSolver.isFast(body)) {
        if (body.bulletValue) {
          if (fastBulletCount < fastBullets.length) fastBullets[fastBulletCount] = body;
          else fastBullets.push(body);
          fastBulletCount++;
        } else {
          if (fastCount < fastBodies.length) fastBodies[fastCount] = body;
          else fastBodies.push(body);
          fastCount++;
        }
      } else {
        bounds.refresh(body, false);
      }

      // Sleep: the body must be slow, and not being moved by position correction either
      // (Box2D v3's rule, with its 0.5 weight on correction).
      // A body with a force still to act (a 'constant' or timed one) must not sleep: a small
      // force on a heavy body is slow at first, and sleeping would zero its velocity and stop it.
      if (!body.allowSleepValue || body.forceList.length > 0) {
        body.sleepTime = 0;
        continue;
      }
      const extent = body.maxExtent;
      const speed = Math.sqrt(vx * vx + vy * vy) + extent * Math.abs(w);
      const moved = Math.sqrt(dpx * dpx + dpy * dpy) + extent * Math.abs(s[k + DELTA_ANGLE]!);
      const sleepSpeed = Math.max(speed, (0.5 * moved) / dt);
      if (sleepSpeed > SLEEP_SPEED) body.sleepTime = 0;
      else body.sleepTime += dt;
    }
    this.fastCount = fastCount;
    this.fastBulletCount = fastBulletCount;
  }
}

// Per awake body in Solver.params.
const INV_MASS = 0;
const INV_INERTIA = 1;
const GRAVITY_SCALE = 2;
const DRAG = 3;
const FORCE_X = 4;
const FORCE_Y = 5;
const TORQUE = 6;
const LINEAR_DAMPING = 7;
const ANGULAR_DAMPING = 8;
const PARAM_STRIDE = 9;

/** Contacts kept together when the sweep order is scrambled (see scrambleOrder). */
const SCRAMBLE_RUN = 32;

/**
 * Writes a scrambled, deterministic visiting order of `count` constraints into `order`.
 * Gauss-Seidel sweeps in creation order (left to right, row by row in a stack) push every row the
 * same way and made a 100-row pyramid lean by half a metre; a scrambled sweep cancels that bias,
 * as Box2D v3's graph colouring does. Runs of SCRAMBLE_RUN neighbouring constraints stay together
 * (they touch nearby bodies and sit together in memory, which keeps both in cache: scrambling
 * single contacts cost half the speed); the runs are visited in the order k * stride mod runs,
 * with a stride near runs / golden ratio and coprime to it.
 */
function scrambleOrder(order: Int32Array, count: number): void {
  const runs = Math.ceil(count / SCRAMBLE_RUN);
  if (runs < 3) {
    for (let i = 0; i < count; i++) order[i] = i;
    return;
  }
  let stride = Math.floor(runs * 0.6180339887498949) | 1;
  while (greatestCommonDivisor(stride, runs) !== 1) stride += 2;
  let k = 0;
  for (let visited = 0, run = 0; visited < runs; visited++) {
    const end = Math.min(count, (run + 1) * SCRAMBLE_RUN);
    for (let i = run * SCRAMBLE_RUN; i < end; i++) order[k++] = i;
    run += stride;
    if (run >= runs) run -= runs;
  }
}

function greatestCommonDivisor(a: number, b: number): number {
  while (b !== 0) {
    const t = a % b;
    a = b;
    b = t;
  }
  return a;
}

/** Bodies slower than this (m/s, at their farthest point) count as resting. */
export const SLEEP_SPEED = 0.05;

/** Sums the body's forces for this step (scaled by the part of the step each acts) and drops spent ones. */
function gatherForces(body: Body, dt: number): void {
  let fx = 0;
  let fy = 0;
  let torque = 0;
  const forces = body.forceList;
  if (forces.length > 0) {
    const c = body.transform.c;
    const sn = body.transform.s;
    for (let i = 0; i < forces.length; i++) {
      const force = forces[i]!;
      const fraction = force.consume(dt);
      if (fraction === 0) continue;
      const x = force.x * fraction;
      const y = force.y * fraction;
      fx += x;
      fy += y;
      torque += force.torque * fraction;
      if (force.hasPoint) {
        // Lever arm from the centre of mass to the point attached to the body.
        const rx = c * force.localPointX - sn * force.localPointY + body.transform.x - body.centerX;
        const ry = sn * force.localPointX + c * force.localPointY + body.transform.y - body.centerY;
        torque += rx * y - ry * x;
      }
    }
    for (let i = forces.length - 1; i >= 0; i--) {
      if (forces[i]!.isExpired) body.removeForce(forces[i]!);
    }
  }
  body.forceX = fx;
  body.forceY = fy;
  body.torqueValue = torque;
}

/**
 * Semi-implicit Euler, velocity half: v += h (F / m + g), with damping and the thesis's drag
 * applied implicitly (v / (1 + h c)) so that no damping value can reverse a velocity; for the
 * awake bodies list[from .. to), or from .. to themselves when `list` is null.
 */
function integrateVelocities(
  params: Float64Array,
  list: Int32Array | null,
  from: number,
  to: number,
  s: Float64Array,
  settings: SolverSettings,
  h: number,
): void {
  const gx = settings.gravityX;
  const gy = settings.gravityY;
  const maxSpeedSquared = settings.maxLinearSpeed * settings.maxLinearSpeed;
  // At most a quarter turn per sub-step (Box2D v3's B2_MAX_ROTATION): faster, the first-order
  // rotation of the contact and joint anchors is meaningless, and a joint pulling a tiny body
  // by a long lever could spin it up without bound until it became NaN.
  const maxAngularSpeed = (0.25 * Math.PI) / h;
  for (let n = from; n < to; n++) {
    const i = list === null ? n : list[n]!;
    const q = i * PARAM_STRIDE;
    const invMass = params[q + INV_MASS]!;
    if (invMass === 0) continue; // kinematic: keeps the velocity it was given
    const k = (i + 1) * STATE_STRIDE;
    const scale = params[q + GRAVITY_SCALE]!;
    let vx = s[k + V_X]!;
    let vy = s[k + V_Y]!;
    // The thesis's drag, F = -drag |v| v, with |v| taken at the start of the sub-step: then the
    // discrete motion has the exact terminal speed sqrt(m g / drag) and coasts exactly as
    // 1/v = 1/v0 + (drag/m) t.
    const drag = params[q + DRAG]!;
    const dragFactor = drag > 0 ? 1 / (1 + h * invMass * drag * Math.sqrt(vx * vx + vy * vy)) : 1;
    vx = (vx + h * (invMass * params[q + FORCE_X]! + scale * gx)) * dragFactor;
    vy = (vy + h * (invMass * params[q + FORCE_Y]! + scale * gy)) * dragFactor;
    let w = s[k + W]! + h * params[q + INV_INERTIA]! * params[q + TORQUE]!;
    const linearDamping = params[q + LINEAR_DAMPING]!;
    if (linearDamping > 0) {
      const factor = 1 / (1 + h * linearDamping);
      vx *= factor;
      vy *= factor;
    }
    const angularDamping = params[q + ANGULAR_DAMPING]!;
    if (angularDamping > 0) w /= 1 + h * angularDamping;
    if (w > maxAngularSpeed) w = maxAngularSpeed;
    else if (w < -maxAngularSpeed) w = -maxAngularSpeed;
    const speedSquared = vx * vx + vy * vy;
    if (speedSquared > maxSpeedSquared) {
      const ratio = settings.maxLinearSpeed / Math.sqrt(speedSquared);
      vx *= ratio;
      vy *= ratio;
    }
    s[k + V_X] = vx;
    s[k + V_Y] = vy;
    s[k + W] = w;
  }
}

/**
 * Semi-implicit Euler, position half: x += h v with the velocity just solved; for the awake
 * bodies list[from .. to), or from .. to themselves when `list` is null.
 */
function integratePositions(
  list: Int32Array | null,
  from: number,
  to: number,
  s: Float64Array,
  h: number,
): void {
  for (let n = from; n < to; n++) {
    const i = list === null ? n : list[n]!;
    const k = (i + 1) * STATE_STRIDE;
    const w = s[k + W]!;
    s[k + DP_X] += h * s[k + V_X]!;
    s[k + DP_Y] += h * s[k + V_Y]!;
    if (w !== 0) {
      s[k + DELTA_ANGLE] += h * w;
      // First-order rotation update, renormalised: enough for the contact anchors within a step.
      const qc = s[k + Q_C]!;
      const qs = s[k + Q_S]!;
      const c = qc - h * w * qs;
      const sn = qs + h * w * qc;
      const inverseLength = 1 / Math.sqrt(c * c + sn * sn);
      s[k + Q_C] = c * inverseLength;
      s[k + Q_S] = sn * inverseLength;
    }
  }
}
