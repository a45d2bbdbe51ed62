import { collideCapsuleAndCircle } from '../collision/collide-capsule-circle.ts';
import { collideCapsules } from '../collision/collide-capsules.ts';
import { collideCircles } from '../collision/collide-circles.ts';
import { collidePolygonAndCapsule } from '../collision/collide-polygon-capsule.ts';
import { collidePolygonAndCircle } from '../collision/collide-polygon-circle.ts';
import { collidePolygons } from '../collision/collide-polygons.ts';
import { collideSegmentAndCapsule } from '../collision/collide-segment-capsule.ts';
import { collideSegmentAndCircle } from '../collision/collide-segment-circle.ts';
import { collideSegmentAndPolygon } from '../collision/collide-segment-polygon.ts';
import { Manifold, type ManifoldPoint } from '../collision/manifold.ts';
import { SPECULATIVE_DISTANCE } from '../core/constants.ts';
import type { Capsule } from '../geometry/capsule.ts';
import type { Circle } from '../geometry/circle.ts';
import type { Polygon } from '../geometry/polygon.ts';
import type { Segment } from '../geometry/segment.ts';
import { Transform } from '../math/transform.ts';
import {
  B_CENTER_X,
  B_CENTER_Y,
  B_LOCAL_CENTER_X,
  B_LOCAL_CENTER_Y,
  B_VX,
  B_VY,
  B_W,
} from './body-memory.ts';
import {
  CACHE,
  CONTACT_STRIDE,
  FRICTION,
  HAS_CACHE,
  NORMAL_X,
  NORMAL_Y,
  POINT_COUNT,
  POINT_STRIDE,
  POINTS,
  P_ID,
  P_MAX_NORMAL_IMPULSE,
  P_NORMAL_IMPULSE,
  P_SEPARATION,
  P_STEP_NORMAL_IMPULSE,
  P_STEP_TANGENT_IMPULSE,
  P_TANGENT_IMPULSE,
  P_X,
  P_Y,
  RADIUS_A,
  RADIUS_B,
  RESTITUTION,
} from './contact-data.ts';
import type { Geometry, Shape } from './shape.ts';

// The narrow-phase table: which collide function handles a pair of shape kinds, with shape A the
// higher-ranked kind (segment > polygon > capsule > circle). One switch here instead of
// registration by import side effects.
const PAIR_CIRCLES = 0;
const PAIR_POLYGON_CIRCLE = 1;
const PAIR_POLYGONS = 2;
const PAIR_SEGMENT_CIRCLE = 3;
const PAIR_SEGMENT_POLYGON = 4;
const PAIR_CAPSULE_CIRCLE = 5;
const PAIR_CAPSULES = 6;
const PAIR_POLYGON_CAPSULE = 7;
const PAIR_SEGMENT_CAPSULE = 8;

const KIND_RANK = { circle: 0, capsule: 1, polygon: 2, segment: 3 } as const;

/** True if two shapes can ever collide (segments never collide with segments). */
export function canCollide(a: Shape, b: Shape): boolean {
  return !(a.geometry.kind === 'segment' && b.geometry.kind === 'segment');
}

/** Orders a pair so that shape A has the higher-ranked kind; returns true if the pair must be swapped. */
export function shouldSwap(a: Shape, b: Shape): boolean {
  return KIND_RANK[a.geometry.kind] < KIND_RANK[b.geometry.kind];
}

/**
 * Sets up contact slot `slot` of `data` for a new pair (a and b already ordered, see shouldSwap),
 * whose numbers the caller has cleared: mixes the materials. Returns the pair kind (which collide
 * function applies). A contact is its slot: its shapes, bodies and kind are in the contact data's
 * flat arrays (contact-data.ts) and its place in each body's contact list in the contact edges
 * (contact-edges.ts); no object stands for it.
 */
