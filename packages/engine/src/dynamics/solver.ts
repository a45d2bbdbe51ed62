import { releaseFrom } from '../core/release.ts';
import type { Body } from './body.ts';
import type { BodyBounds } from './body-bounds.ts';
import {
  BODY_STRIDE,
  B_ANGLE,
  B_ANGLE0,
  B_ANGULAR_DAMPING,
  B_AWAKE,
  B_CENTER0_X,
  B_CENTER0_Y,
  B_CENTER_X,
  B_CENTER_Y,
  B_DRAG,
  B_FORCE_X,
  B_FORCE_Y,
  B_GRAVITY_SCALE,
  B_INV_INERTIA,
  B_INV_MASS,
  B_LINEAR_DAMPING,
  B_LOCAL_CENTER_X,
  B_LOCAL_CENTER_Y,
  B_FLAGS,
  B_MAX_EXTENT,
  B_SLEEP_TIME,
  FLAG_ALLOW_SLEEP,
  B_TORQUE,
  B_VX,
  B_VY,
  B_W,
} from './body-memory.ts';
import {
  BodyStates,
  DELTA_ANGLE,
  DP_X,
  DP_Y,
  Q_C,
  Q_S,
  KICK_VX,
  KICK_VY,
  KICK_W,
  MARK_STRIDE,
  STATE_STRIDE,
  stateDoubles,
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
import {
  IMPACT_CLOSE,
  IMPACT_CONTINUE,
  IMPACT_OPEN,
  IMPACT_ROUND,
} from './contact-constraint-layout.ts';
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
import { ContactPairing } from './contact-pairing.ts';

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
  /** Pairs for the kernel's lanes and the constraints' numbering (contact-pairing.ts). */
  private readonly pairing = new ContactPairing();
  /** The slowest approach of a loaded contact the impact rounds count as an impact (m/s). */
  private loadSpeed = -0;
  /** The most a push-out moves a contact (m/s): a pressed point approaching faster is an impact. */
  private pushSpeed = -0;
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
   * Frees the room sized for many more bodies and contacts than the world now has (`bodies`
   * bodies' numbers and `contacts` live contact slots, kept); the next steps grow it again as
   * needed.
   */
  shrink(bodies: number, contacts: number): void {
    this.releaseReferences();
    this.awake.length = 0;
    this.fastBodies.length = 0;
    this.fastBullets.length = 0;
    if (this.params.length > PARAM_STRIDE * 64) this.params = new Float64Array(PARAM_STRIDE * 64);
    this.memory.shrink(bodies, contacts);
  }

  /**
   * Makes room for a step of `bodies` bodies and `contacts` contacts (`liveContacts` of them
   * already in their slots, the rest about to be made) in one move of the solver memory, before
   * the new contacts are made and the narrow phase reads the slots.
   */
  reserve(bodies: number, contacts: number, liveContacts: number): void {
    this.memory.reserveStep(stateDoubles(bodies), bodies, contacts, liveContacts);
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
    // The bodies' own numbers, by world index (body-memory.ts): read in place, in order. Taken
    // after the reserves above, which may move the memory.
    const d = this.memory.bodyStore.data;
    let count = 0;
    for (let n = 0; n < bodies.length; n++) {
      const body = bodies[n]!;
      body.solverIndex = 0;
      const b = n * BODY_STRIDE;
      const t = n * TABLE_STRIDE;
      const centerX = d[b + B_CENTER_X]!;
      const centerY = d[b + B_CENTER_Y]!;
      table[t + TABLE_CENTER_X] = centerX;
      table[t + TABLE_CENTER_Y] = centerY;
      if (d[b + B_AWAKE] === 0 || body.typeValue === 'static') {
        table[t + TABLE_SLOT] = 0;
        table[t + TABLE_INV_MASS] = 0;
        table[t + TABLE_INV_I] = 0;
        continue;
      }
      const i = count++;
      const invMass = d[b + B_INV_MASS]!;
      const invInertia = d[b + B_INV_INERTIA]!;
      table[t + TABLE_SLOT] = count;
      table[t + TABLE_INV_MASS] = invMass;
      table[t + TABLE_INV_I] = invInertia;
      if (i < awake.length) awake[i] = body;
      else awake.push(body);
      body.solverIndex = count;
      const k = (i + 1) * STATE_STRIDE;
      s[k + V_X] = d[b + B_VX]!;
      s[k + V_Y] = d[b + B_VY]!;
      s[k + W] = d[b + B_W]!;
      s[k + DELTA_ANGLE] = 0;
      s[k + DP_X] = 0;
      s[k + DP_Y] = 0;
      s[k + Q_C] = 1;
      s[k + Q_S] = 0;
      d[b + B_CENTER0_X] = centerX;
      d[b + B_CENTER0_Y] = centerY;
      d[b + B_ANGLE0] = d[b + B_ANGLE]!;
      if (body.forceList.length > 0) gatherForces(body, dt);
      else {
        d[b + B_FORCE_X] = 0;
        d[b + B_FORCE_Y] = 0;
        d[b + B_TORQUE] = 0;
      }
      const q = i * PARAM_STRIDE;
      params[q + INV_MASS] = invMass;
      params[q + INV_INERTIA] = invInertia;
      params[q + GRAVITY_SCALE] = d[b + B_GRAVITY_SCALE]!;
      params[q + DRAG] = d[b + B_DRAG]!;
      params[q + FORCE_X] = d[b + B_FORCE_X]!;
      params[q + FORCE_Y] = d[b + B_FORCE_Y]!;
      params[q + TORQUE] = d[b + B_TORQUE]!;
      params[q + LINEAR_DAMPING] = d[b + B_LINEAR_DAMPING]!;
      params[q + ANGULAR_DAMPING] = d[b + B_ANGULAR_DAMPING]!;
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
    joints.prepare(dt, subSteps, contactHertz, this.awakeCount, settings.maxLinearSpeed);
    const batches = this.batches;
    const batchable = joints.activeCount === 0 && batches.wants(contactCount);
    // Contacts are classified here and filled once their visiting order and numbering are
    // known (below); with batches, each batch fills its constraints just before its sub-steps,
    // while they stay in cache.
    let filled = false;
    const o = memory.offsets;
    constraints.count = kernel.classify(
      o[CONTACT_DATA]!,
      o[CONTACT_BODIES]!,
      o[BODY_TABLE]!,
      o[CONSTRAINT_BODIES]!,
      o[CONSTRAINT_SLOTS]!,
      o[CIRCLE_PAIRS]!,
      contactCount,
    );
    constraints.circlePairCount = kernel.circlePairCount.value;
    constraints.heavyOnLightCount = kernel.heavyOnLightCount.value;
    scrambleOrder(constraints.order, constraints.count);
    // Pairs for the WebAssembly kernel's lanes, in both builds (the same order, the same bits).
    const pairing = this.pairing;
    pairing.pair(constraints.order, constraints.count, constraints.bodies, SCRAMBLE_RUN);
    this.storeInOrder();
    const shock = this.shock;
    // The heavy-on-light sweep reads the prepared constraints.
    if (!filled && constraints.heavyOnLightCount > 0) {
      this.fill(0, constraints.count, dt);
      filled = true;
    }
    shock.prepare(
      constraints,
      this.states.data,
      this.awakeCount,
      this.staticSoftness.biasRate,
      settings.gravityX,
      settings.gravityY,
      Math.max(settings.restitutionThreshold, MIN_IMPACT_SPEED, MIN_LOADED_IMPACT_SPEED),
      settings.maxLinearSpeed,
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
      // The batches visit island by island: constraint n is again the n-th visited.
      if (!filled) this.storeInOrder();
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

  /** Renumbers the classified, unfilled constraints in their visiting order (contact-pairing.ts). */
  private storeInOrder(): void {
    const c = this.constraints;
    this.pairing.storeInOrder(
      c.order,
      c.count,
      c.bodies,
      c.slots,
      c.circlePairs,
      c.circlePairCount,
    );
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
    const impactSpeed = Math.max(threshold, MIN_IMPACT_SPEED);
    this.loadSpeed = Math.max(impactSpeed, MIN_LOADED_IMPACT_SPEED);
    this.pushSpeed = maxPushSpeed;
    // The bodies' impact marks (body-state.ts), as a kernel pointer.
    const marksPointer = memory.offsets[STATES]! + 8 * this.states.marks;
    for (let step = 0; step < settings.subSteps; step++) {
      integrateVelocities(
        this.params,
        bodyList,
        bodyFrom,
        bodyTo,
        s,
        this.states.marks,
        settings,
        h,
      );
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
        impactSpeed,
        this.loadSpeed,
        marksPointer,
        1,
      );
      if (shock.count > 0) {
        shock.solve(
          constraints,
          s,
          this.states.marks,
          inverseH,
          shockBiasRate,
          maxPushSpeed,
          threshold,
          true,
        );
      }
      joints.solveChains(s, true);
      integratePositions(this.params, bodyList, bodyFrom, bodyTo, s, settings, h);
      joints.solveChains(s, false, true);
      refreshCirclePairs(constraints, s);
      joints.solve(s, false);
      const bounces = kernel.solve(
        memory.offsets[CONSTRAINT_DATA]!,
        memory.offsets[CONSTRAINT_BODIES]!,
        order,
        memory.offsets[STATES]!,
        count,
        inverseH,
        maxPushSpeed,
        threshold,
        impactSpeed,
        this.loadSpeed,
        marksPointer,
        0,
      );
      if (shock.count > 0) {
        shock.solve(
          constraints,
          s,
          this.states.marks,
          inverseH,
          shockBiasRate,
          maxPushSpeed,
          threshold,
          false,
        );
      }
      // Something bounced: the impact travels through the contacts and joints it presses
      // (the kernel's impacts, wasm/contact-kernel.ts).
      if (bounces > 0) this.impactRounds(from, to, impactSpeed);
      joints.solveChains(s, false);
      // The relax pass can ask more of a light body than the limits allow (a torqued hinge chain
      // of 1,000:1 against the floor grew 1e2 -> 1e226 m/s in one pass): held to them here, as
      // the position half does, so no step ends with a velocity no later step could move.
      limitSpeeds(this.params, bodyList, bodyFrom, bodyTo, s, settings, h);
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
   * The impact rounds after a relax pass that bounced (the kernel's impacts), for the constraints
   * at positions `from` to `to` of the visiting order: round after round until no touching contact
   * approaches faster than `impactSpeed` (at most MAX_IMPACT_ROUNDS); a lone bounce of the relax
   * pass first solved again together with the joints, when there are any.
   */
  private impactRounds(from: number, to: number, impactSpeed: number): void {
    // The relax pass's bounce was computed with free bodies: with joints, it is solved again
    // together with them. Only a lone bounce: two impacts of one chain solved together towards
    // fixed targets would make energy (a cradle's balls would all fly apart).
    if (this.joints.activeCount > 0 && this.impacts(from, to, impactSpeed, IMPACT_OPEN) === 1) {
      this.impactsWithJoints(this.joints, from, to, impactSpeed);
    }
    let rounds = 0;
    while (this.impacts(from, to, impactSpeed, IMPACT_ROUND) > 0) {
      if (++rounds === MAX_IMPACT_ROUNDS) break;
    }
    // Closes the last round and clears the marks: the next sub-step starts without impacts.
    this.impacts(from, to, impactSpeed, IMPACT_CLOSE);
  }

  /** Gauss-Seidel iterations of the open impacts and the joints (relax: no position bias). */
  private impactsWithJoints(
    joints: JointSolver,
    from: number,
    to: number,
    impactSpeed: number,
  ): void {
    const s = this.states.data;
    for (let k = 0; k < JOINT_IMPACT_ITERATIONS; k++) {
      joints.solve(s, false);
      this.impacts(from, to, impactSpeed, IMPACT_CONTINUE);
    }
  }

  /** One pass of the kernel's impact rounds (impacts, wasm/contact-kernel.ts) in `mode`. */
  private impacts(from: number, to: number, impactSpeed: number, mode: number): number {
    const memory = this.memory;
    return memory.kernel.impacts(
      memory.offsets[CONSTRAINT_DATA]!,
      memory.offsets[CONSTRAINT_BODIES]!,
      memory.offsets[CONSTRAINT_ORDER]! + 4 * from,
      memory.offsets[STATES]!,
      to - from,
      impactSpeed,
      this.loadSpeed,
      this.pushSpeed,
      memory.offsets[STATES]! + 8 * this.states.marks,
      mode,
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
    // The bodies' own numbers (body-memory.ts), written in place at each body's world index.
    const d = this.memory.bodyStore.data;
    for (let i = 0; i < this.awakeCount; i++) {
      const body = awake[i]!;
      const b = body.base;
      const k = (i + 1) * STATE_STRIDE;
      const vx = s[k + V_X]!;
      const vy = s[k + V_Y]!;
      const w = s[k + W]!;
      const dpx = s[k + DP_X]!;
      const dpy = s[k + DP_Y]!;
      d[b + B_VX] = vx;
      d[b + B_VY] = vy;
      d[b + B_W] = w;
      const centerX = d[b + B_CENTER_X]! + dpx;
      const centerY = d[b + B_CENTER_Y]! + dpy;
      d[b + B_CENTER_X] = centerX;
      d[b + B_CENTER_Y] = centerY;
      const angle = d[b + B_ANGLE]! + s[k + DELTA_ANGLE]!;
      d[b + B_ANGLE] = angle;
      // The angle is the exact sum of h w; the transform follows it, so rotation never drifts
      // from the integrated angle.
      body.transform.setFromCenter(
        centerX,
        centerY,
        angle,
        d[b + B_LOCAL_CENTER_X]!,
        d[b + B_LOCAL_CENTER_Y]!,
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
      if ((d[b + B_FLAGS]! & FLAG_ALLOW_SLEEP) === 0 || body.forceList.length > 0) {
        d[b + B_SLEEP_TIME] = 0;
        continue;
      }
      const extent = d[b + B_MAX_EXTENT]!;
      const speed = Math.sqrt(vx * vx + vy * vy) + extent * Math.abs(w);
      const moved = Math.sqrt(dpx * dpx + dpy * dpy) + extent * Math.abs(s[k + DELTA_ANGLE]!);
      const sleepSpeed = Math.max(speed, (0.5 * moved) / dt);
      if (sleepSpeed > SLEEP_SPEED) d[b + B_SLEEP_TIME] = 0;
      else d[b + B_SLEEP_TIME] += dt;
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

/**
 * Slowest approach (m/s) an impact round counts as an impact, with a restitution threshold below
 * it: slower approaches are left to the next sub-step's contact solve, so the rounds end.
 */
const MIN_IMPACT_SPEED = 0.01;
/**
 * Slowest approach (m/s) of a loaded contact (pushing, not a bounce of this sub-step) that the
 * impact rounds and the relax pass count as an impact that reached it: a pile jostles its bouncy
 * particles slower, and bouncing them would let the load through (12 rows of e = 0.3 particles
 * went through the floor at 0.05 m/s and held at 0.5-2 m/s, test/fidelity/bouncy-piles.test.ts).
 */
const MIN_LOADED_IMPACT_SPEED = 1;
/** Most impact rounds after one relax pass (a light body between a floor and a 60 times heavier
 * one bounces about pi sqrt(60), 25 times). */
const MAX_IMPACT_ROUNDS = 64;
/** Gauss-Seidel iterations of a round's impacts with the joints. */
const JOINT_IMPACT_ITERATIONS = 8;

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
 * awake bodies list[from .. to), or from .. to themselves when `list` is null. Each body's
 * velocity change goes after its impact mark (from `marks` in `s`, body-state.ts).
 */
function integrateVelocities(
  params: Float64Array,
  list: Int32Array | null,
  from: number,
  to: number,
  s: Float64Array,
  marks: number,
  settings: SolverSettings,
  h: number,
): void {
  const gx = settings.gravityX;
  const gy = settings.gravityY;
  setSpeedLimits(settings, h);
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
    const vx0 = s[k + V_X]!;
    const vy0 = s[k + V_Y]!;
    const w0 = s[k + W]!;
    s[k + V_X] = vx;
    s[k + V_Y] = vy;
    s[k + W] = w;
    limitSpeed(s, k);
    // The velocity change of this integration, for a bounce later in the sub-step (body-state.ts).
    const m = marks + (i + 1) * MARK_STRIDE;
    s[m + KICK_VX] = s[k + V_X]! - vx0;
    s[m + KICK_VY] = s[k + V_Y]! - vy0;
    s[m + KICK_W] = s[k + W]! - w0;
  }
}

/** maxLinearSpeed and the quarter turn per sub-step (rad/s), for limitSpeed (see below). */
const SPEED_LIMITS = new Float64Array(2);

/**
 * At most a quarter turn per sub-step (Box2D v3's B2_MAX_ROTATION): faster, the first-order
 * rotation of the contact and joint anchors is meaningless, and a joint pulling a tiny body by a
 * long lever could spin it up without bound until it became NaN.
 */
function setSpeedLimits(settings: SolverSettings, h: number): void {
  SPEED_LIMITS[0] = settings.maxLinearSpeed;
  SPEED_LIMITS[1] = (0.25 * Math.PI) / h;
}

/**
 * Holds the velocity of the body at state offset k to the limits setSpeedLimits wrote (read from
 * a typed array: a fractional argument would be boxed). A velocity with a component that
 * overflowed to infinity or became NaN has no direction left to keep: it is dropped (set to zero),
 * so a solve that failed for one sub-step stops the body instead of making its pose NaN.
 */
function limitSpeed(s: Float64Array, k: number): void {
  const maxAngularSpeed = SPEED_LIMITS[1]!;
  const w = s[k + W]!;
  if (w > maxAngularSpeed) s[k + W] = maxAngularSpeed;
  else if (w < -maxAngularSpeed) s[k + W] = -maxAngularSpeed;
  else if (w !== w) s[k + W] = 0;
  const maxSpeed = SPEED_LIMITS[0]!;
  const vx = s[k + V_X]!;
  const vy = s[k + V_Y]!;
  const speedSquared = vx * vx + vy * vy;
  if (speedSquared <= maxSpeed * maxSpeed) return;
  if (speedSquared < Infinity) {
    const ratio = maxSpeed / Math.sqrt(speedSquared);
    s[k + V_X] = vx * ratio;
    s[k + V_Y] = vy * ratio;
    return;
  }
  // The square overflowed (or is NaN): scale by the larger component first.
  const big = Math.max(Math.abs(vx), Math.abs(vy));
  if (big < Infinity) {
    const ux = vx / big;
    const uy = vy / big;
    const ratio = maxSpeed / Math.sqrt(ux * ux + uy * uy);
    s[k + V_X] = ux * ratio;
    s[k + V_Y] = uy * ratio;
  } else {
    s[k + V_X] = 0;
    s[k + V_Y] = 0;
  }
}

/** Holds every awake dynamic body's velocity to the limits (see limitSpeed). */
function limitSpeeds(
  params: Float64Array,
  list: Int32Array | null,
  from: number,
  to: number,
  s: Float64Array,
  settings: SolverSettings,
  h: number,
): void {
  setSpeedLimits(settings, h);
  for (let n = from; n < to; n++) {
    const i = list === null ? n : list[n]!;
    if (params[i * PARAM_STRIDE + INV_MASS]! !== 0) limitSpeed(s, (i + 1) * STATE_STRIDE);
  }
}

/**
 * Semi-implicit Euler, position half: x += h v with the velocity just solved; for the awake
 * bodies list[from .. to), or from .. to themselves when `list` is null.
 *
 * A dynamic body's solved velocity is held to the same limits as in integrateVelocities
 * (maxLinearSpeed, a quarter turn per sub-step). The solve can exceed them: a joint that cannot
 * hold a tiny body against a large torque (a constant 2 N m on a 0.01 kg box on a prismatic
 * joint) let each sub-step's impulses grow the last's, until the velocities overflowed and the
 * whole world went NaN. Bounded, every pose moves at most maxLinearSpeed h and a quarter turn per
 * sub-step, so no error a constraint sees can grow without bound (see limitSpeed for a velocity
 * that is no longer finite).
 */
function integratePositions(
  params: Float64Array,
  list: Int32Array | null,
  from: number,
  to: number,
  s: Float64Array,
  settings: SolverSettings,
  h: number,
): void {
  setSpeedLimits(settings, h);
  for (let n = from; n < to; n++) {
    const i = list === null ? n : list[n]!;
    const k = (i + 1) * STATE_STRIDE;
    // Kinematic bodies keep the velocity they were given.
    if (params[i * PARAM_STRIDE + INV_MASS]! !== 0) limitSpeed(s, k);
    const w = s[k + W]!;
    const vx = s[k + V_X]!;
    const vy = s[k + V_Y]!;
    s[k + DP_X] += h * vx;
    s[k + DP_Y] += h * vy;
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
