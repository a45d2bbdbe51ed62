// The narrow phase's gates (issue #30: ported from ContactManager.collide's loop, whose order it
// keeps): over the contact slots from `from`, each decided from numbers in place (the bodies' in
// BODIES, the shapes' boxes in SHAPE_BOXES, the slot's own in CONTACT_DATA) and, where no gate
// settles it, its manifold recomputed (update-manifold.ts). It stops at the first slot whose
// outcome needs the TypeScript side's objects, and says why in GATE_ACTION of the narrow-phase
// scratch: the contact ends (GATE_DESTROY: its fat boxes parted and its shapes are more than
// KEEP_GAP apart), or it stopped (GATE_END) or started (GATE_BEGIN) touching. The contact manager
// does that work (destroying moves the last slot into this one; a begin wakes the bodies' islands,
// which later slots must see) and runs the pass again from there, so every slot is decided in the
// order and with the state the TypeScript loop had.
import {
  BODY_STRIDE,
  B_AWAKE,
  B_C,
  B_MAX_EXTENT,
  B_ORIGIN_REACH,
  B_S,
  B_VX,
  B_VY,
  B_W,
  B_X,
  B_Y,
  CONTACT_STRIDE,
  C_CACHE,
  C_HAS_CACHE,
  C_MAX_NORMAL_IMPULSE,
  C_NORMAL_X,
  C_NORMAL_Y,
  C_POINTS,
  C_POINT_COUNT,
  C_POINT_STRIDE,
  C_SEPARATION,
  C_STEP_NORMAL_IMPULSE,
  C_STEP_TANGENT_IMPULSE,
  C_X,
  C_Y,
  GATE_ACTION,
  GATE_BEGIN,
  GATE_DESTROY,
  GATE_END,
  KEEP_GAP,
  REUSE_TOLERANCE_SQUARED,
  SHAPE_STRIDE,
  SPECULATIVE_DISTANCE,
} from './contact-layout';
import { ld, st } from './load-store';
import { updateManifold } from './update-manifold';

/** Where the numbers of world index `index` start (`stride` doubles each) in the region at `p`. */
function row(p: usize, index: i32, stride: i32): usize {
  return p + ((<usize>(index * stride)) << 3);
}

/** Int32 number k of the list at `p`. */
function int(p: usize, k: i32): i32 {
  return load<i32>(p + ((<usize>k) << 2));
}

/**
 * Runs the gates over contact slots `from` to `count` - 1; returns the first slot that needs the
 * contact manager (GATE_ACTION in the scratch `m` says why), or `count`. Regions: the contact data
 * (`data`), each slot's body world indices (`slotBodies`), shape ids (`slotShapes`) and pair kind
 * (`kinds`), the bodies' numbers (`bodies`), the shapes' boxes (`boxes`, shape-table.ts: tight box
 * 0-3, fat box 4-7) and geometry rows (`geometry`).
 */