export function initContactSlot(slot: number, a: Shape, b: Shape, data: Float64Array): number {
  const base = slot * CONTACT_STRIDE;
  data[base + FRICTION] = Math.sqrt(a.friction * b.friction);
  data[base + RESTITUTION] = Math.max(a.restitution, b.restitution);
  const kindA = a.geometry.kind;
  const kindB = b.geometry.kind;
  if (kindA === 'circle') return PAIR_CIRCLES;
  if (kindA === 'capsule') return kindB === 'circle' ? PAIR_CAPSULE_CIRCLE : PAIR_CAPSULES;
  if (kindA === 'polygon') {
    return kindB === 'circle'
      ? PAIR_POLYGON_CIRCLE
      : kindB === 'capsule'
        ? PAIR_POLYGON_CAPSULE
        : PAIR_POLYGONS;
  }
  return kindB === 'circle'
    ? PAIR_SEGMENT_CIRCLE
    : kindB === 'capsule'
      ? PAIR_SEGMENT_CAPSULE
      : PAIR_SEGMENT_POLYGON;
}

/**
 * Narrow phase in full for contact slot `slot`: recomputes the manifold of geometries `a` and `b`
 * (pair kind `kind`) at the transforms in {@link gateTransformA} and {@link gateTransformB} into
 * the slot of `data`, and carries the accumulated impulses over to points with the same feature
 * id. Returns the number of points (the contact touches when it is not 0). The contact manager's
 * gates (contact-manager.ts) ran first: the shapes are within the margin in
 * {@link narrowPhaseGate}, and the manifold could not be reused. The bodies' numbers are read in
 * place in the body memory `pose` at offsets `pa` and `pb` (body-memory.ts), for circle pairs and
 * far speculative points only.
 *
 * Speculative contacts (Catto, "Speculative contacts", 2013): a point is kept while the gap is
 * under SPECULATIVE_DISTANCE, or while the shapes approach fast enough to close the gap within
 * this step of `dt` seconds; the solver then lets them close exactly the gap and no more. So a
 * ball falling at 14 m/s stops at the floor's surface instead of sinking 0.2 m into it, and a
 * body only passing by a corner gets no point (no "ghost" collision), because it does not
 * approach along that point's normal.
 */
