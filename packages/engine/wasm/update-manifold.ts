// The narrow phase in full for one contact (issue #30: ported from src/dynamics/contact.ts, whose
// collide functions it calls in wasm/collide-*.ts): the manifold of the two shapes' geometry rows
// (SHAPE_GEOMETRY, src/dynamics/shape-geometry.ts) at their bodies' poses (the BODIES region, read
// in place), written into the contact's slot (CONTACT_DATA, contact-data.ts) with last step's
// impulses carried over by feature id. Like the other passes it is one source built to
// WebAssembly and by wasm2js to JavaScript (scripts/contact-kernel-build.ts), f64 operations in
// the order the TypeScript had them, so the regression hashes did not move.
import {
  BODY_STRIDE,
  B_C,
  B_CENTER_X,
  B_CENTER_Y,
  B_LOCAL_CENTER_X,
  B_LOCAL_CENTER_Y,
  B_S,
  B_VX,
  B_VY,
  B_W,
  B_X,
  B_Y,
  CONTACT_STRIDE,
  C_CACHE,
  C_HAS_CACHE,
  C_ID,
  C_MAX_NORMAL_IMPULSE,
  C_NORMAL_IMPULSE,
  C_NORMAL_X,
  C_NORMAL_Y,
  C_POINTS,
  C_POINT_COUNT,
  C_POINT_STRIDE,
  C_RADIUS_A,
  C_RADIUS_B,
  C_SEPARATION,
  C_STEP_NORMAL_IMPULSE,
  C_STEP_TANGENT_IMPULSE,
  C_TANGENT_IMPULSE,
  C_X,
  C_Y,
  GEOMETRY_CIRCLE,
  GEOMETRY_STRIDE,
  G_KIND,
  G_RADIUS,
  G_VERTICES,
  MP_ID,
  MP_SEPARATION,
  MP_X,
  MP_Y,
  M_NORMAL_X,
  M_NORMAL_Y,
  M_SPECULATIVE_DISTANCE,
  PAIR_CAPSULES,
  PAIR_CAPSULE_CIRCLE,
  PAIR_CIRCLES,
  PAIR_POLYGONS,
  PAIR_POLYGON_CAPSULE,
  PAIR_POLYGON_CIRCLE,
  PAIR_SEGMENT_CIRCLE,
  PAIR_SEGMENT_POLYGON,
  SPECULATIVE_DISTANCE,
  S_TRANSFORM_A,
  S_TRANSFORM_B,
} from './contact-layout';
import { collideCapsuleAndCircle } from './collide-capsule-circle';
import { collideCapsules } from './collide-capsules';
import { collideCircles } from './collide-circles';
import { collidePolygonAndCapsule } from './collide-polygon-capsule';
import { collidePolygonAndCircle } from './collide-polygon-circle';
import { collidePolygons } from './collide-polygons';
import { collideSegmentAndCapsule } from './collide-segment-capsule';
import { collideSegmentAndCircle } from './collide-segment-circle';
import { collideSegmentAndPolygon } from './collide-segment-polygon';
import { ld, st } from './load-store';
import { pointAt, pointCountOf, setPointCount } from './manifold';

/** Runs the collide function of pair kind `kind` into the manifold at `m`. */
function collide(kind: i32, a: usize, xfA: usize, b: usize, xfB: usize, m: usize): void {
  switch (kind) {
    case PAIR_CIRCLES:
      collideCircles(a, xfA, b, xfB, m);
      break;
    case PAIR_POLYGON_CIRCLE:
      collidePolygonAndCircle(a, xfA, b, xfB, m);
      break;
    case PAIR_POLYGONS:
      collidePolygons(a, xfA, b, xfB, m);
      break;
    case PAIR_SEGMENT_CIRCLE:
      collideSegmentAndCircle(a, xfA, b, xfB, m);
      break;
    case PAIR_SEGMENT_POLYGON:
      collideSegmentAndPolygon(a, xfA, b, xfB, m);
      break;
    case PAIR_CAPSULE_CIRCLE:
      collideCapsuleAndCircle(a, xfA, b, xfB, m);
      break;
    case PAIR_CAPSULES:
      collideCapsules(a, xfA, b, xfB, m);
      break;
    case PAIR_POLYGON_CAPSULE:
      collidePolygonAndCapsule(a, xfA, b, xfB, m);
      break;
    default:
      collideSegmentAndCapsule(a, xfA, b, xfB, m);
      break;
  }
}

/** Whether pair kind `kind` has a circle as shape B. */
function circleB(kind: i32): bool {
  return (
    kind == PAIR_CIRCLES ||
    kind == PAIR_POLYGON_CIRCLE ||
    kind == PAIR_SEGMENT_CIRCLE ||
    kind == PAIR_CAPSULE_CIRCLE
  );
}

