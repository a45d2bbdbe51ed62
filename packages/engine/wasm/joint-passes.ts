// The joints' passes of a sub-step: warm start and solve (with or without the position bias) of
// every joint kind, over the step's active joints of one kind. Like the contact and body passes,
// this is their one source, built to WebAssembly and by wasm2js to JavaScript
// (scripts/contact-kernel-build.ts) as a module of its own over the same imported memory, which
// only the joints' code loads (src/dynamics/joints/joint-kernel-loader.ts), in AssemblyScript's
// portable subset:
// f64 and i32 arithmetic over the solver memory at the byte offsets the solver passes in
// (src/dynamics/solver-memory.ts), no allocation.
//
// `records` is the JOINT_RECORDS region (every joint's record, src/dynamics/joints/joint-record.ts
// and each kind's file), `active` the JOINT_ACTIVE list (per active joint: its record's offset and
// its two bodies' state offsets, in doubles), `states` the STATES region (body-state.ts). A pass
// visits active joints `from` to `to` (one kind's range, in the world's joint order). The step's
// numbers come as f64 arguments, once per pass. One entry, jointPass, takes the kind and the pass
// (src/dynamics/joints/joint-batch.ts's codes); its loop opens every joint the same way (record,
// states, inverse masses, velocities, turned levers, the separation), runs the kind's rows on
// those numbers, and stores the velocities once.
//
// Every sum is kept in the order of the TypeScript passes these replaced, so no recorded result
// changed: Math.sqrt, max and min of doubles are f64.sqrt, max and min here, the same IEEE results
// for every finite number (they differ only in how a NaN among the arguments propagates). The
// opening loads each body's velocities once, before the kind's pass writes either: the same
// numbers the passes loaded later, since a joint's two state offsets always differ (a joint
// joins two bodies, and one with both at the sleeping or static state 0 is not active).
//
// Sequential impulses on soft constraints (Catto, Box2D v3's joints and "Solver2D"); the
// revolute and weld joints' rows are Box2D v3's (b2SolveRevoluteJoint, b2SolveWeldJoint,
// b2SolvePrismaticJoint, ...).
import {
  A_JOINT_BIAS_RATE,
  A_JOINT_H,
  A_JOINT_IMPULSE_SCALE,
  A_JOINT_INVERSE_H,
  A_JOINT_MASS_SCALE,
  A_JOINT_MAX_BIAS_SPEED,
  DELTA_ANGLE,
  DP_X,
  DP_Y,
  J_DELTA_CENTER_X,
  J_DISTANCE_DAMPING_RATIO,
  J_DISTANCE_EXPLICIT_SPRING,
  J_DISTANCE_IMPULSE,
  J_DISTANCE_LENGTH_EPSILON,
  J_DISTANCE_LENGTH_ROW_ON,
  J_DISTANCE_LOWER_IMPULSE,
  J_DISTANCE_LOWER_ON,
  J_DISTANCE_MAX_LENGTH,
  J_DISTANCE_MIN_LENGTH,
  J_DISTANCE_REST,
  J_DISTANCE_SPRING_BIAS_RATE,
  J_DISTANCE_SPRING_ENABLED,
  J_DISTANCE_SPRING_IMPULSE_SCALE,
  J_DISTANCE_SPRING_MASS_SCALE,
  J_DISTANCE_SPRING_OMEGA,
  J_DISTANCE_SPRING_SUB_STEP_IMPULSE,
  J_DISTANCE_UPPER_IMPULSE,
  J_DISTANCE_UPPER_ON,
  J_MOUSE_ANGULAR_IMPULSE,
  J_MOUSE_ANGULAR_IMPULSE_SCALE,
  J_MOUSE_ANGULAR_MASS_SCALE,
  J_MOUSE_LINEAR_BIAS_RATE,
  J_MOUSE_LINEAR_IMPULSE_SCALE,
  J_MOUSE_LINEAR_IMPULSE_X,
  J_MOUSE_LINEAR_IMPULSE_Y,
  J_MOUSE_LINEAR_MASS_SCALE,
  J_MOUSE_MAX_FORCE,
  J_DELTA_CENTER_Y,
  J_INV_I_A,
  J_INV_I_B,
  J_INV_MASS_A,
  J_INV_MASS_B,
  J_KIND_DISTANCE,
  J_KIND_MOUSE,
  J_KIND_PRISMATIC,
  J_KIND_REVOLUTE,
  J_KIND_WELD,
  J_PASS_SOLVE,
  J_PASS_WARM_START,
  J_JOINT_ANGLE_0,
  J_LIMIT_ON,
  J_LOWER,
  J_LOWER_IMPULSE,
  J_MAX_MOTOR,
  J_MOTOR_IMPULSE,
  J_MOTOR_ON,
  J_MOTOR_SPEED,
  J_PRISMATIC_ANGULAR_IMPULSE,
  J_PRISMATIC_AXIS_X,
  J_PRISMATIC_PERPENDICULAR_IMPULSE,
  J_REVOLUTE_AXIAL_MASS,
  J_REVOLUTE_LINEAR_IMPULSE_X,
  J_REVOLUTE_LINEAR_IMPULSE_Y,
  J_R_AX,
  J_R_BX,
  J_SPRING_BIAS_RATE,
  J_SPRING_IMPULSE,
  J_SPRING_IMPULSE_SCALE,
  J_SPRING_MASS_SCALE,
  J_SPRING_ON,
  J_STEP_ANGULAR_IMPULSE,
  J_STEP_IMPULSE_X,
  J_STEP_IMPULSE_Y,
  J_UPPER,
  J_UPPER_IMPULSE,
  J_WELD_ANGULAR_BIAS_RATE,
  J_WELD_ANGULAR_IMPULSE,
  J_WELD_ANGULAR_IMPULSE_SCALE,
  J_WELD_ANGULAR_MASS_SCALE,
  J_WELD_ANGULAR_SPRINGY,
  J_WELD_AXIAL_MASS,
  J_WELD_LINEAR_IMPULSE_X,
  J_WELD_LINEAR_IMPULSE_Y,
  J_WELD_LINEAR_SPRINGY,
  Q_C,
  Q_S,
  V_X,
  V_Y,
  W,
} from './contact-layout';
import { ld, st } from './load-store';

