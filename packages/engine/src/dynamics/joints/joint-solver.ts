import { releaseFrom } from '../../core/release.ts';
import { Softness } from '../softness.ts';
import type { SolverMemory } from '../solver-memory.ts';
import type { Joint, JointStep, JointType } from './joint.ts';
import type { JointBatch } from './joint-batch.ts';
import { PASS_RELAX, PASS_SOLVE, PASS_WARM_START } from './joint-pass-codes.ts';
import { STATE_A, STATE_B } from './joint-record.ts';
import type { PinChains } from './pin-chains.ts';

/**
 * Box2D v3's rigid-joint softness: twice the contact stiffness, damping ratio 2 (stiff and well
 * damped, so a chain does not ring), for the position error of rigid joints and limits. Springs
 * use their own frequency and damping ratio.
 */
const JOINT_DAMPING_RATIO = 2;

/**
 * Runs the joints of one step through the soft step's stages (see Solver.solve): prepare once,
 * then each sub-step warm start, solve with bias (before the contacts), relax (with the contacts);
 * at the end the summed impulses become each joint's reaction force. Only joints with at least
 * one awake body take part; the rest sleep with their island.
 */
export class JointSolver {
  /** The world's solver memory: the joints' records and the step's active list are there. */
  constructor(private readonly memory: SolverMemory) {}

  /** The world's joints (the world's own list, shared). */
  list: readonly Joint[] = [];
  /** Joints solved this step (the first `count`). */
  private readonly active: Joint[] = [];
  private count = 0;
  /** Joints solved this step. */
  get activeCount(): number {
    return this.count;
  }
  private readonly step: JointStep = {
    h: 0,
    inverseH: 0,
    dt: 0,
    softness: new Softness(),
    maxBiasSpeed: 0,
  };
  /** The exact solve of hinge chains with unlike masses, once a hinge has been solved. */
  chains: PinChains | null = null;
  /** Each kind's batch, once a joint of it was solved; in `batches` in that order. */
  private readonly batchOf: Partial<Record<JointType, JointBatch>> = {};
  private readonly batches: JointBatch[] = [];

  /**
   * Picks the joints to solve and prepares them; `contact` the contacts' softness this step (its
   * hertz as the contacts use it), `bodyCount` the step's awake bodies, `limits` the world's
   * speed limit. Objects, not their numbers: V8 boxes a fractional argument of a call it does not
   * inline.
   */
  prepare(
    dt: number,
    subSteps: number,
    contact: Softness,
    bodyCount: number,
    limits: { readonly maxLinearSpeed: number },
  ): void {
    const step = this.step;
    step.dt = dt;
    step.h = dt / subSteps;
    step.inverseH = subSteps / dt;
    step.maxBiasSpeed = limits.maxLinearSpeed;
    step.softness.set(2 * contact.hertz, JOINT_DAMPING_RATIO, step.h);
    const list = this.list;
    const active = this.active;
    const batches = this.batches;
    const memory = this.memory;
    // Room first for every joint's record and the active list: growing moves the whole memory
    // (every view replaced), so it happens before anything of the step is read from it.
    memory.reserveJoints(list.length, list.length);
    const store = memory.jointStore;
    for (let i = 0; i < batches.length; i++) batches[i]!.active = 0;
    let count = 0;
    for (let i = 0; i < list.length; i++) {
      const joint = list[i]!;
      if (joint.bodyA.solverIndex === 0 && joint.bodyB.solverIndex === 0) continue;
      if (count < active.length) active[count] = joint;
      else active.push(joint);
      count++;
      let batch = this.batchOf[joint.type];
      if (batch === undefined) {
        batch = joint.createBatch();
        batch.load(memory);
        this.batchOf[joint.type] = batch;
        batches.push(batch);
      }
      batch.active++;
      // The joint's record moves into the world's store at its first step in this world (it
      // leaves with the joint: see Joint.worldRef).
      if (joint.store !== store) store.adopt(joint);
      joint.prepare(step);
      // Made by the first joint kind that needs it, however the joint came in (added or
      // restored from a snapshot); apps without such joints never load it.
      this.chains ??= joint.createChains();
    }
    this.count = count;
    this.chains?.prepare(active, count, bodyCount, step);
    // The active list, kind after kind in the order the kinds first came, each kind's joints in
    // the world's order; after the chains: they add their pins' geometric stiffness to the
    // joints' inertia, which the state offsets do not depend on but the passes read.
    let start = 0;
    for (let i = 0; i < batches.length; i++) {
      const batch = batches[i]!;
      batch.start = start;
      start += batch.active;
      batch.active = 0;
    }
    const d = store.data;
    const listed = memory.jointActive;
    for (let i = 0; i < count; i++) {
      const joint = active[i]!;
      const batch = this.batchOf[joint.type]!;
      const at = 3 * (batch.start + batch.active++);
      const o = joint.base;
      listed[at] = o;
      listed[at + 1] = d[o + STATE_A]!;
      listed[at + 2] = d[o + STATE_B]!;
    }
  }

  /** Drops the references to the last step's joints (see Solver.releaseReferences). */
  releaseReferences(): void {
    releaseFrom(this.active, 0);
    this.count = 0;
    for (let i = 0; i < this.batches.length; i++) this.batches[i]!.active = 0;
    this.chains?.release();
  }

  /** Kind after kind, in the order the kinds first came. */
  warmStart(): void {
    const batches = this.batches;
    for (let i = 0; i < batches.length; i++)
      batches[i]!.run(this.memory, this.step, PASS_WARM_START);
  }

  solve(useBias: boolean): void {
    const step = this.step;
    const batches = this.batches;
    const pass = useBias ? PASS_SOLVE : PASS_RELAX;
    for (let i = 0; i < batches.length; i++) batches[i]!.run(this.memory, step, pass);
  }

  /**
   * The exact chain solve (pin-chains.ts), when the world has one: after the solve pass
   * (`useBias`), after the relax pass, or (`project`) after the positions moved.
   */
  solveChains(s: Float64Array, useBias: boolean, project = false): void {
    this.chains?.run(s, useBias, project);
  }

  /** Turns the step's impulses into reaction forces. */
  finish(): void {
    const dt = this.step.dt;
    const batches = this.batches;
    for (let i = 0; i < batches.length; i++) batches[i]!.finish(this.memory, dt);
  }
}
