import { releaseFrom } from '../../core/release.ts';
import { DELTA_ANGLE, DP_X, DP_Y, Q_C, Q_S, STATE_STRIDE, V_X, V_Y, W } from '../body-state.ts';
import type { JointStep } from './joint.ts';

/** What the chain solve needs of a hinge (RevoluteJoint). */
export interface PinJoint {
  readonly stateA: number;
  readonly stateB: number;
  readonly invMassA: number;
  readonly invMassB: number;
  /**
   * Writes the inverse masses as the solver sees them, in the record's order: invMassA,
   * invInertiaA, invMassB, invInertiaB (the inertias set by the joint's prepare, then maybe
   * stiffened by the chain for the step: see PinChains.stiffen).
   */
  pinMasses(out: Float64Array): void;
  /** Writes back the inverse inertias at out[1] (A) and out[3] (B) (PinChains.stiffen). */
  setPinInertias(values: Float64Array): void;
  /** Writes the levers from the centres to the pin, rotated to now: rAx, rAy, rBx, rBy. */
  pinLevers(s: Float64Array, out: Float64Array, offset: number): void;
  /**
   * Writes the pin's position error (B's pin minus A's, m) with `positions`; otherwise its
   * velocity error plus biasRate[0] times that position error (2 numbers).
   */
  pinError(
    s: Float64Array,
    biasRate: Float64Array,
    positions: boolean,
    out: Float64Array,
    offset: number,
  ): void;
  /**
   * Adds the impulse in `t` (x at offset + 15, y at offset + 5; on B, its opposite on A) to the
   * accumulated one; `relax`: to the step's sum too.
   */
  addPinImpulse(t: Float64Array, offset: number, relax: boolean): void;
  /** Writes |P . rA| and |P . rB| (P the pin's accumulated impulse, levers at the step's start). */
  pinLoad(out: Float64Array, offset: number): void;
}

// Chains of hinges solved exactly (block tridiagonal elimination; Baraff, "Linear-time dynamics
// using Lagrange multipliers", SIGGRAPH 1996, for the idea of solving an acyclic joint graph
// directly).
//
// Why: sequential impulses move a heavy body on light links by m_light / m_heavy of what each
// hinge asks per pass, so a 1000 kg bob on four 1 kg links stretches its chain by a metre and
// more. The hinges' pins along a chain couple only neighbours (through the body they share), so
// the pins' equations form a block tridiagonal system with 2x2 blocks, solved exactly in O(n).
// After each solve and relax pass, the pins' remaining velocity error (and, in the solve pass,
// part of their position error) is removed by that exact solve, with the true masses on both
// sides: momentum is kept, no energy is made, and the impulses join each hinge's accumulated
// ones, so reaction forces are the weights the chain carries. Only chains with a mass ratio over
// five take part (see UNLIKE): elsewhere the sequential passes converge well enough.

/** Hinge chains with unlike masses, and their exact pin solve. */
export class PinChains {
  /** Joints of every chain, chain after chain; `chainEnd[c]` is one past chain c's last. */
  private readonly joints: PinJoint[] = [];
  private readonly chainEnd: number[] = [];
  private chainCount = 0;
  /** Per joint of `joints`: the state offset of the body shared with the next joint (0: none). */
  private shared: Int32Array = new Int32Array(16);
  // Per joint scratch: levers (rAx, rAy, rBx, rBy), error, D^-1 (3 numbers, symmetric), y, B.
  private scratch: Float64Array = new Float64Array(16 * 16);
  // Chain search: the hinges, and per solver slot its hinge count and first two hinges.
  private readonly pins: PinJoint[] = [];
  private degree: Int32Array = new Int32Array(64);
  private hinge1: Int32Array = new Int32Array(64);
  private hinge2: Int32Array = new Int32Array(64);
  private used: Uint8Array = new Uint8Array(16);
  /** Farthest a body moves in one projection (m): maxLinearSpeed h, set by prepare. */
  private maxMove = -0;
  /**
   * The step's joint softness bias rate (set by prepare): a field, not run's argument, since V8
   * boxes a fractional argument of a call it does not inline, and run is called three times a
   * sub-step.
   */
  private biasRate = -0;

  /** Forgets the last step's joints (see Solver.releaseReferences). */
  release(): void {
    this.chainCount = 0;
    releaseFrom(this.joints, 0);
    releaseFrom(this.pins, 0);
  }