/** Where the numbers at double offset `at` of the region at `region` start. */
function row(region: usize, at: i32): usize {
  return region + ((<usize>at) << 3);
}

/** Entry k (0: record offset, 1: state A, 2: state B) of active joint i. */
function listed(active: usize, i: i32, k: i32): i32 {
  return load<i32>(active + ((<usize>(3 * i + k)) << 2));
}

// A vector of the record at `v` (x, then y) turned by the rotation this step of the state at `k`
// (src/dynamics/joints/joint-levers.ts does it in TypeScript for the pin chains).

function turnedX(k: usize, r: usize, v: i32): f64 {
  return ld(k, Q_C) * ld(r, v) - ld(k, Q_S) * ld(r, v + 1);
}

function turnedY(k: usize, r: usize, v: i32): f64 {
  return ld(k, Q_S) * ld(r, v) + ld(k, Q_C) * ld(r, v + 1);
}

/**
 * The accumulated impulse of a one-sided limit row (C >= 0: the revolute's angle, the prismatic's
 * translation, the distance joint's length, each against its lower and upper bound) after one
 * more solve: `c` the row's position, `cdot` its speed, `old` its impulse so far, `mass` its
 * effective mass. Speculative like contacts: an open gap may close within the sub-step (bias
 * c / h); a violated limit is pushed back with the joint softness in the biased pass only.
 */
function limitRow(
  mass: f64,
  c: f64,
  cdot: f64,
  old: f64,
  inverseH: f64,
  useBias: i32,
  biasRate: f64,
  softMassScale: f64,
  softImpulseScale: f64,
): f64 {
  let bias: f64 = 0;
  let massScale: f64 = 1;
  let impulseScale: f64 = 0;
  if (c > 0) bias = c * inverseH;
  else if (useBias != 0) {
    bias = biasRate * c;
    massScale = softMassScale;
    impulseScale = softImpulseScale;
  }
  return Math.max(old + (-mass * massScale * (cdot + bias) - impulseScale * old), 0);
}

/**
 * The pass `pass` (J_PASS_WARM_START, J_PASS_SOLVE with the position bias, J_PASS_RELAX without)
 * of the joints of kind `kind` (J_KIND_...) at entries `from` to `to` of the active list. The
 * step's numbers (JointStep: the sub-step, its inverse, the joint softness and the bias bound) are
 * the arguments at `args` (A_JOINT_..., kernel-arguments.ts); the warm start reads none of them.
 * A mouse joint has one body, B.
 */