export function updateManifold(
  slot: number,
  kind: number,
  a: Geometry,
  b: Geometry,
  dt: number,
  data: Float64Array,
  pose: Float64Array,
  pa: number,
  pb: number,
): number {
  const base = slot * CONTACT_STRIDE;
  const gate = narrowPhaseGate;
  const margin = gate[GATE_MARGIN]!;
  const reach = gate[GATE_REACH]!;
  const xfA = gateTransformA;
  const xfB = gateTransformB;
  const k = base + CACHE;
  const p0 = base + POINTS;
  const p1 = p0 + POINT_STRIDE;
  const m = scratch;
  m.speculativeDistance = margin;
  // Kernels that find no point may return without a normal: clear the one the last call (of
  // any world: the manifold is shared) left, so the slot holds the same numbers in a copy
  // restored from a snapshot.
  m.normalX = 0;
  m.normalY = 0;
  switch (kind) {
    case PAIR_CIRCLES:
      collideCircles(a as Circle, xfA, b as Circle, xfB, m);
      break;
    case PAIR_POLYGON_CIRCLE:
      collidePolygonAndCircle(a as Polygon, xfA, b as Circle, xfB, m);
      break;
    case PAIR_POLYGONS:
      collidePolygons(a as Polygon, xfA, b as Polygon, xfB, m);
      break;
    case PAIR_SEGMENT_CIRCLE:
      collideSegmentAndCircle(a as Segment, xfA, b as Circle, xfB, m);
      break;
    case PAIR_SEGMENT_POLYGON:
      collideSegmentAndPolygon(a as Segment, xfA, b as Polygon, xfB, m);
      break;
    case PAIR_CAPSULE_CIRCLE:
      collideCapsuleAndCircle(a as Capsule, xfA, b as Circle, xfB, m);
      break;
    case PAIR_CAPSULES:
      collideCapsules(a as Capsule, xfA, b as Capsule, xfB, m);
      break;
    case PAIR_POLYGON_CAPSULE:
      collidePolygonAndCapsule(a as Polygon, xfA, b as Capsule, xfB, m);
      break;
    default:
      collideSegmentAndCapsule(a as Segment, xfA, b as Capsule, xfB, m);
      break;
  }
  if (reach > 0 && kind !== PAIR_CIRCLES && hasFarPoint(m)) dropPassingPoints(m, pose, pa, pb, dt);
  // The solver pushes particles along their line of centres (see contact-solver.ts). Read
  // here, not when the contact starts, because adding a shape can move a centre of mass.
  if (kind === PAIR_CIRCLES) writeCentredCircleRadius(data, base + RADIUS_A, a, pose, pa);
  if (
    kind === PAIR_CIRCLES ||
    kind === PAIR_POLYGON_CIRCLE ||
    kind === PAIR_SEGMENT_CIRCLE ||
    kind === PAIR_CAPSULE_CIRCLE
  ) {
    writeCentredCircleRadius(data, base + RADIUS_B, b, pose, pb);
  }

  // Carry the impulses of last step's points over to the new points with the same feature.
  const oldCount = data[base + POINT_COUNT]!;
  const id0 = data[p0 + P_ID]!;
  const id1 = data[p1 + P_ID]!;
  const normal0 = data[p0 + P_NORMAL_IMPULSE]!;
  const tangent0 = data[p0 + P_TANGENT_IMPULSE]!;
  const normal1 = data[p1 + P_NORMAL_IMPULSE]!;
  const tangent1 = data[p1 + P_TANGENT_IMPULSE]!;
  data[base + NORMAL_X] = m.normalX;
  data[base + NORMAL_Y] = m.normalY;
  data[base + POINT_COUNT] = m.pointCount;
  for (let i = 0; i < m.pointCount; i++) {
    const mp = m.points[i]!;
    const p = p0 + i * POINT_STRIDE;
    data[p + P_X] = mp.x;
    data[p + P_Y] = mp.y;
    data[p + P_SEPARATION] = mp.separation;
    data[p + P_ID] = mp.id;
    let normal = 0;
    let tangent = 0;
    if (oldCount > 0 && mp.id === id0) {
      normal = normal0;
      tangent = tangent0;
    } else if (oldCount > 1 && mp.id === id1) {
      normal = normal1;
      tangent = tangent1;
    }
    data[p + P_NORMAL_IMPULSE] = normal;
    data[p + P_TANGENT_IMPULSE] = tangent;
    data[p + P_MAX_NORMAL_IMPULSE] = 0;
    data[p + P_STEP_NORMAL_IMPULSE] = 0;
    data[p + P_STEP_TANGENT_IMPULSE] = 0;
  }
  // B's pose in A's frame, for the next step's reuse test.
  data[k] = gate[GATE_REL_X]!;
  data[k + 1] = gate[GATE_REL_Y]!;
  data[k + 2] = gate[GATE_REL_C]!;
  data[k + 3] = gate[GATE_REL_S]!;
  storeCache(data, base, kind, xfA, xfB);
  return m.pointCount;
}

/** Keeps the manifold for reuse; B's pose in A's frame is already in the cache's first 4 slots. */
function storeCache(
  data: Float64Array,
  base: number,
  kind: number,
  xfA: Transform,
  xfB: Transform,
): void {
  const count = data[base + POINT_COUNT]!;
  // Only polygon-like pairs are worth it: the circle kernels cost less than the bookkeeping.
  if (
    count === 0 ||
    kind === PAIR_CIRCLES ||
    kind === PAIR_POLYGON_CIRCLE ||
    kind === PAIR_SEGMENT_CIRCLE ||
    kind === PAIR_CAPSULE_CIRCLE
  ) {
    data[base + HAS_CACHE] = 0;
    return;
  }
  const k = base + CACHE;
  const nx = data[base + NORMAL_X]!;
  const ny = data[base + NORMAL_Y]!;
  for (let i = 0; i < count; i++) {
    const p = base + POINTS + i * POINT_STRIDE;
    const half = 0.5 * data[p + P_SEPARATION]!;
    // Surface points: the manifold point is midway between them along the normal.
    const ax = data[p + P_X]! - half * nx - xfA.x;
    const ay = data[p + P_Y]! - half * ny - xfA.y;
    const bx = data[p + P_X]! + half * nx - xfB.x;
    const by = data[p + P_Y]! + half * ny - xfB.y;
    const q = k + 4 + 4 * i;
    data[q] = xfA.c * ax + xfA.s * ay;
    data[q + 1] = -xfA.s * ax + xfA.c * ay;
    data[q + 2] = xfB.c * bx + xfB.s * by;
    data[q + 3] = -xfB.s * bx + xfB.c * by;
  }
  data[k + 12] = xfA.c * nx + xfA.s * ny;
  data[k + 13] = -xfA.s * nx + xfA.c * ny;
  data[base + HAS_CACHE] = 1;
}