  /**
   * Finds the chains among `joints` (prepared this step); `bodyCount`: awake bodies; `step`: the
   * step's numbers (its sub-step, its bias rate, and its maxBiasSpeed, the world's speed limit,
   * which also bounds the projection: see run).
   */
  prepare(
    joints: readonly { pinJoint(): PinJoint | null }[],
    count: number,
    bodyCount: number,
    step: JointStep,
  ): void {
    this.chainCount = 0;
    this.maxMove = step.maxBiasSpeed * step.h;
    this.biasRate = step.softness.biasRate;
    const pins = this.pins;
    let pinCount = 0;
    let unlike = false;
    for (let i = 0; i < count; i++) {
      const joint = joints[i]!.pinJoint();
      if (joint === null) continue;
      if (pinCount < pins.length) pins[pinCount] = joint;
      else pins.push(joint);
      pinCount++;
      if (isUnlike(joint)) unlike = true;
    }
    if (!unlike) return;
    if (this.degree.length <= bodyCount) {
      this.degree = new Int32Array(2 * bodyCount + 2);
      this.hinge1 = new Int32Array(2 * bodyCount + 2);
      this.hinge2 = new Int32Array(2 * bodyCount + 2);
    }
    if (this.used.length < pinCount) this.used = new Uint8Array(2 * pinCount);
    const degree = this.degree;
    degree.fill(0, 0, bodyCount + 1);
    this.used.fill(0, 0, pinCount);
    for (let n = 0; n < pinCount; n++) {
      for (let side = 0; side < 2; side++) {
        const k = slotOf(pins[n]!, side);
        if (k === 0) continue;
        if (degree[k] === 0) this.hinge1[k] = n;
        else if (degree[k] === 1) this.hinge2[k] = n;
        degree[k]!++;
      }
    }
    let total = 0;
    for (let start = 0; start < pinCount; start++) {
      if (this.used[start] === 1) continue;
      // Walk to one end of start's chain: through bodies with exactly two hinges.
      let n = start;
      let from = slotOf(pins[n]!, 0) !== 0 ? slotOf(pins[n]!, 0) : slotOf(pins[n]!, 1);
      for (let guard = 0; guard < pinCount && degree[from] === 2; guard++) {
        const next = this.hinge1[from] === n ? this.hinge2[from]! : this.hinge1[from]!;
        if (next === start) break; // a loop: not a chain
        n = next;
        from = otherSlot(pins[n]!, from);
        if (from === 0) break;
      }
      // n is an end hinge and `from` its outer body: collect toward the other end.
      const first = total;
      let at = otherSlot(pins[n]!, from);
      let mass = false;
      for (;;) {
        this.used[n] = 1;
        const joint = pins[n]!;
        if (total < this.joints.length) this.joints[total] = joint;
        else this.joints.push(joint);
        total++;
        if (isUnlike(joint)) mass = true;
        if (at === 0 || degree[at] !== 2) break;
        const next = this.hinge1[at] === n ? this.hinge2[at]! : this.hinge1[at]!;
        if (this.used[next] === 1) break;
        n = next;
        at = otherSlot(pins[n]!, at);
      }
      if (!mass || total - first < 2) {
        total = first;
        continue;
      }
      if (this.chainCount < this.chainEnd.length) this.chainEnd[this.chainCount] = total;
      else this.chainEnd.push(total);
      this.chainCount++;
    }
    if (this.shared.length < total) this.shared = new Int32Array(2 * total);
    if (this.scratch.length < 16 * (total + 1)) this.scratch = new Float64Array(32 * (total + 1));
    let begin = 0;
    for (let c = 0; c < this.chainCount; c++) {
      const end = this.chainEnd[c]!;
      for (let k = begin; k < end; k++) {
        let shared = 0;
        if (k + 1 < end) {
          const a = this.joints[k]!;
          const b = this.joints[k + 1]!;
          const sa = slotOf(a, 0);
          shared = sa !== 0 && (sa === slotOf(b, 0) || sa === slotOf(b, 1)) ? a.stateA : a.stateB;
        }
        this.shared[k] = shared;
      }
      begin = end;
    }
    this.stiffen(step);
  }