/**
 * Narrow phase in full for contact slot `slot` (pair kind `kind`) of the contact data at `data`:
 * recomputes the manifold of shapes `shapeA` and `shapeB` (rows of the geometry at `geometry`)
 * at the poses of bodies `bodyA` and `bodyB` (world indices into `bodies`) into the slot, and
 * carries the accumulated impulses over to points with the same feature id; `m` is the
 * narrow-phase scratch. Returns the number of points (the contact touches when it is not 0).
 * The contact manager's gates (contact-manager.ts) ran first and pass what they computed: the
 * margin (m), the reach (m) and B's pose in A's frame (relX, relY, relC, relS), kept for the next
 * step's reuse test.
 *
 * Speculative contacts (Catto, "Speculative contacts", 2013): a point is kept while the gap is
 * under SPECULATIVE_DISTANCE, or while the shapes approach fast enough to close the gap within
 * this step of `dt` seconds; the solver then lets them close exactly the gap and no more. So a
 * ball falling at 14 m/s stops at the floor's surface instead of sinking 0.2 m into it, and a
 * body only passing by a corner gets no point (no "ghost" collision), because it does not
 * approach along that point's normal.
 */
export function updateManifold(
  data: usize,
  bodies: usize,
  geometry: usize,
  m: usize,
  slot: i32,
  kind: i32,
  shapeA: i32,
  shapeB: i32,
  bodyA: i32,
  bodyB: i32,
  dt: f64,
  margin: f64,
  reach: f64,
  relX: f64,
  relY: f64,
  relC: f64,
  relS: f64,
): i32 {
  const base = data + ((<usize>(slot * CONTACT_STRIDE)) << 3);
  const pa = bodies + ((<usize>(bodyA * BODY_STRIDE)) << 3);
  const pb = bodies + ((<usize>(bodyB * BODY_STRIDE)) << 3);
  const a = geometry + ((<usize>(shapeA * GEOMETRY_STRIDE)) << 3);
  const b = geometry + ((<usize>(shapeB * GEOMETRY_STRIDE)) << 3);
  st(m, M_SPECULATIVE_DISTANCE, margin);
  // Functions that find no point may return without a normal: clear the one the last call left,
  // so the slot holds the same numbers in a copy restored from a snapshot.
  st(m, M_NORMAL_X, 0);
  st(m, M_NORMAL_Y, 0);
  // A body's pose (x, y, cos, sin) is its transform: read in place.
  collide(kind, a, pa, b, pb, m);
  if (reach > 0 && kind != PAIR_CIRCLES && hasFarPoint(m)) dropPassingPoints(m, pa, pb, dt);
  // The solver pushes particles along their line of centres (see contact-solver.ts). Read
  // here, not when the contact starts, because adding a shape can move a centre of mass.
  if (kind == PAIR_CIRCLES) st(base, C_RADIUS_A, centredCircleRadius(a, pa));
  if (circleB(kind)) st(base, C_RADIUS_B, centredCircleRadius(b, pb));

  // Carry the impulses of last step's points over to the new points with the same feature.
  const p0 = base + ((<usize>C_POINTS) << 3);
  const p1 = p0 + ((<usize>C_POINT_STRIDE) << 3);
  const oldCount = ld(base, C_POINT_COUNT);
  const id0 = ld(p0, C_ID);
  const id1 = ld(p1, C_ID);
  const normal0 = ld(p0, C_NORMAL_IMPULSE);
  const tangent0 = ld(p0, C_TANGENT_IMPULSE);
  const normal1 = ld(p1, C_NORMAL_IMPULSE);
  const tangent1 = ld(p1, C_TANGENT_IMPULSE);
  const count = pointCountOf(m);
  st(base, C_NORMAL_X, ld(m, M_NORMAL_X));
  st(base, C_NORMAL_Y, ld(m, M_NORMAL_Y));
  st(base, C_POINT_COUNT, <f64>count);
  for (let i: i32 = 0; i < count; i++) {
    const mp = pointAt(m, i);
    const p = p0 + ((<usize>(i * C_POINT_STRIDE)) << 3);
    const id = ld(mp, MP_ID);
    st(p, C_X, ld(mp, MP_X));
    st(p, C_Y, ld(mp, MP_Y));
    st(p, C_SEPARATION, ld(mp, MP_SEPARATION));
    st(p, C_ID, id);
    let normal: f64 = 0;
    let tangent: f64 = 0;
    if (oldCount > 0 && id == id0) {
      normal = normal0;
      tangent = tangent0;
    } else if (oldCount > 1 && id == id1) {
      normal = normal1;
      tangent = tangent1;
    }
    st(p, C_NORMAL_IMPULSE, normal);
    st(p, C_TANGENT_IMPULSE, tangent);
    st(p, C_MAX_NORMAL_IMPULSE, 0);
    st(p, C_STEP_NORMAL_IMPULSE, 0);
    st(p, C_STEP_TANGENT_IMPULSE, 0);
  }
  // B's pose in A's frame, for the next step's reuse test.
  st(base, C_CACHE, relX);
  st(base, C_CACHE + 1, relY);
  st(base, C_CACHE + 2, relC);
  st(base, C_CACHE + 3, relS);
  storeCache(base, kind, pa, pb);
  return count;
}

