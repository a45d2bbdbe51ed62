// The circle pairs' normals between the sub-step passes: the one source (built into the kernel
// with the contact passes, contact-kernel.ts, by scripts/contact-kernel-build.ts).
import {
  BASE_SEPARATION,
  CENTER_DX,
  CENTER_DY,
  DP_X,
  DP_Y,
  INV_I_A,
  INV_I_B,
  INV_MASS_A,
  INV_MASS_B,
  NORMAL_MASS,
  NORMAL_X,
  NORMAL_Y,
  Q_C,
  Q_S,
  RADIUS_A,
  RADIUS_B,
  REF_DP_AX,
  REF_DP_AY,
  REF_DP_BX,
  REF_DP_BY,
  RN_A,
  RN_B,
  R_AX,
  R_AY,
  R_BX,
  R_BY,
  TANGENT_MASS,
} from './contact-layout';
import { constraintAt, lc, pointAt, sc } from './constraint-access';
import { ld } from './load-store';

/**
 * Points the normal of each of the `count` circle pairs listed at `pairs` (CIRCLE_PAIRS:
 * constraint indices) along the line through the two centres as they are now, with lever arms
 * along it and the separation measured exactly (|cB - cA| - rA - rB). Called at each sub-step and
 * before the relax pass: two particles then push each other only through their centres, so
 * frictionless particles never spin and the impulse's line of action is the same for both
 * (angular momentum is kept). `bodies`: the constraints' state offsets (CONSTRAINT_BODIES).
 */
export function refreshCirclePairs(
  constraints: usize,
  bodies: usize,
  pairs: usize,
  count: i32,
  states: usize,
): void {
  for (let k = 0; k < count; k++) {
    const i = load<i32>(pairs + ((<usize>k) << 2));
    const c = constraintAt(constraints, i);
    const a = states + ((<usize>load<i32>(bodies + ((<usize>i) << 3))) << 3);
    const b = states + ((<usize>load<i32>(bodies + ((<usize>i) << 3), 4)) << 3);
    const dpAx = ld(a, DP_X);
    const dpAy = ld(a, DP_Y);
    const dpBx = ld(b, DP_X);
    const dpBy = ld(b, DP_Y);
    const dx = lc(c, CENTER_DX) + dpBx - dpAx;
    const dy = lc(c, CENTER_DY) + dpBy - dpAy;
    const length = Math.sqrt(dx * dx + dy * dy);
    if (!(length > 1e-12)) continue; // coincident centres: keep the last normal
    const nx = dx / length;
    const ny = dy / length;
    const radiusA = lc(c, RADIUS_A);
    const radiusB = lc(c, RADIUS_B);
    // Both arms end at the same point, midway across the gap (or overlap), so that a friction
    // impulse too acts on one line for both particles.
    const halfGap = 0.5 * (length - radiusA - radiusB);
    const armA = radiusA + halfGap;
    const armB = radiusB + halfGap;
    const rAx = nx * armA;
    const rAy = ny * armA;
    const rBx = -nx * armB;
    const rBy = -ny * armB;
    sc(c, NORMAL_X, nx);
    sc(c, NORMAL_Y, ny);
    sc(c, REF_DP_AX, dpAx);
    sc(c, REF_DP_AY, dpAy);
    sc(c, REF_DP_BX, dpBx);
    sc(c, REF_DP_BY, dpBy);
    const p = pointAt(c, 0);
    sc(p, R_AX, rAx);
    sc(p, R_AY, rAy);
    sc(p, R_BX, rBx);
    sc(p, R_BY, rBy);
    // Along the line of centres: no arm across n.
    sc(p, RN_A, 0);
    sc(p, RN_B, 0);
    // Baseline such that the solver's separation formula gives the exact gap now.
    const qAc = ld(a, Q_C);
    const qAs = ld(a, Q_S);
    const qBc = ld(b, Q_C);
    const qBs = ld(b, Q_S);
    const gx = dpBx - dpAx + (qBc * rBx - qBs * rBy) - (qAc * rAx - qAs * rAy);
    const gy = dpBy - dpAy + (qBs * rBx + qBc * rBy) - (qAs * rAx + qAc * rAy);
    sc(p, BASE_SEPARATION, length - radiusA - radiusB - (gx * nx + gy * ny));
    const mA = lc(c, INV_MASS_A);
    const mB = lc(c, INV_MASS_B);
    const kNormal = mA + mB;
    sc(p, NORMAL_MASS, kNormal > 0 ? 1 / kNormal : 0);
    const kTangent = kNormal + lc(c, INV_I_A) * armA * armA + lc(c, INV_I_B) * armB * armB;
    sc(p, TANGENT_MASS, kTangent > 0 ? 1 / kTangent : 0);
  }
}