  /**
   * Geometric stiffness (Andrews, Erleben and Ferguson, "Geometric Stiffness for Real-time
   * Constrained Multibody Dynamics", 2017). A light link held by two loaded pins turns against a
   * stiffness |f . r| per pin that the solver treats explicitly, so its turning goes unstable
   * once h sqrt(k / I) nears 2: a 1000:1 chain of eight 0.25 m links released from the
   * horizontal exploded. The stiffness' diagonal, added implicitly to each inner body's inertia
   * for the step (I + h^2 k, with f = P / h from the pins' last impulses), bounds that mode for
   * every joint that moves the body; it damps only the links' whipping, by h^2 k / I.
   */
  private stiffen(step: JointStep): void {
    const h = step.h;
    const t = this.scratch;
    let begin = 0;
    for (let c = 0; c < this.chainCount; c++) {
      const end = this.chainEnd[c]!;
      for (let k = begin; k < end; k++) this.joints[k]!.pinLoad(t, 2 * k);
      for (let k = begin; k + 1 < end; k++) {
        const x = this.shared[k]!;
        const joint = this.joints[k]!;
        const next = this.joints[k + 1]!;
        const onJoint = joint.stateA === x ? 0 : 1;
        const onNext = next.stateA === x ? 0 : 1;
        const extra = h * (t[2 * k + onJoint]! + t[2 * k + 2 + onNext]!);
        joint.pinMasses(MASSES);
        const inverse = MASSES[2 * onJoint + 1]!;
        // A body that cannot turn stays so: 0 / (1 + 0 * extra) is NaN once a load overflows.
        // At most MAX_STIFFENING times its inertia: the loads are last step's impulses, and a
        // link made stiffer needs larger impulses to turn (a constant torque on it, a joint
        // pulling it), which made it stiffer still: a 10,000:1 chain with 1,000 N m on its first
        // link grew its impulses a thousandfold per sub-step until they overflowed.
        const stiff =
          inverse > 0 ? inverse / Math.min(1 + inverse * extra, MAX_STIFFENING) : inverse;
        MASSES[2 * onJoint + 1] = stiff;
        joint.setPinInertias(MASSES);
        next.pinMasses(MASSES);
        MASSES[2 * onNext + 1] = stiff;
        next.setPinInertias(MASSES);
      }
      begin = end;
    }
  }