/** Keeps the manifold for reuse; B's pose in A's frame is already in the cache's first 4 slots. */
function storeCache(base: usize, kind: i32, xfA: usize, xfB: usize): void {
  const count = <i32>ld(base, C_POINT_COUNT);
  // Only polygon-like pairs are worth it: the circle kernels cost less than the bookkeeping.
  if (count == 0 || circleB(kind)) {
    st(base, C_HAS_CACHE, 0);
    return;
  }
  const cA = ld(xfA, B_C);
  const sA = ld(xfA, B_S);
  const cB = ld(xfB, B_C);
  const sB = ld(xfB, B_S);
  const nx = ld(base, C_NORMAL_X);
  const ny = ld(base, C_NORMAL_Y);
  for (let i: i32 = 0; i < count; i++) {
    const p = base + ((<usize>(C_POINTS + i * C_POINT_STRIDE)) << 3);
    const half = 0.5 * ld(p, C_SEPARATION);
    // Surface points: the manifold point is midway between them along the normal.
    const ax = ld(p, C_X) - half * nx - ld(xfA, B_X);
    const ay = ld(p, C_Y) - half * ny - ld(xfA, B_Y);
    const bx = ld(p, C_X) + half * nx - ld(xfB, B_X);
    const by = ld(p, C_Y) + half * ny - ld(xfB, B_Y);
    const q = C_CACHE + 4 + 4 * i;
    st(base, q, cA * ax + sA * ay);
    st(base, q + 1, -sA * ax + cA * ay);
    st(base, q + 2, cB * bx + sB * by);
    st(base, q + 3, -sB * bx + cB * by);
  }
  st(base, C_CACHE + 12, cA * nx + sA * ny);
  st(base, C_CACHE + 13, -sA * nx + cA * ny);
  st(base, C_HAS_CACHE, 1);
}

/**
 * The radius of geometry row `g` if it is a circle centred on its body's centre of mass (the
 * body's numbers at `p`), else 0.
 */
function centredCircleRadius(g: usize, p: usize): f64 {
  return <i32>ld(g, G_KIND) != GEOMETRY_CIRCLE ||
    ld(g, G_VERTICES) != ld(p, B_LOCAL_CENTER_X) ||
    ld(g, G_VERTICES + 1) != ld(p, B_LOCAL_CENTER_Y)
    ? 0
    : ld(g, G_RADIUS);
}

/** True if a point of the manifold at `m` lies as far as the speculative distance. */
function hasFarPoint(m: usize): bool {
  const count = pointCountOf(m);
  for (let i: i32 = 0; i < count; i++) {
    if (ld(pointAt(m, i), MP_SEPARATION) >= SPECULATIVE_DISTANCE) return true;
  }
  return false;
}

/**
 * Keeps far speculative points only where the bodies (numbers at `pa` and `pb`) approach along
 * the normal fast enough.
 */
function dropPassingPoints(m: usize, pa: usize, pb: usize, dt: f64): void {
  const nx = ld(m, M_NORMAL_X);
  const ny = ld(m, M_NORMAL_Y);
  const count = pointCountOf(m);
  let kept: i32 = 0;
  for (let i: i32 = 0; i < count; i++) {
    const p = pointAt(m, i);
    const separation = ld(p, MP_SEPARATION);
    const x = ld(p, MP_X);
    const y = ld(p, MP_Y);
    if (separation >= SPECULATIVE_DISTANCE) {
      const wA = ld(pa, B_W);
      const wB = ld(pb, B_W);
      const vx =
        ld(pb, B_VX) -
        wB * (y - ld(pb, B_CENTER_Y)) -
        (ld(pa, B_VX) - wA * (y - ld(pa, B_CENTER_Y)));
      const vy =
        ld(pb, B_VY) +
        wB * (x - ld(pb, B_CENTER_X)) -
        (ld(pa, B_VY) + wA * (x - ld(pa, B_CENTER_X)));
      const approach = -(vx * nx + vy * ny) * dt;
      if (separation >= SPECULATIVE_DISTANCE + 1.5 * approach) continue;
    }
    if (kept != i) {
      const to = pointAt(m, kept);
      st(to, MP_X, x);
      st(to, MP_Y, y);
      st(to, MP_SEPARATION, separation);
      st(to, MP_ID, ld(p, MP_ID));
    }
    kept++;
  }
  setPointCount(m, kept);
}

/**
 * For tests: runs the collide function of pair kind `kind` on geometry rows `a` and `b` at the
 * transforms in the scratch (S_TRANSFORM_A, S_TRANSFORM_B: x, y, cos, sin) with speculative
 * distance `speculativeDistance`, leaving the manifold in the scratch at `m`.
 */
export function collidePair(
  kind: i32,
  a: usize,
  b: usize,
  m: usize,
  speculativeDistance: f64,
): void {
  st(m, M_SPECULATIVE_DISTANCE, speculativeDistance);
  st(m, M_NORMAL_X, 0);
  st(m, M_NORMAL_Y, 0);
  const xfA = m + ((<usize>S_TRANSFORM_A) << 3);
  const xfB = m + ((<usize>S_TRANSFORM_B) << 3);
  collide(kind, a, xfA, b, xfB, m);
}
