import { releaseFrom } from '../core/release.ts';
import type { Body } from './body.ts';
import type { BodyBounds } from './body-bounds.ts';
import {
  BODY_STRIDE,
  B_ANGLE,
  B_ANGLE0,
  B_AWAKE,
  B_CENTER0_X,
  B_CENTER0_Y,
  B_CENTER_X,
  B_CENTER_Y,
  B_FORCES_LEFT,
  B_FORCE_X,
  B_FORCE_Y,
  B_INV_INERTIA,
  B_INV_MASS,
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
import { CONSTRAINT_STRIDE, ContactConstraints, ShockPropagation } from './contact-solver.ts';
import {
  IMPACT_CLOSE,
  IMPACT_CONTINUE,
  IMPACT_COUNT,
  IMPACT_OPEN,
  IMPACT_ROUND,
} from './contact-constraint-layout.ts';
import { JointSolver } from './joints/joint-solver.ts';
import {
  AWAKE_BODIES,
  BATCH_BODIES,
  BODIES,
  BODY_TABLE,
  CIRCLE_PAIRS,
  CONSTRAINT_BODIES,
  CONSTRAINT_DATA,
  CONSTRAINT_ORDER,
  CONSTRAINT_SLOTS,
  CONTACT_BODIES,
  CONTACT_DATA,
  ESCAPED_SHAPES,
  FAST_BODIES,
  SHAPE_BOXES,
  SHAPE_GEOMETRY,
  KERNEL_ARGUMENTS,
  SHAPE_NEXT,
  SolverMemory,
  STATES,
} from './solver-memory.ts';
import {
  A_BOUNDS_DT,
  A_CONTACT_BIAS_RATE,
  A_CONTACT_HERTZ,
  A_CONTACT_IMPULSE_SCALE,
  A_CONTACT_MASS_SCALE,
  A_CONTACT_ZETA,
  A_DT,
  A_GRAVITY_X,
  A_GRAVITY_Y,
  A_H,
  A_IMPACT_SPEED,
  A_INVERSE_H,
  A_LOAD_SPEED,
  A_MAX_ANGULAR_SPEED,
  A_MAX_PUSH_SPEED,
  A_MAX_SPEED,
  A_RESTITUTION_THRESHOLD,
  A_SHOCK_BIAS_RATE,
  A_SHOCK_MAX_APPROACH,
  A_SHOCK_REST_SPEED,
  A_STATIC_BIAS_RATE,
  A_STATIC_IMPULSE_SCALE,
  A_STATIC_MASS_SCALE,
} from './kernel-arguments.ts';
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
  readonly constraints: ContactConstraints = new ContactConstraints(this.memory);
  /** The joints, solved before the contacts in each pass (as Box2D v3 orders them). */
  readonly joints: JointSolver = new JointSolver(this.memory);
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
    this.memory.shrink(bodies, contacts);
  }

  /**
   * Makes room, as bodies and shapes join, for `bodies` bodies, `shapes` shapes and a step of
   * `contacts` contacts (the contact manager's foreseenContacts), its pages touched, so that the
   * world's first step neither moves the solver memory nor faults its pages in
   * (SolverMemory.reserveForeseen).
   */
  reserveForeseen(bodies: number, shapes: number, contacts: number): void {
    this.memory.reserveForeseen(stateDoubles(bodies), bodies, shapes, contacts);
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
    // The body passes (the kernel's, wasm/body-passes.ts) read awake body i's numbers in place,
    // at the world index listed here.
    const awakeBodies = this.memory.awakeBodies;
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
      awakeBodies[i] = n;
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
      // Spent forces are dropped above: what is left still acts, and keeps the body awake.
      d[b + B_FORCES_LEFT] = body.forceList.length > 0 ? 1 : 0;
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
    // The heavy-on-light sweep's scratch (ShockPropagation.prepare).
    this.memory.reserveShockScratch(2 * (this.awakeCount + 1) + 5 * contactCount);
    const memory = this.memory;
    const subSteps = settings.subSteps;
    const h = dt / subSteps;

    // A contact spring stiffer than a quarter of the sub-step rate would be under-resolved.
    const contactHertz = Math.min(settings.contactHertz, (0.25 * subSteps) / dt);
    this.contactSoftness.set(contactHertz, settings.contactDampingRatio, h);
    this.staticSoftness.set(2 * contactHertz, settings.contactDampingRatio, h);
    // Joints first (they do not depend on the contacts): whether the step may run in batches of
    // islands decides how the contacts are prepared. They may grow the memory: the kernel after.
    const joints = this.joints;
    joints.prepare(dt, subSteps, this.contactSoftness, this.awakeCount, settings);
    // The kernel's fractional arguments for the whole step, stored once the memory has stopped
    // moving (the joints' prepare may grow it): V8 can box each double passed to WebAssembly
    // (kernel-arguments.ts), 16 bytes per argument per call.
    this.storeArguments(settings, dt, h);
    const kernel = memory.kernel;
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
      this.fill(0, constraints.count);
      filled = true;
    }
    // Its bias rate, gravity and rest speed are in the kernel's arguments (storeArguments).
    shock.prepare(constraints, this.awakeCount);

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
      // The batches' bodies, where the kernel's body passes read them (a loop: subarray would
      // allocate a view each step).
      const batchBodies = this.memory.batchBodies;
      const from = batches.bodies;
      for (let i = 0; i < this.awakeCount; i++) batchBodies[i] = from[i]!;
      for (let k = 0; k < batches.count; k++) {
        if (!filled) this.fill(orderStart[k]!, orderStart[k + 1]!);
        this.subSteps(
          settings,
          orderStart[k]!,
          orderStart[k + 1]!,
          true,
          bodyStart[k]!,
          bodyStart[k + 1]!,
        );
      }
    } else {
      if (!filled) this.fill(0, constraints.count);
      this.subSteps(settings, 0, constraints.count, false, 0, this.awakeCount);
    }
    joints.finish();
  }

  /**
   * Stores the step's fractional numbers where the kernel's passes read them (KERNEL_ARGUMENTS,
   * kernel-arguments.ts): the step `dt`, the sub-step `h`, gravity, the speed limits, the contacts'
   * softness and the impact rounds' speeds, the heavy-on-light sweep's bias rate and rest speed.
   */
  private storeArguments(settings: SolverSettings, dt: number, h: number): void {
    const args = this.memory.kernelArguments;
    const soft = this.contactSoftness;
    const hard = this.staticSoftness;
    const threshold = settings.restitutionThreshold;
    const impactSpeed = Math.max(threshold, MIN_IMPACT_SPEED);
    args[A_DT] = dt;
    args[A_H] = h;
    args[A_INVERSE_H] = 1 / h;
    args[A_GRAVITY_X] = settings.gravityX;
    args[A_GRAVITY_Y] = settings.gravityY;
    // maxLinearSpeed, and at most a quarter turn per sub-step (Box2D v3's B2_MAX_ROTATION).
    args[A_MAX_SPEED] = settings.maxLinearSpeed;
    args[A_MAX_ANGULAR_SPEED] = (0.25 * Math.PI) / h;
    // The most a push-out moves a contact: a pressed point approaching faster is an impact.
    args[A_MAX_PUSH_SPEED] = settings.maxContactPushSpeed;
    args[A_RESTITUTION_THRESHOLD] = threshold;
    args[A_IMPACT_SPEED] = impactSpeed;
    // The slowest approach of a loaded contact the impact rounds count as an impact.
    args[A_LOAD_SPEED] = Math.max(impactSpeed, MIN_LOADED_IMPACT_SPEED);
    args[A_CONTACT_BIAS_RATE] = soft.biasRate;
    args[A_CONTACT_MASS_SCALE] = soft.massScale;
    args[A_CONTACT_IMPULSE_SCALE] = soft.impulseScale;
    args[A_STATIC_BIAS_RATE] = hard.biasRate;
    args[A_STATIC_MASS_SCALE] = hard.massScale;
    args[A_STATIC_IMPULSE_SCALE] = hard.impulseScale;
    args[A_CONTACT_HERTZ] = soft.hertz;
    args[A_CONTACT_ZETA] = soft.zeta;
    args[A_SHOCK_BIAS_RATE] = hard.biasRate;
    args[A_SHOCK_REST_SPEED] = Math.max(threshold, MIN_IMPACT_SPEED, MIN_LOADED_IMPACT_SPEED);
    // The fastest approach a swept bounce reverses: two bodies each at maxLinearSpeed.
    args[A_SHOCK_MAX_APPROACH] = 2 * settings.maxLinearSpeed;
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
  private fill(from: number, to: number): void {
    const o = this.memory.offsets;
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
      o[KERNEL_ARGUMENTS]!,
    );
  }

  /**
   * The sub-steps of a step, for the constraints at positions `from` to `to` of the visiting
   * order and the awake bodies listed at `bodyFrom .. bodyTo` of the batches' bodies (with
   * `batch` false, the awake indices bodyFrom .. bodyTo themselves): the whole step, or one batch
   * of islands. Then stores those constraints' impulses in their contacts' slots.
   */
  private subSteps(
    settings: SolverSettings,
    from: number,
    to: number,
    batch: boolean,
    bodyFrom: number,
    bodyTo: number,
  ): void {
    const constraints = this.constraints;
    const memory = this.memory;
    const kernel = memory.kernel;
    const s = this.states.data;
    const joints = this.joints;
    const shock = this.shock;
    const circlePairCount = constraints.circlePairCount;
    const count = to - from;
    // The bodies' impact marks (body-state.ts), as a kernel pointer.
    const marksPointer = memory.offsets[STATES]! + 8 * this.states.marks;
    // The body passes' pointers (wasm/body-passes.ts); the sub-step, gravity, the limits and the
    // contacts' speeds are in the kernel's arguments (storeArguments).
    const bodies = memory.offsets[BODIES]!;
    const awake = memory.offsets[AWAKE_BODIES]!;
    const list = memory.offsets[BATCH_BODIES]!;
    const useList = batch ? 1 : 0;
    const states = memory.offsets[STATES]!;
    const args = memory.offsets[KERNEL_ARGUMENTS]!;
    for (let step = 0; step < settings.subSteps; step++) {
      kernel.integrateVelocities(
        bodies,
        awake,
        list,
        useList,
        bodyFrom,
        bodyTo,
        states,
        marksPointer,
        args,
      );
      if (circlePairCount > 0) this.refreshCirclePairs();
      joints.warmStart();
      // Offsets in bytes: the order holds 4-byte indices.
      const order = memory.offsets[CONSTRAINT_ORDER]! + 4 * from;
      kernel.warmStart(
        memory.offsets[CONSTRAINT_DATA]!,
        memory.offsets[CONSTRAINT_BODIES]!,
        order,
        memory.offsets[STATES]!,
        count,
      );
      joints.solve(true);
      kernel.solve(
        memory.offsets[CONSTRAINT_DATA]!,
        memory.offsets[CONSTRAINT_BODIES]!,
        order,
        memory.offsets[STATES]!,
        count,
        args,
        marksPointer,
        1,
      );
      if (shock.count > 0) shock.solve(constraints, marksPointer, 1);
      joints.solveChains(s, true);
      kernel.integratePositions(bodies, awake, list, useList, bodyFrom, bodyTo, states, args);
      joints.solveChains(s, false, true);
      if (circlePairCount > 0) this.refreshCirclePairs();
      joints.solve(false);
      const bounces = kernel.solve(
        memory.offsets[CONSTRAINT_DATA]!,
        memory.offsets[CONSTRAINT_BODIES]!,
        order,
        memory.offsets[STATES]!,
        count,
        args,
        marksPointer,
        0,
      );
      if (shock.count > 0) shock.solve(constraints, marksPointer, 0);
      // Something bounced: the impact travels through the contacts and joints it presses
      // (the kernel's impacts, wasm/contact-kernel.ts).
      if (bounces > 0) this.impactRounds(from, to);
      joints.solveChains(s, false);
      // The relax pass can ask more of a light body than the limits allow (a torqued hinge chain
      // of 1,000:1 against the floor grew 1e2 -> 1e226 m/s in one pass): held to them here, as
      // the position half does, so no step ends with a velocity no later step could move.
      kernel.limitSpeeds(bodies, awake, list, useList, bodyFrom, bodyTo, states, args);
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

  /** The circle pairs' normals along their centres as they are now (the kernel's, wasm/circle-pairs.ts). */
  private refreshCirclePairs(): void {
    const o = this.memory.offsets;
    this.memory.kernel.refreshCirclePairs(
      o[CONSTRAINT_DATA]!,
      o[CONSTRAINT_BODIES]!,
      o[CIRCLE_PAIRS]!,
      this.constraints.circlePairCount,
      o[STATES]!,
    );
  }

  /**
   * The impact rounds after a relax pass that bounced (the kernel's impacts), for the constraints
   * at positions `from` to `to` of the visiting order: round after round until no touching contact
   * approaches faster than the impact speed (A_IMPACT_SPEED, at most MAX_IMPACT_ROUNDS); a lone bounce of the relax
   * pass first solved again together with the joints, when there are any.
   */
  private impactRounds(from: number, to: number): void {
    // The relax pass's bounce was computed with free bodies: with joints, it is solved again
    // together with them. Only a lone bounce: two impacts of one chain solved together towards
    // fixed targets would make energy (a cradle's balls would all fly apart).
    // Counted first, then opened: opening every bounce to count them left several bounces open,
    // so the rounds passed them over (closed without their round) in any world with an active
    // joint, and a particle under a pile, bouncing with others, went through the floor.
    if (
      this.joints.activeCount > 0 &&
      this.impacts(from, to, IMPACT_COUNT) === 1 &&
      this.impacts(from, to, IMPACT_OPEN) === 1
    ) {
      this.impactsWithJoints(this.joints, from, to);
    }
    let rounds = 0;
    while (this.impacts(from, to, IMPACT_ROUND) > 0) {
      if (++rounds === MAX_IMPACT_ROUNDS) break;
    }
    // Closes the last round and clears the marks: the next sub-step starts without impacts.
    this.impacts(from, to, IMPACT_CLOSE);
  }

  /** Gauss-Seidel iterations of the open impacts and the joints (relax: no position bias). */
  private impactsWithJoints(joints: JointSolver, from: number, to: number): void {
    for (let k = 0; k < JOINT_IMPACT_ITERATIONS; k++) {
      joints.solve(false);
      this.impacts(from, to, IMPACT_CONTINUE);
    }
  }

  /**
   * One pass of the kernel's impact rounds (impacts, wasm/contact-kernel.ts) in `mode`; its speeds
   * are in the kernel's arguments (storeArguments).
   */
  private impacts(from: number, to: number, mode: number): number {
    const memory = this.memory;
    return memory.kernel.impacts(
      memory.offsets[CONSTRAINT_DATA]!,
      memory.offsets[CONSTRAINT_BODIES]!,
      memory.offsets[CONSTRAINT_ORDER]! + 4 * from,
      memory.offsets[STATES]!,
      to - from,
      memory.offsets[KERNEL_ARGUMENTS]!,
      memory.offsets[STATES]! + 8 * this.states.marks,
      mode,
    );
  }

  /**
   * Writes velocities and poses back to the bodies, updates their sleep timers and moves their
   * shapes' broad-phase boxes (`bounds`, predicting a next step of its `dt`). With `continuous`,
   * dynamic bodies that moved far enough to need a sweep test are listed in `fastBodies` and
   * `fastBullets` instead, their boxes left to the sweep.
   */
  finalizeBodies(dt: number, bounds: BodyBounds, continuous: boolean): void {
    const awake = this.awake;
    const fastBodies = this.fastBodies;
    const fastBullets = this.fastBullets;
    const memory = this.memory;
    // Through the memory, not as arguments: V8 can box each double passed to WebAssembly.
    const args = memory.kernelArguments;
    args[A_DT] = dt;
    args[A_BOUNDS_DT] = bounds.dt;
    // Velocities, centres, angles, transforms and sleep clocks, in the body memory, and the fast
    // bodies' awake indices (the kernel's finalizeBodies, wasm/body-passes.ts).
    const fast = memory.kernel.finalizeBodies(
      memory.offsets[BODIES]!,
      memory.offsets[AWAKE_BODIES]!,
      this.awakeCount,
      memory.offsets[STATES]!,
      memory.offsets[KERNEL_ARGUMENTS]!,
      memory.offsets[FAST_BODIES]!,
      continuous ? 1 : 0,
    );
    // The other bodies' shapes' boxes (the kernel's shapeBounds, wasm/shape-bounds.ts), then the
    // proxies of those that left their fat boxes moved in the trees, in awake order.
    const escaped = memory.kernel.shapeBounds(
      memory.offsets[BODIES]!,
      memory.offsets[AWAKE_BODIES]!,
      this.awakeCount,
      memory.offsets[FAST_BODIES]!,
      fast,
      memory.offsets[SHAPE_BOXES]!,
      memory.offsets[SHAPE_GEOMETRY]!,
      memory.offsets[SHAPE_NEXT]!,
      memory.offsets[KERNEL_ARGUMENTS]!,
      memory.offsets[ESCAPED_SHAPES]!,
    );
    bounds.moveEscaped(memory.escapedShapes, escaped);
    // Then what needs the body objects: the fast bodies' lists, in awake order (the fast list is
    // in that order too).
    const fastList = memory.fastBodies;
    let fastCount = 0;
    let fastBulletCount = 0;
    let next = fast > 0 ? fastList[0]! : -1;
    for (let i = 0; i < this.awakeCount; i++) {
      const body = awake[i]!;
      if (i !== next) continue;
      const listed = fastCount + fastBulletCount + 1;
      next = listed < fast ? fastList[listed]! : -1;
      if (body.bulletValue) {
        if (fastBulletCount < fastBullets.length) fastBullets[fastBulletCount] = body;
        else fastBullets.push(body);
        fastBulletCount++;
      } else {
        if (fastCount < fastBodies.length) fastBodies[fastCount] = body;
        else fastBodies.push(body);
        fastCount++;
      }
    }
    this.fastCount = fastCount;
    this.fastBulletCount = fastBulletCount;
  }
}

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