  /**
   * The exact pin solve of every chain (see the note above), with the step's bias rate (with
   * `useBias`; else none) times the pins' position error in the target; or, with `positions`, moves the chains' bodies so every pin
   * closes exactly (post-stabilisation, Cline and Pai 2003): a taut chain of light links whips
   * sideways at no first-order cost to its pins, and the second-order drift would otherwise be
   * pushed back by velocity, which makes energy.
   *
   * The projection moves each body at most maxLinearSpeed h and MAX_PROJECTION_TURN per
   * sub-step, as the solver's speed limits move any pose: a pin torn far open (a body teleported
   * by a setter or a damaged snapshot, a far-anchored joint dragging a light link) would
   * otherwise be closed in one jump of any length, and bodies thrown that far come back into
   * contacts with levers of that length, whose impulses grow step after step until they
   * overflow (a 30:1 chain restored with one link 4e10 m off went non-finite in 3 steps).
   */
  run(s: Float64Array, useBias: boolean, positions: boolean): void {
    BIAS_RATE[0] = useBias ? this.biasRate : 0;
    const t = this.scratch;
    LIMITS[0] = this.maxMove;
    let begin = 0;
    for (let c = 0; c < this.chainCount; c++) {
      const end = this.chainEnd[c]!;
      // Forward: D_k = K_k - B_{k-1}^T D_{k-1}^-1 B_{k-1}, y_k = -c_k - B_{k-1}^T D_{k-1}^-1 y_{k-1}.
      for (let k = begin; k < end; k++) {
        const joint = this.joints[k]!;
        const o = 16 * k;
        joint.pinLevers(s, t, o);
        joint.pinError(s, BIAS_RATE, positions, t, o + 4);
        joint.pinMasses(MASSES);
        // K_k: each moving body's m I + i p(r) p(r)^T, with p(r) = (-r_y, r_x).
        let k11 = 0;
        let k12 = 0;
        let k22 = 0;
        for (let side = 0; side < 2; side++) {
          const m = MASSES[2 * side]!;
          const i = MASSES[2 * side + 1]!;
          const rx = t[o + 2 * side]!;
          const ry = t[o + 2 * side + 1]!;
          k11 += m + i * ry * ry;
          k12 -= i * ry * rx;
          k22 += m + i * rx * rx;
        }
        let y1 = -t[o + 4]!;
        let y2 = -t[o + 5]!;
        if (k > begin) {
          // B_{k-1} couples joint k-1 and k through their shared body X.
          const p = 16 * (k - 1);
          const b11 = t[p + 11]!;
          const b12 = t[p + 12]!;
          const b21 = t[p + 13]!;
          const b22 = t[p + 14]!;
          const d11 = t[p + 6]!;
          const d12 = t[p + 7]!;
          const d22 = t[p + 8]!;
          // L = B^T D^-1 (2x2)
          const l11 = b11 * d11 + b21 * d12;
          const l12 = b11 * d12 + b21 * d22;
          const l21 = b12 * d11 + b22 * d12;
          const l22 = b12 * d12 + b22 * d22;
          k11 -= l11 * b11 + l12 * b21;
          k12 -= l11 * b12 + l12 * b22;
          k22 -= l21 * b12 + l22 * b22;
          y1 -= l11 * t[p + 9]! + l12 * t[p + 10]!;
          y2 -= l21 * t[p + 9]! + l22 * t[p + 10]!;
        }
        const det = k11 * k22 - k12 * k12;
        if (!(det > 0 && det < Infinity)) {
          // A degenerate chain (a zero-mass gap): leave it to the sequential passes this time.
          begin = -1;
          break;
        }
        t[o + 6] = k22 / det;
        t[o + 7] = -k12 / det;
        t[o + 8] = k11 / det;
        t[o + 9] = y1;
        t[o + 10] = y2;
        // B_k (to the next joint) through the shared body X.
        const x = this.shared[k]!;
        if (x !== 0) {
          const next = this.joints[k + 1]!;
          next.pinLevers(s, t, o + 16 + 0); // the next joint's levers, written early (reused)
          const signK = joint.stateB === x ? 1 : -1;
          const signN = next.stateB === x ? 1 : -1;
          const m = signK === 1 ? MASSES[2]! : MASSES[0]!;
          const i = signK === 1 ? MASSES[3]! : MASSES[1]!;
          const rkx = t[o + (signK === 1 ? 2 : 0)]!;
          const rky = t[o + (signK === 1 ? 3 : 1)]!;
          const rnx = t[o + 16 + (signN === 1 ? 2 : 0)]!;
          const rny = t[o + 16 + (signN === 1 ? 3 : 1)]!;
          const sign = signK * signN;
          // sign (m I + i p(r_k) p(r_n)^T)
          t[o + 11] = sign * (m + i * rky * rny);
          t[o + 12] = sign * (-i * rky * rnx);
          t[o + 13] = sign * (-i * rkx * rny);
          t[o + 14] = sign * (m + i * rkx * rnx);
        }
      }
      if (begin < 0) {
        begin = end;
        continue;
      }
      // Back: lambda_k = D_k^-1 (y_k - B_k lambda_{k+1}); apply and accumulate.
      let nextX = 0;
      let nextY = 0;
      for (let k = end - 1; k >= begin; k--) {
        const o = 16 * k;
        let y1 = t[o + 9]!;
        let y2 = t[o + 10]!;
        if (k < end - 1) {
          y1 -= t[o + 11]! * nextX + t[o + 12]! * nextY;
          y2 -= t[o + 13]! * nextX + t[o + 14]! * nextY;
        }
        const lx = t[o + 6]! * y1 + t[o + 7]! * y2;
        const ly = t[o + 7]! * y1 + t[o + 8]! * y2;
        t[o + 15] = lx;
        // Keep lambda_y for the application pass below in the error slot (no longer needed).
        t[o + 5] = ly;
        nextX = lx;
        nextY = ly;
      }
      for (let k = begin; k < end; k++) {
        const joint = this.joints[k]!;
        const o = 16 * k;
        joint.pinLevers(s, t, o);
        joint.pinMasses(MASSES);
        // Both sides through one call that takes no fractional argument: V8 boxes (allocates)
        // the numbers it passes to a call it does not inline.
        applyPin(s, joint, 0, t, o, positions);
        applyPin(s, joint, 1, t, o, positions);
        if (!positions) joint.addPinImpulse(t, o, !useBias);
      }
      begin = end;
    }
  }
}

/**
 * Largest turn of a body in one projection (rad): the projection is linear in the angle, so a
 * light link asked to turn far would overshoot; the rest closes over the next sub-steps.
 */
const MAX_PROJECTION_TURN = 0.2;

/**
 * Largest factor by which the geometric stiffness multiplies a link's inertia for a step (see
 * PinChains.stiffen). Every regression hash, the chain samples' among them, is the same with it;
 * 1e4 still let a 10,000:1 chain of eight links with 1,000 N m on its first link go NaN.
 */