export function collideContacts(
  data: usize,
  slotBodies: usize,
  slotShapes: usize,
  kinds: usize,
  bodies: usize,
  boxes: usize,
  geometry: usize,
  m: usize,
  from: i32,
  count: i32,
  dt: f64,
): i32 {
  for (let i = from; i < count; i++) {
    const bodyA = int(slotBodies, 2 * i);
    const bodyB = int(slotBodies, 2 * i + 1);
    const pa = row(bodies, bodyA, BODY_STRIDE);
    const pb = row(bodies, bodyB, BODY_STRIDE);
    if (ld(pa, B_AWAKE) == 0 && ld(pb, B_AWAKE) == 0) continue;
    const shapeA = int(slotShapes, 2 * i);
    const shapeB = int(slotShapes, 2 * i + 1);
    const sa = row(boxes, shapeA, SHAPE_STRIDE);
    const sb = row(boxes, shapeB, SHAPE_STRIDE);
    // Parted fat boxes end the contact only once the shapes' tight boxes are also apart by more
    // than KEEP_GAP (see contact-gates.ts): re-fattening often parts and joins a pair again.
    if (
      !(
        ld(sa, 4) <= ld(sb, 6) &&
        ld(sb, 4) <= ld(sa, 6) &&
        ld(sa, 5) <= ld(sb, 7) &&
        ld(sb, 5) <= ld(sa, 7)
      ) &&
      (ld(sa, 0) - KEEP_GAP > ld(sb, 2) ||
        ld(sb, 0) - KEEP_GAP > ld(sa, 2) ||
        ld(sa, 1) - KEEP_GAP > ld(sb, 3) ||
        ld(sb, 1) - KEEP_GAP > ld(sa, 3))
    ) {
      st(m, GATE_ACTION, GATE_DESTROY);
      return i;
    }
    const base = row(data, i, CONTACT_STRIDE);
    // Bound on how much the gap can close this step: relative speed plus rotation at the rim.
    const dvx = ld(pb, B_VX) - ld(pa, B_VX);
    const dvy = ld(pb, B_VY) - ld(pa, B_VY);
    // Rotation at the rim: |angular velocity| times the farthest point from the centre of mass.
    const spinA = abs<f64>(ld(pa, B_W)) * ld(pa, B_MAX_EXTENT);
    const spinB = abs<f64>(ld(pb, B_W)) * ld(pb, B_MAX_EXTENT);
    const reach = dt * (Math.sqrt(dvx * dvx + dvy * dvy) + spinA + spinB);
    const margin = SPECULATIVE_DISTANCE + reach;
    // Most pairs whose fat boxes overlap are nowhere near touching: their tight boxes settle it.
    if (
      ld(sa, 0) - margin > ld(sb, 2) ||
      ld(sb, 0) - margin > ld(sa, 2) ||
      ld(sa, 1) - margin > ld(sb, 3) ||
      ld(sb, 1) - margin > ld(sa, 3)
    ) {
      // A contact touches exactly when its slot holds points.
      const wasTouching = ld(base, C_POINT_COUNT) != 0;
      st(base, C_POINT_COUNT, 0);
      st(base, C_HAS_CACHE, 0);
      if (wasTouching) {
        st(m, GATE_ACTION, GATE_END);
        return i;
      }
      continue;
    }
    // B's pose in A's frame.
    const cA = ld(pa, B_C);
    const sA = ld(pa, B_S);
    const cB = ld(pb, B_C);
    const sB = ld(pb, B_S);
    const relC = cA * cB + sA * sB;
    const relS = cA * sB - sA * cB;
    const ox = ld(pb, B_X) - ld(pa, B_X);
    const oy = ld(pb, B_Y) - ld(pa, B_Y);
    const relX = cA * ox + sA * oy;
    const relY = -sA * ox + cA * oy;
    // Reuse: B moved relative to A by less than the reuse tolerance at any of its points since
    // the manifold was computed in full, so the same features touch and only the separations need
    // updating (the manifold reuse of Parry/Rapier).
    const k = base + ((<usize>C_CACHE) << 3);
    const dx = relX - ld(k, 0);
    const dy = relY - ld(k, 1);
    // |sin| of the rotation since then, times the farthest point of B from its own origin.
    const turn = abs<f64>(relS * ld(k, 2) - relC * ld(k, 3)) * ld(pb, B_ORIGIN_REACH);
    if (ld(base, C_HAS_CACHE) == 1 && dx * dx + dy * dy + turn * turn < REUSE_TOLERANCE_SQUARED) {
      // Move the cached surface points with their bodies and measure the gap along the normal.
      const xA = ld(pa, B_X);
      const yA = ld(pa, B_Y);
      const xB = ld(pb, B_X);
      const yB = ld(pb, B_Y);
      const nx = cA * ld(k, 12) - sA * ld(k, 13);
      const ny = sA * ld(k, 12) + cA * ld(k, 13);
      st(base, C_NORMAL_X, nx);
      st(base, C_NORMAL_Y, ny);
      const points = <i32>ld(base, C_POINT_COUNT);
      for (let j: i32 = 0; j < points; j++) {
        const q = 4 + 4 * j;
        const ax = cA * ld(k, q) - sA * ld(k, q + 1) + xA;
        const ay = sA * ld(k, q) + cA * ld(k, q + 1) + yA;
        const bx = cB * ld(k, q + 2) - sB * ld(k, q + 3) + xB;
        const by = sB * ld(k, q + 2) + cB * ld(k, q + 3) + yB;
        const p = base + ((<usize>(C_POINTS + j * C_POINT_STRIDE)) << 3);
        st(p, C_SEPARATION, (bx - ax) * nx + (by - ay) * ny);
        st(p, C_X, 0.5 * (ax + bx));
        st(p, C_Y, 0.5 * (ay + by));
      }
      for (let j: i32 = 0; j < 2; j++) {
        const p = base + ((<usize>(C_POINTS + j * C_POINT_STRIDE)) << 3);
        st(p, C_MAX_NORMAL_IMPULSE, 0);
        st(p, C_STEP_NORMAL_IMPULSE, 0);
        st(p, C_STEP_TANGENT_IMPULSE, 0);
      }
      continue;
    }
    const wasTouching = ld(base, C_POINT_COUNT) != 0;
    const touching =
      updateManifold(
        data,
        bodies,
        geometry,
        m,
        i,
        int(kinds, i),
        shapeA,
        shapeB,
        bodyA,
        bodyB,
        dt,
        margin,
        reach,
        relX,
        relY,
        relC,
        relS,
      ) > 0;
    if (touching != wasTouching) {
      st(m, GATE_ACTION, touching ? GATE_BEGIN : GATE_END);
      return i;
    }
  }
  return count;
}