/**
 * Writes the radius of circle geometry `g` if it is centred on its body's centre of mass (the
 * body's stride at `p` of the body memory), else 0, to data[at].
 */
function writeCentredCircleRadius(
  data: Float64Array,
  at: number,
  g: Geometry,
  pose: Float64Array,
  p: number,
): void {
  // Written in place rather than returned: V8 boxes a fractional return value of a call it does
  // not inline, and this runs per circle contact per step.
  data[at] =
    g.kind !== 'circle' ||
    g.centerX !== pose[p + B_LOCAL_CENTER_X] ||
    g.centerY !== pose[p + B_LOCAL_CENTER_Y]
      ? 0
      : g.radius;
}

/** The narrow phase's output before it is copied into a contact's slot (one step at a time). */
const scratch = new Manifold();

// What the contact manager's gates computed for the contact it hands to updateManifold: a scratch
// array rather than arguments, since V8 boxes fractional arguments of calls it does not inline.
export const GATE_MARGIN = 0;
export const GATE_REACH = 1;
export const GATE_REL_X = 2;
export const GATE_REL_Y = 3;
export const GATE_REL_C = 4;
export const GATE_REL_S = 5;
/** @internal The margin (m), the reach (m) and B's pose in A's frame (x, y, cos, sin). */
export const narrowPhaseGate = new Float64Array(6);
/** @internal The transforms of body A and body B of that contact. */
export const gateTransformA: Transform = new Transform();
export const gateTransformB: Transform = new Transform();

/** True if a point of `m` lies as far as the speculative distance (dropPassingPoints' work). */
function hasFarPoint(m: Manifold): boolean {
  for (let i = 0; i < m.pointCount; i++) {
    if (m.points[i]!.separation >= SPECULATIVE_DISTANCE) return true;
  }
  return false;
}

/**
 * Keeps far speculative points only where the bodies (strides `pa` and `pb` of the body memory
 * `pose`) approach along the normal fast enough.
 */
function dropPassingPoints(
  m: Manifold,
  pose: Float64Array,
  pa: number,
  pb: number,
  dt: number,
): void {
  const nx = m.normalX;
  const ny = m.normalY;
  let kept = 0;
  for (let i = 0; i < m.pointCount; i++) {
    const p = m.points[i]!;
    if (p.separation >= SPECULATIVE_DISTANCE) {
      const wA = pose[pa + B_W]!;
      const wB = pose[pb + B_W]!;
      const vx =
        pose[pb + B_VX]! -
        wB * (p.y - pose[pb + B_CENTER_Y]!) -
        (pose[pa + B_VX]! - wA * (p.y - pose[pa + B_CENTER_Y]!));
      const vy =
        pose[pb + B_VY]! +
        wB * (p.x - pose[pb + B_CENTER_X]!) -
        (pose[pa + B_VY]! + wA * (p.x - pose[pa + B_CENTER_X]!));
      const approach = -(vx * nx + vy * ny) * dt;
      if (p.separation >= SPECULATIVE_DISTANCE + 1.5 * approach) continue;
    }
    if (kept !== i) copyGeometry(m.points[kept]!, p);
    kept++;
  }
  m.pointCount = kept;
}

function copyGeometry(to: ManifoldPoint, from: ManifoldPoint): void {
  to.x = from.x;
  to.y = from.y;
  to.anchorAX = from.anchorAX;
  to.anchorAY = from.anchorAY;
  to.anchorBX = from.anchorBX;
  to.anchorBY = from.anchorBY;
  to.separation = from.separation;
  to.id = from.id;
}