const MAX_STIFFENING = 1e3;

/** The projection's move limit (m), for applyPin: a call with a fractional argument would box it. */
const LIMITS = new Float64Array(1);

/** The bias rate handed to pinError, for the same reason. */
const BIAS_RATE = new Float64Array(1);

/**
 * A joint's inverse masses (PinJoint.pinMasses): read through a typed array, not getters, since
 * a getter V8 does not inline boxes the double it returns (per hinge per pass).
 */
const MASSES = new Float64Array(4);

/**
 * Applies the pin impulse in t (x at o + 15, y at o + 5, on B; the opposite on A) to one side of
 * the joint (levers at o, inverse masses in MASSES): to its velocity, or (`positions`) to its
 * pose, as a positional impulse.
 */
function applyPin(
  s: Float64Array,
  joint: PinJoint,
  side: number,
  t: Float64Array,
  o: number,
  positions: boolean,
): void {
  const k = side === 0 ? joint.stateA : joint.stateB;
  const m = MASSES[2 * side]!;
  const i = MASSES[2 * side + 1]!;
  if (k === 0 || (m === 0 && i === 0)) return;
  const sign = side === 0 ? -1 : 1;
  const px = sign * t[o + 15]!;
  const py = sign * t[o + 5]!;
  const rx = t[o + 2 * side]!;
  const ry = t[o + 2 * side + 1]!;
  const turn = i * (rx * py - ry * px);
  if (!positions) {
    s[k + V_X] = s[k + V_X]! + m * px;
    s[k + V_Y] = s[k + V_Y]! + m * py;
    s[k + W] = s[k + W]! + turn;
    return;
  }
  let dx = m * px;
  let dy = m * py;
  const maxMove = LIMITS[0]!;
  const moveSquared = dx * dx + dy * dy;
  if (!(moveSquared <= maxMove * maxMove)) {
    // Along the same direction, maxMove long (scaled by the larger component first, so an
    // overflowed square does not turn the direction into NaN); the rest closes in later sub-steps.
    const big = Math.max(Math.abs(dx), Math.abs(dy));
    if (big < Infinity) {
      const ux = dx / big;
      const uy = dy / big;
      const scale = maxMove / Math.sqrt(ux * ux + uy * uy);
      dx = ux * scale;
      dy = uy * scale;
    } else {
      dx = 0;
      dy = 0;
    }
  }
  s[k + DP_X] = s[k + DP_X]! + dx;
  s[k + DP_Y] = s[k + DP_Y]! + dy;
  const angle = Math.max(-MAX_PROJECTION_TURN, Math.min(MAX_PROJECTION_TURN, turn));
  if (angle === 0) return;
  // The turn of contact-solver's advancePose, written out: a call with a fractional argument
  // would box (allocate) it here, every sub-step.
  s[k + DELTA_ANGLE] = s[k + DELTA_ANGLE]! + angle;
  const qc = s[k + Q_C]!;
  const qs = s[k + Q_S]!;
  const c = qc - angle * qs;
  const sn = qs + angle * qc;
  const inverseLength = 1 / Math.sqrt(c * c + sn * sn);
  s[k + Q_C] = c * inverseLength;
  s[k + Q_S] = sn * inverseLength;
}

/** The solver slot of side 0 (A) or 1 (B); 0 for an immovable body. */
function slotOf(joint: PinJoint, side: number): number {
  if (side === 0) return joint.invMassA === 0 ? 0 : joint.stateA / STATE_STRIDE;
  return joint.invMassB === 0 ? 0 : joint.stateB / STATE_STRIDE;
}

/** The slot of the joint's body that is not at `slot` (0 when that body is immovable). */
function otherSlot(joint: PinJoint, slot: number): number {
  return slotOf(joint, 0) === slot ? slotOf(joint, 1) : slotOf(joint, 0);
}

/**
 * Mass ratio over which a hinge makes its chain solved exactly. Below it the sequential passes
 * hold a chain well (10:1 stretches a hanging chain by 9 mm) and a ragdoll's limbs (2-5:1) would
 * pay for the solve in every step (Box2D's rain scene: +15 % per step at 2).
 */
const UNLIKE = 5;

/** Two moving bodies more than UNLIKE-fold apart in mass. */
function isUnlike(joint: PinJoint): boolean {
  const mA = joint.invMassA;
  const mB = joint.invMassB;
  return mA > 0 && mB > 0 && (mA > UNLIKE * mB || mB > UNLIKE * mA);
}