export function jointPass(
  kind: i32,
  pass: i32,
  records: usize,
  active: usize,
  states: usize,
  from: i32,
  to: i32,
  args: usize,
): void {
  const h = ld(args, A_JOINT_H);
  const inverseH = ld(args, A_JOINT_INVERSE_H);
  const biasRate = ld(args, A_JOINT_BIAS_RATE);
  const softMassScale = ld(args, A_JOINT_MASS_SCALE);
  const softImpulseScale = ld(args, A_JOINT_IMPULSE_SCALE);
  const maxBiasSpeed = ld(args, A_JOINT_MAX_BIAS_SPEED);
  const useBias = pass == J_PASS_SOLVE ? 1 : 0;
  const twoBodies = kind != J_KIND_MOUSE;
  // The kinds whose rows act along the line between the anchors read their separation.
  const along = kind == J_KIND_PRISMATIC || kind == J_KIND_DISTANCE;
  for (let i = from; i < to; i++) {
    // The opening every kind shares.
    const r = row(records, listed(active, i, 0));
    const ka = row(states, listed(active, i, 1));
    const kb = row(states, listed(active, i, 2));
    const mA = ld(r, J_INV_MASS_A);
    const iA = ld(r, J_INV_I_A);
    const mB = ld(r, J_INV_MASS_B);
    const iB = ld(r, J_INV_I_B);
    let vAx = ld(ka, V_X);
    let vAy = ld(ka, V_Y);
    let wA = ld(ka, W);
    let vBx = ld(kb, V_X);
    let vBy = ld(kb, V_Y);
    let wB = ld(kb, W);
    const rAx = turnedX(ka, r, J_R_AX);
    const rAy = turnedY(ka, r, J_R_AX);
    const rBx = turnedX(kb, r, J_R_BX);
    const rBy = turnedY(kb, r, J_R_BX);
    // B's anchor from A's: how far B's centre is from A's now (their motion this step plus their
    // offset at its start), then the turned levers' difference, in that order. (The soft point's
    // separation, below, is summed in another order.)
    let dx: f64 = 0;
    let dy: f64 = 0;
    if (along) {
      dx = ld(kb, DP_X) - ld(ka, DP_X) + ld(r, J_DELTA_CENTER_X) + rBx - rAx;
      dy = ld(kb, DP_Y) - ld(ka, DP_Y) + ld(r, J_DELTA_CENTER_Y) + rBy - rAy;
    }

    if (pass == J_PASS_WARM_START) {
      // Last step's impulses applied again: (fx, fy) on B (on A the opposite), lA and lB the
      // angular impulses on A (taken away) and B.
      let fx: f64;
      let fy: f64;
      let lA: f64 = 0;
      let lB: f64;
      if (kind == J_KIND_REVOLUTE || kind == J_KIND_WELD) {
        // The point's impulse and the one about the axis (the revolute's spring, motor and
        // limits, the weld's angle row).
        const revolute = kind == J_KIND_REVOLUTE;
        fx = ld(r, revolute ? J_REVOLUTE_LINEAR_IMPULSE_X : J_WELD_LINEAR_IMPULSE_X);
        fy = ld(r, revolute ? J_REVOLUTE_LINEAR_IMPULSE_Y : J_WELD_LINEAR_IMPULSE_Y);
        const axial = revolute
          ? ld(r, J_SPRING_IMPULSE) +
            ld(r, J_MOTOR_IMPULSE) +
            ld(r, J_LOWER_IMPULSE) -
            ld(r, J_UPPER_IMPULSE)
          : ld(r, J_WELD_ANGULAR_IMPULSE);
        lA = rAx * fy - rAy * fx + axial;
        lB = rBx * fy - rBy * fx + axial;
      } else if (kind == J_KIND_PRISMATIC) {
        // The axial, perpendicular and angle impulses.
        const ax = turnedX(ka, r, J_PRISMATIC_AXIS_X);
        const ay = turnedY(ka, r, J_PRISMATIC_AXIS_X);
        // Lever arms of the axial and perpendicular rows (A's arm reaches B's anchor: d + rA).
        const a1 = (dx + rAx) * ay - (dy + rAy) * ax;
        const a2 = rBx * ay - rBy * ax;
        const px = -ay;
        const py = ax;
        const s1 = (dx + rAx) * py - (dy + rAy) * px;
        const s2 = rBx * py - rBy * px;
        const axial =
          ld(r, J_SPRING_IMPULSE) +
          ld(r, J_MOTOR_IMPULSE) +
          ld(r, J_LOWER_IMPULSE) -
          ld(r, J_UPPER_IMPULSE);
        const perpendicular = ld(r, J_PRISMATIC_PERPENDICULAR_IMPULSE);
        const angular = ld(r, J_PRISMATIC_ANGULAR_IMPULSE);
        fx = axial * ax + perpendicular * px;
        fy = axial * ay + perpendicular * py;
        lA = axial * a1 + perpendicular * s1 + angular;
        lB = axial * a2 + perpendicular * s2 + angular;
      } else if (kind == J_KIND_DISTANCE) {
        // The impulses along the line between the anchors.
        const length = Math.sqrt(dx * dx + dy * dy);
        if (!(length > J_DISTANCE_LENGTH_EPSILON)) continue;
        const axial =
          ld(r, J_DISTANCE_IMPULSE) +
          ld(r, J_DISTANCE_LOWER_IMPULSE) -
          ld(r, J_DISTANCE_UPPER_IMPULSE);
        fx = (axial * dx) / length;
        fy = (axial * dy) / length;
        lA = rAx * fy - rAy * fx;
        lB = rBx * fy - rBy * fx;
      } else {
        // The mouse's pull and spin brake on its one body.
        fx = ld(r, J_MOUSE_LINEAR_IMPULSE_X);
        fy = ld(r, J_MOUSE_LINEAR_IMPULSE_Y);
        lB = rBx * fy - rBy * fx + ld(r, J_MOUSE_ANGULAR_IMPULSE);
      }
      if (twoBodies) {
        st(ka, V_X, vAx - mA * fx);
        st(ka, V_Y, vAy - mA * fy);
        st(ka, W, wA - iA * lA);
      }
      st(kb, V_X, vBx + mB * fx);
      st(kb, V_Y, vBy + mB * fy);
      st(kb, W, wB + iB * lB);
      continue;
    }

    if (kind == J_KIND_REVOLUTE) {
      // The spring, the motor and the two limits on the angle, then the point (below).
      const jointAngle = ld(r, J_JOINT_ANGLE_0) + ld(kb, DELTA_ANGLE) - ld(ka, DELTA_ANGLE);
      const axialMass = ld(r, J_REVOLUTE_AXIAL_MASS);

      if (ld(r, J_SPRING_ON) == 1) {
        const bias = ld(r, J_SPRING_BIAS_RATE) * jointAngle;
        const impulse =
          -ld(r, J_SPRING_MASS_SCALE) * axialMass * (wB - wA + bias) -
          ld(r, J_SPRING_IMPULSE_SCALE) * ld(r, J_SPRING_IMPULSE);
        st(r, J_SPRING_IMPULSE, ld(r, J_SPRING_IMPULSE) + impulse);
        wA -= iA * impulse;
        wB += iB * impulse;
      }

      if (ld(r, J_MOTOR_ON) == 1) {
        const impulse = -axialMass * (wB - wA - ld(r, J_MOTOR_SPEED));
        const old = ld(r, J_MOTOR_IMPULSE);
        const maxImpulse = h * ld(r, J_MAX_MOTOR);
        const accumulated = Math.max(-maxImpulse, Math.min(old + impulse, maxImpulse));
        st(r, J_MOTOR_IMPULSE, accumulated);
        const applied = accumulated - old;
        wA -= iA * applied;
        wB += iB * applied;
      }

      if (ld(r, J_LIMIT_ON) == 1) {
        // Lower limit: C = angle - lower >= 0; upper: C = upper - angle >= 0, the same row with
        // the sign turned. Speculative like contacts: a gap may close within the sub-step.
        for (let side = 1; side >= -1; side -= 2) {
          const c = side == 1 ? jointAngle - ld(r, J_LOWER) : ld(r, J_UPPER) - jointAngle;
          const at = side == 1 ? J_LOWER_IMPULSE : J_UPPER_IMPULSE;
          const cdot = side == 1 ? wB - wA : wA - wB;
          const old = ld(r, at);
          const accumulated = limitRow(
            axialMass,
            c,
            cdot,
            old,
            inverseH,
            useBias,
            biasRate,
            softMassScale,
            softImpulseScale,
          );
          const applied = accumulated - old;
          st(r, at, accumulated);
          if (side == 1) {
            wA -= iA * applied;
            wB += iB * applied;
          } else {
            wA += iA * applied;
            wB -= iB * applied;
          }
        }
      }
    } else if (kind == J_KIND_WELD) {
      // The angle row, then the point (below; Box2D v3's b2SolveWeldJoint). A rigid hold
      // corrects its error with the joint softness in the biased pass only, a soft one with its
      // own softness in both.
      let bias: f64 = 0;
      let rowMassScale: f64 = 1;
      let rowImpulseScale: f64 = 0;
      const springy = ld(r, J_WELD_ANGULAR_SPRINGY) == 1;
      if (useBias != 0 || springy) {
        const c = ld(r, J_JOINT_ANGLE_0) + ld(kb, DELTA_ANGLE) - ld(ka, DELTA_ANGLE);
        if (springy) {
          bias = ld(r, J_WELD_ANGULAR_BIAS_RATE) * c;
          rowMassScale = ld(r, J_WELD_ANGULAR_MASS_SCALE);
          rowImpulseScale = ld(r, J_WELD_ANGULAR_IMPULSE_SCALE);
        } else {
          bias = biasRate * c;
          rowMassScale = softMassScale;
          rowImpulseScale = softImpulseScale;
        }
      }
      const impulse =
        -ld(r, J_WELD_AXIAL_MASS) * rowMassScale * (wB - wA + bias) -
        rowImpulseScale * ld(r, J_WELD_ANGULAR_IMPULSE);
      st(r, J_WELD_ANGULAR_IMPULSE, ld(r, J_WELD_ANGULAR_IMPULSE) + impulse);
      wA -= iA * impulse;
      wB += iB * impulse;
    } else if (kind == J_KIND_PRISMATIC) {
      // Box2D v3's b2SolvePrismaticJoint: the rows along the axis one after another (spring,
      // motor, lower and upper limit), then the perpendicular offset and the relative angle
      // together as a 2x2 block.
      const ax = turnedX(ka, r, J_PRISMATIC_AXIS_X);
      const ay = turnedY(ka, r, J_PRISMATIC_AXIS_X);
      const translation = ax * dx + ay * dy;
      const a1 = (dx + rAx) * ay - (dy + rAy) * ax;
      const a2 = rBx * ay - rBy * ax;
      const kAxial = mA + mB + iA * a1 * a1 + iB * a2 * a2;
      const axialMass: f64 = kAxial > 0 ? 1 / kAxial : 0;

      // The rows along the axis, one after another, each on the velocities the one before left:
      // the spring (row 0), the motor (1), translation >= lower (2) and translation <= upper (3).
      // Each gives the impulse `push` on B along the axis (on A the opposite), applied in one place.
      for (let k = 0; k < 4; k++) {
        if (ld(r, k == 0 ? J_SPRING_ON : k == 1 ? J_MOTOR_ON : J_LIMIT_ON) != 1) continue;
        let push: f64;
        if (k < 2) {
          const cdot = ax * (vBx - vAx) + ay * (vBy - vAy) + a2 * wB - a1 * wA;
          if (k == 0) {
            push =
              -ld(r, J_SPRING_MASS_SCALE) *
                axialMass *
                (cdot + ld(r, J_SPRING_BIAS_RATE) * translation) -
              ld(r, J_SPRING_IMPULSE_SCALE) * ld(r, J_SPRING_IMPULSE);
            st(r, J_SPRING_IMPULSE, ld(r, J_SPRING_IMPULSE) + push);
          } else {
            const impulse = axialMass * (ld(r, J_MOTOR_SPEED) - cdot);
            const old = ld(r, J_MOTOR_IMPULSE);
            const maxImpulse = h * ld(r, J_MAX_MOTOR);
            const accumulated = Math.max(-maxImpulse, Math.min(old + impulse, maxImpulse));
            st(r, J_MOTOR_IMPULSE, accumulated);
            push = accumulated - old;
          }
        } else {
          // Lower: translation - lower >= 0; upper: upper - translation >= 0, the same row with
          // the sign turned. Speculative like contacts: a gap may close within the sub-step.
          const lower = k == 2;
          const c = lower ? translation - ld(r, J_LOWER) : ld(r, J_UPPER) - translation;
          const cdot = lower
            ? ax * (vBx - vAx) + ay * (vBy - vAy) + a2 * wB - a1 * wA
            : ax * (vAx - vBx) + ay * (vAy - vBy) + a1 * wA - a2 * wB;
          const at = lower ? J_LOWER_IMPULSE : J_UPPER_IMPULSE;
          const old = ld(r, at);
          const accumulated = limitRow(
            axialMass,
            c,
            cdot,
            old,
            inverseH,
            useBias,
            biasRate,
            softMassScale,
            softImpulseScale,
          );
          st(r, at, accumulated);
          push = lower ? accumulated - old : -(accumulated - old);
        }
        vAx -= mA * push * ax;
        vAy -= mA * push * ay;
        wA -= iA * push * a1;
        vBx += mB * push * ax;
        vBy += mB * push * ay;
        wB += iB * push * a2;
      }

      // Perpendicular offset and relative angle, solved together.
      const px = -ay;
      const py = ax;
      const s1 = (dx + rAx) * py - (dy + rAy) * px;
      const s2 = rBx * py - rBy * px;
      const cdot1 = px * (vBx - vAx) + py * (vBy - vAy) + s2 * wB - s1 * wA;
      const cdot2 = wB - wA;
      let bias1: f64 = 0;
      let bias2: f64 = 0;
      let massScale: f64 = 1;
      let impulseScale: f64 = 0;
      if (useBias != 0) {
        bias1 = biasRate * (px * dx + py * dy);
        bias2 = biasRate * (ld(r, J_JOINT_ANGLE_0) + ld(kb, DELTA_ANGLE) - ld(ka, DELTA_ANGLE));
        massScale = softMassScale;
        impulseScale = softImpulseScale;
      }
      const k11 = mA + mB + iA * s1 * s1 + iB * s2 * s2;
      const k12 = iA * s1 + iB * s2;
      let k22 = iA + iB;
      if (k22 == 0) k22 = 1; // neither body turns: the angle row is idle
      const bX = cdot1 + bias1;
      const bY = cdot2 + bias2;
      let det = k11 * k22 - k12 * k12;
      if (det != 0) det = 1 / det;
      const solvedX = det * (k22 * bX - k12 * bY);
      const solvedY = det * (k11 * bY - k12 * bX);
      const impulse1 =
        -massScale * solvedX - impulseScale * ld(r, J_PRISMATIC_PERPENDICULAR_IMPULSE);
      const impulse2 = -massScale * solvedY - impulseScale * ld(r, J_PRISMATIC_ANGULAR_IMPULSE);
      st(r, J_PRISMATIC_PERPENDICULAR_IMPULSE, ld(r, J_PRISMATIC_PERPENDICULAR_IMPULSE) + impulse1);
      st(r, J_PRISMATIC_ANGULAR_IMPULSE, ld(r, J_PRISMATIC_ANGULAR_IMPULSE) + impulse2);
      const fx = impulse1 * px;
      const fy = impulse1 * py;
      const lA = impulse1 * s1 + impulse2;
      const lB = impulse1 * s2 + impulse2;
      vAx -= mA * fx;
      vAy -= mA * fy;
      wA -= iA * lA;
      vBx += mB * fx;
      vBy += mB * fy;
      wB += iB * lB;

      if (useBias == 0) {
        const axial =
          ld(r, J_SPRING_IMPULSE) +
          ld(r, J_MOTOR_IMPULSE) +
          ld(r, J_LOWER_IMPULSE) -
          ld(r, J_UPPER_IMPULSE);
        st(
          r,
          J_STEP_IMPULSE_X,
          ld(r, J_STEP_IMPULSE_X) + (axial * ax + ld(r, J_PRISMATIC_PERPENDICULAR_IMPULSE) * px),
        );
        st(
          r,
          J_STEP_IMPULSE_Y,
          ld(r, J_STEP_IMPULSE_Y) + (axial * ay + ld(r, J_PRISMATIC_PERPENDICULAR_IMPULSE) * py),
        );
        st(
          r,
          J_STEP_ANGULAR_IMPULSE,
          ld(r, J_STEP_ANGULAR_IMPULSE) + ld(r, J_PRISMATIC_ANGULAR_IMPULSE),
        );
      }
    } else if (kind == J_KIND_DISTANCE) {
      // Box2D v3's b2SolveDistanceJoint, with an explicit spring force for slow springs: the rows
      // along the line between the anchors one after another.
      const length = Math.sqrt(dx * dx + dy * dy);
      // Coincident anchors have no direction to push along.
      if (length > J_DISTANCE_LENGTH_EPSILON) {
        const nx = dx / length;
        const ny = dy / length;
        const crA = rAx * ny - rAy * nx;
        const crB = rBx * ny - rBy * nx;
        const k = mA + mB + iA * crA * crA + iB * crB * crB;
        const axialMass: f64 = k > 0 ? 1 / k : 0;

        // The rows along n, one after another, each on the velocities the one before left: the
        // explicit spring's force (row 0), the rod or the soft spring (1), length >= minLength (2,
        // pushes apart only) and length <= maxLength (3, pulls together only: a rope). Each gives
        // the impulse `push` on B along n (on A the opposite), applied in one place.
        const explicit = ld(r, J_DISTANCE_EXPLICIT_SPRING) == 1;
        for (let n = 0; n < 4; n++) {
          if (
            n == 0
              ? !explicit || useBias == 0
              : n == 1
                ? explicit || ld(r, J_DISTANCE_LENGTH_ROW_ON) != 1
                : ld(r, n == 2 ? J_DISTANCE_LOWER_ON : J_DISTANCE_UPPER_ON) != 1
          ) {
            continue;
          }
          const cdot =
            (vBx - wB * rBy - vAx + wA * rAy) * nx + (vBy + wB * rBx - vAy - wA * rAx) * ny;
          let push: f64;
          if (n == 0) {
            // Spring force -k C - c Cdot over the sub-step (C = length - rest), with k and c for
            // the effective mass; the damping part implicit, so no damping ratio can reverse the
            // motion.
            const omega = ld(r, J_DISTANCE_SPRING_OMEGA);
            const damping = 2 * ld(r, J_DISTANCE_DAMPING_RATIO) * omega;
            push =
              (-axialMass *
                h *
                (omega * omega * (length - ld(r, J_DISTANCE_REST)) + damping * cdot)) /
              (1 + damping * h);
            st(r, J_DISTANCE_SPRING_SUB_STEP_IMPULSE, push);
          } else if (n == 1) {
            // C = length - rest.
            let bias: f64 = 0;
            let massScale: f64 = 1;
            let impulseScale: f64 = 0;
            if (ld(r, J_DISTANCE_SPRING_ENABLED) == 1) {
              bias = ld(r, J_DISTANCE_SPRING_BIAS_RATE) * (length - ld(r, J_DISTANCE_REST));
              massScale = ld(r, J_DISTANCE_SPRING_MASS_SCALE);
              impulseScale = ld(r, J_DISTANCE_SPRING_IMPULSE_SCALE);
            } else if (useBias != 0) {
              bias = biasRate * (length - ld(r, J_DISTANCE_REST));
              massScale = softMassScale;
              impulseScale = softImpulseScale;
            }
            push =
              -massScale * axialMass * (cdot + bias) - impulseScale * ld(r, J_DISTANCE_IMPULSE);
            st(r, J_DISTANCE_IMPULSE, ld(r, J_DISTANCE_IMPULSE) + push);
          } else {
            // Lower: C = length - minLength >= 0; upper: C = maxLength - length >= 0, the same
            // row with the sign turned. Speculative like contacts: a gap may close within the
            // sub-step.
            const lower = n == 2;
            const c = lower
              ? length - ld(r, J_DISTANCE_MIN_LENGTH)
              : ld(r, J_DISTANCE_MAX_LENGTH) - length;
            const at = lower ? J_DISTANCE_LOWER_IMPULSE : J_DISTANCE_UPPER_IMPULSE;
            const old = ld(r, at);
            // (-massScale * axialMass here before: the same product, IEEE products commute.)
            const accumulated = limitRow(
              axialMass,
              c,
              lower ? cdot : -cdot,
              old,
              inverseH,
              useBias,
              biasRate,
              softMassScale,
              softImpulseScale,
            );
            st(r, at, accumulated);
            push = lower ? accumulated - old : -(accumulated - old);
          }
          const px = push * nx;
          const py = push * ny;
          vAx -= mA * px;
          vAy -= mA * py;
          wA -= iA * (rAx * py - rAy * px);
          vBx += mB * px;
          vBy += mB * py;
          wB += iB * (rBx * py - rBy * px);
        }

        if (useBias == 0) {
          const axial =
            ld(r, J_DISTANCE_IMPULSE) +
            ld(r, J_DISTANCE_SPRING_SUB_STEP_IMPULSE) +
            ld(r, J_DISTANCE_LOWER_IMPULSE) -
            ld(r, J_DISTANCE_UPPER_IMPULSE);
          st(r, J_STEP_IMPULSE_X, ld(r, J_STEP_IMPULSE_X) + axial * nx);
          st(r, J_STEP_IMPULSE_Y, ld(r, J_STEP_IMPULSE_Y) + axial * ny);
        }
      }
    } else {
      // The mouse (Box2D v3's b2SolveMouseJoint): a soft brake on the spin, then the spring to
      // the target, soft in both passes, its impulse bounded by the joint's maxForce. The brake
      // has no target angle.
      let spin: f64 = iB > 0 ? -wB / iB : 0;
      spin =
        ld(r, J_MOUSE_ANGULAR_MASS_SCALE) * spin -
        ld(r, J_MOUSE_ANGULAR_IMPULSE_SCALE) * ld(r, J_MOUSE_ANGULAR_IMPULSE);
      st(r, J_MOUSE_ANGULAR_IMPULSE, ld(r, J_MOUSE_ANGULAR_IMPULSE) + spin);
      wB += iB * spin;

      // The spring to the target; always soft, in both passes (it is a spring, not a rigid link).
      const pullBiasRate = ld(r, J_MOUSE_LINEAR_BIAS_RATE);
      const pullMassScale = ld(r, J_MOUSE_LINEAR_MASS_SCALE);
      const pullImpulseScale = ld(r, J_MOUSE_LINEAR_IMPULSE_SCALE);
      const cdotX = vBx - wB * rBy;
      const cdotY = vBy + wB * rBx;
      const sepX = ld(kb, DP_X) + rBx + ld(r, J_DELTA_CENTER_X);
      const sepY = ld(kb, DP_Y) + rBy + ld(r, J_DELTA_CENTER_Y);
      const k11 = mB + rBy * rBy * iB;
      const k12 = -rBy * rBx * iB;
      const k22 = mB + rBx * rBx * iB;
      const bX = cdotX + pullBiasRate * sepX;
      const bY = cdotY + pullBiasRate * sepY;
      let det = k11 * k22 - k12 * k12;
      if (det != 0) det = 1 / det;
      const solvedX = det * (k22 * bX - k12 * bY);
      const solvedY = det * (k11 * bY - k12 * bX);
      const oldX = ld(r, J_MOUSE_LINEAR_IMPULSE_X);
      const oldY = ld(r, J_MOUSE_LINEAR_IMPULSE_Y);
      let accX = oldX - pullMassScale * solvedX - pullImpulseScale * oldX;
      let accY = oldY - pullMassScale * solvedY - pullImpulseScale * oldY;
      const maxImpulse = ld(r, J_MOUSE_MAX_FORCE) * h;
      const magnitude = Math.sqrt(accX * accX + accY * accY);
      if (magnitude > maxImpulse) {
        const scale = maxImpulse / magnitude;
        accX *= scale;
        accY *= scale;
      }
      st(r, J_MOUSE_LINEAR_IMPULSE_X, accX);
      st(r, J_MOUSE_LINEAR_IMPULSE_Y, accY);
      const px = accX - oldX;
      const py = accY - oldY;
      vBx += mB * px;
      vBy += mB * py;
      wB += iB * (rBx * py - rBy * px);
      if (useBias == 0) {
        st(r, J_STEP_IMPULSE_X, ld(r, J_STEP_IMPULSE_X) + ld(r, J_MOUSE_LINEAR_IMPULSE_X));
        st(r, J_STEP_IMPULSE_Y, ld(r, J_STEP_IMPULSE_Y) + ld(r, J_MOUSE_LINEAR_IMPULSE_Y));
        st(
          r,
          J_STEP_ANGULAR_IMPULSE,
          ld(r, J_STEP_ANGULAR_IMPULSE) + ld(r, J_MOUSE_ANGULAR_IMPULSE),
        );
      }
    }

    if (kind == J_KIND_REVOLUTE || kind == J_KIND_WELD) {
      // The soft point: B's anchor held on A's, both directions solved together as a 2x2 block
      // (Box2D v3's revolute and weld joints), on the spins the rows above left. The position
      // error is corrected in the biased pass with the step's joint softness, or (a soft weld) in
      // both passes with the record's own (J_WELD_LINEAR_SPRINGY: 1 when it applies, then bias
      // rate, mass scale and impulse scale); the revolute's bias is bounded by maxBiasSpeed.
      const revolute = kind == J_KIND_REVOLUTE;
      const impulse = revolute ? J_REVOLUTE_LINEAR_IMPULSE_X : J_WELD_LINEAR_IMPULSE_X;
      const cdotX = vBx - wB * rBy - (vAx - wA * rAy);
      const cdotY = vBy + wB * rBx - (vAy + wA * rAx);
      let biasX: f64 = 0;
      let biasY: f64 = 0;
      let massScale: f64 = 1;
      let impulseScale: f64 = 0;
      const springy = !revolute && ld(r, J_WELD_LINEAR_SPRINGY) == 1;
      if (useBias != 0 || springy) {
        // Summed in this order, not the other kinds' shift + rBx - rAx: the bridge's, car's and
        // ragdoll's recorded hashes depend on it.
        const sepX = ld(kb, DP_X) - ld(ka, DP_X) + rBx - rAx + ld(r, J_DELTA_CENTER_X);
        const sepY = ld(kb, DP_Y) - ld(ka, DP_Y) + rBy - rAy + ld(r, J_DELTA_CENTER_Y);
        if (springy) {
          biasX = ld(r, J_WELD_LINEAR_SPRINGY + 1) * sepX;
          biasY = ld(r, J_WELD_LINEAR_SPRINGY + 1) * sepY;
          massScale = ld(r, J_WELD_LINEAR_SPRINGY + 2);
          impulseScale = ld(r, J_WELD_LINEAR_SPRINGY + 3);
        } else {
          biasX = biasRate * sepX;
          biasY = biasRate * sepY;
          massScale = softMassScale;
          impulseScale = softImpulseScale;
        }
        if (revolute) {
          // At most maxBiasSpeed (see JointStep.maxBiasSpeed).
          const biasSquared = biasX * biasX + biasY * biasY;
          if (biasSquared > maxBiasSpeed * maxBiasSpeed) {
            const ratio = maxBiasSpeed / Math.sqrt(biasSquared);
            biasX *= ratio;
            biasY *= ratio;
          }
        }
      }
      const k11 = mA + mB + rAy * rAy * iA + rBy * rBy * iB;
      const k12 = -rAy * rAx * iA - rBy * rBx * iB;
      const k22 = mA + mB + rAx * rAx * iA + rBx * rBx * iB;
      const bX = cdotX + biasX;
      const bY = cdotY + biasY;
      let det = k11 * k22 - k12 * k12;
      if (det != 0) det = 1 / det;
      const solvedX = det * (k22 * bX - k12 * bY);
      const solvedY = det * (k11 * bY - k12 * bX);
      const px = -massScale * solvedX - impulseScale * ld(r, impulse);
      const py = -massScale * solvedY - impulseScale * ld(r, impulse + 1);
      st(r, impulse, ld(r, impulse) + px);
      st(r, impulse + 1, ld(r, impulse + 1) + py);
      vAx = vAx - mA * px;
      vAy = vAy - mA * py;
      wA = wA - iA * (rAx * py - rAy * px);
      vBx = vBx + mB * px;
      vBy = vBy + mB * py;
      wB = wB + iB * (rBx * py - rBy * px);
      if (useBias == 0) {
        // The step's impulses (the reaction).
        if (revolute) {
          st(r, J_STEP_IMPULSE_X, ld(r, J_STEP_IMPULSE_X) + ld(r, J_REVOLUTE_LINEAR_IMPULSE_X));
          st(r, J_STEP_IMPULSE_Y, ld(r, J_STEP_IMPULSE_Y) + ld(r, J_REVOLUTE_LINEAR_IMPULSE_Y));
          st(
            r,
            J_STEP_ANGULAR_IMPULSE,
            ld(r, J_STEP_ANGULAR_IMPULSE) +
              (ld(r, J_SPRING_IMPULSE) +
                ld(r, J_MOTOR_IMPULSE) +
                ld(r, J_LOWER_IMPULSE) -
                ld(r, J_UPPER_IMPULSE)),
          );
        } else {
          st(r, J_STEP_IMPULSE_X, ld(r, J_STEP_IMPULSE_X) + ld(r, J_WELD_LINEAR_IMPULSE_X));
          st(r, J_STEP_IMPULSE_Y, ld(r, J_STEP_IMPULSE_Y) + ld(r, J_WELD_LINEAR_IMPULSE_Y));
          st(
            r,
            J_STEP_ANGULAR_IMPULSE,
            ld(r, J_STEP_ANGULAR_IMPULSE) + ld(r, J_WELD_ANGULAR_IMPULSE),
          );
        }
      }
    }

    if (twoBodies) {
      st(ka, V_X, vAx);
      st(ka, V_Y, vAy);
      st(ka, W, wA);
    }
    st(kb, V_X, vBx);
    st(kb, V_Y, vBy);
    st(kb, W, wB);
  }
}
