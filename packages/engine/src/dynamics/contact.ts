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
import { LINEAR_SLOP, SPECULATIVE_DISTANCE } from '../core/constants.ts';
import type { Capsule } from '../geometry/capsule.ts';
import type { Circle } from '../geometry/circle.ts';
import type { Polygon } from '../geometry/polygon.ts';
import type { Segment } from '../geometry/segment.ts';
import type { Body } from './body.ts';
import type { Shape } from './shape.ts';

// Manifolds are reused while B moved less than this relative to A (m). Motion along the normal is
// measured exactly on reuse; only sliding along the surface can leave a contact point behind its
// true place, by at most this much: half the slop, below anything the solver resolves.
const REUSE_TOLERANCE = 0.5 * LINEAR_SLOP;
const REUSE_TOLERANCE_SQUARED = REUSE_TOLERANCE * REUSE_TOLERANCE;

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
 * A potential or actual contact between two shapes whose fat boxes overlap. It lives from the
 * moment the broad phase finds the pair until the boxes separate, so its manifold's impulses carry
 * from step to step (warm starting).
 */
export class Contact {
  shapeA!: Shape;
  shapeB!: Shape;
  bodyA!: Body;
  bodyB!: Body;
  readonly manifold: Manifold = new Manifold();
  /** Mixed material: sqrt(fA fB) and max(eA, eB), as Box2D mixes them. */
  friction = 0;
  restitution = 0;
  /** Which collide function applies. */
  pairKind = 0;
  /**
   * Normal and friction impulse each manifold point delivered during the last solved step (N s):
   * the sum over the sub-steps plus restitution, for events. The manifold's own impulses are the
   * per-sub-step values kept for warm starting.
   */
  readonly stepNormalImpulse: [number, number] = [0, 0];
  readonly stepTangentImpulse: [number, number] = [0, 0];
  /** The manifold has at least one point (possibly speculative). */
  touching = false;
  /**
   * Manifold reuse: the relative pose of B in A's frame when the manifold was last computed in
   * full (x, y, cosine, sine), then per point the surface point of A in A's frame and of B in B's
   * frame (4 numbers each), then the normal in A's frame. `hasCache` says whether it is valid.
   */
  private readonly cache = new Float64Array(14);
  private hasCache = false;
  /** Distance from body B's origin to its centre of mass (m), for the reuse bound. */
  private extentB = 0;
  /** Index in the world's contact array, and in each body's contact list. */
  index = -1;
  indexInA = -1;
  indexInB = -1;

  /** Sets up a pooled contact for a new pair; a and b must already be ordered (see shouldSwap). */
  init(a: Shape, b: Shape): void {
    this.shapeA = a;
    this.shapeB = b;
    this.bodyA = a.body;
    this.bodyB = b.body;
    this.friction = Math.sqrt(a.friction * b.friction);
    this.restitution = Math.max(a.restitution, b.restitution);
    this.touching = false;
    this.hasCache = false;
    this.extentB = Math.hypot(b.body.localCenterX, b.body.localCenterY);
    this.manifold.pointCount = 0;
    this.stepNormalImpulse[0] = this.stepNormalImpulse[1] = 0;
    this.stepTangentImpulse[0] = this.stepTangentImpulse[1] = 0;
    const kindA = a.geometry.kind;
    const kindB = b.geometry.kind;
    if (kindA === 'circle') this.pairKind = PAIR_CIRCLES;
    else if (kindA === 'capsule')
      this.pairKind = kindB === 'circle' ? PAIR_CAPSULE_CIRCLE : PAIR_CAPSULES;
    else if (kindA === 'polygon')
      this.pairKind =
        kindB === 'circle'
          ? PAIR_POLYGON_CIRCLE
          : kindB === 'capsule'
            ? PAIR_POLYGON_CAPSULE
            : PAIR_POLYGONS;
    else
      this.pairKind =
        kindB === 'circle'
          ? PAIR_SEGMENT_CIRCLE
          : kindB === 'capsule'
            ? PAIR_SEGMENT_CAPSULE
            : PAIR_SEGMENT_POLYGON;
  }

  /**
   * Narrow phase: recomputes the manifold at the bodies' current transforms and carries the
   * accumulated impulses over to points with the same feature id. Returns whether it touches.
   *
   * Speculative contacts (Catto, "Speculative contacts", 2013): a point is kept while the gap is
   * under SPECULATIVE_DISTANCE, or while the shapes approach fast enough to close the gap within
   * this step of `dt` seconds; the solver then lets them close exactly the gap and no more. So a
   * ball falling at 14 m/s stops at the floor's surface instead of sinking 0.2 m into it, and a
   * body only passing by a corner gets no point (no "ghost" collision), because it does not
   * approach along that point's normal.
   */
  update(dt: number): boolean {
    const bodyA = this.bodyA;
    const bodyB = this.bodyB;
    const m = this.manifold;
    // Bound on how much the gap can close this step: relative speed plus rotation at the rim.
    const dvx = bodyB.velocityX - bodyA.velocityX;
    const dvy = bodyB.velocityY - bodyA.velocityY;
    const reach =
      dt *
      (Math.sqrt(dvx * dvx + dvy * dvy) +
        Math.abs(bodyA.angularVelocityValue) * bodyA.maxExtent +
        Math.abs(bodyB.angularVelocityValue) * bodyB.maxExtent);
    const margin = SPECULATIVE_DISTANCE + reach;
    // Most pairs whose fat boxes overlap are nowhere near touching: their tight boxes, kept
    // current by the world, settle that before anything else of the contact is read.
    const boxA = this.shapeA.aabb;
    const boxB = this.shapeB.aabb;
    if (
      boxA.minX - margin > boxB.maxX ||
      boxB.minX - margin > boxA.maxX ||
      boxA.minY - margin > boxB.maxY ||
      boxB.minY - margin > boxA.maxY
    ) {
      if (this.touching || m.pointCount > 0) {
        m.pointCount = 0;
        this.hasCache = false;
        this.touching = false;
      }
      return false;
    }

    const xfA = bodyA.transform;
    const xfB = bodyB.transform;
    // B's pose in A's frame.
    const cA = xfA.c;
    const sA = xfA.s;
    const relC = cA * xfB.c + sA * xfB.s;
    const relS = cA * xfB.s - sA * xfB.c;
    const ox = xfB.x - xfA.x;
    const oy = xfB.y - xfA.y;
    const relX = cA * ox + sA * oy;
    const relY = -sA * ox + cA * oy;
    const p0 = m.points[0];
    const p1 = m.points[1];
    if (this.hasCache && this.poseIsClose(relX, relY, relC, relS)) {
      this.refreshFromCache();
      p0.maxNormalImpulse = 0;
      p1.maxNormalImpulse = 0;
      this.stepNormalImpulse[0] = this.stepNormalImpulse[1] = 0;
      this.stepTangentImpulse[0] = this.stepTangentImpulse[1] = 0;
      return this.touching;
    }
    const oldCount = m.pointCount;
    const id0 = p0.id;
    const id1 = p1.id;
    const normal0 = p0.normalImpulse;
    const tangent0 = p0.tangentImpulse;
    const normal1 = p1.normalImpulse;
    const tangent1 = p1.tangentImpulse;
    const a = this.shapeA.geometry;
    const b = this.shapeB.geometry;
    m.speculativeDistance = margin;
    switch (this.pairKind) {
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
    if (reach > 0 && m.pointCount > 0) this.dropPassingPoints(dt);
    this.storeCache(relX, relY, relC, relS);

    for (let i = 0; i < m.pointCount; i++) {
      const p = i === 0 ? p0 : p1;
      p.normalImpulse = 0;
      p.tangentImpulse = 0;
      p.maxNormalImpulse = 0;
      if (oldCount > 0 && p.id === id0) {
        p.normalImpulse = normal0;
        p.tangentImpulse = tangent0;
      } else if (oldCount > 1 && p.id === id1) {
        p.normalImpulse = normal1;
        p.tangentImpulse = tangent1;
      }
    }
    this.stepNormalImpulse[0] = this.stepNormalImpulse[1] = 0;
    this.stepTangentImpulse[0] = this.stepTangentImpulse[1] = 0;
    this.touching = m.pointCount > 0;
    return this.touching;
  }

  /**
   * True if B moved relative to A by less than REUSE_TOLERANCE at any of its points since the
   * manifold was computed in full: then the same features touch, and only the separations need
   * updating. Resting stacks (most contacts of a settled scene) skip the separating-axis test and
   * the clipping this way (the manifold reuse of Parry/Rapier).
   */
  private poseIsClose(x: number, y: number, c: number, s: number): boolean {
    const cache = this.cache;
    const dx = x - cache[0]!;
    const dy = y - cache[1]!;
    // |sin| of the rotation since then, times the farthest point of B from its own origin.
    const turn = Math.abs(s * cache[2]! - c * cache[3]!);
    const reachB = this.bodyB.maxExtent + this.extentB;
    return dx * dx + dy * dy + turn * reachB * turn * reachB < REUSE_TOLERANCE_SQUARED;
  }

  private storeCache(x: number, y: number, c: number, s: number): void {
    const m = this.manifold;
    const cache = this.cache;
    // Only polygon-like pairs are worth it: the circle kernels cost less than the bookkeeping.
    const kind = this.pairKind;
    if (
      m.pointCount === 0 ||
      kind === PAIR_CIRCLES ||
      kind === PAIR_POLYGON_CIRCLE ||
      kind === PAIR_SEGMENT_CIRCLE ||
      kind === PAIR_CAPSULE_CIRCLE
    ) {
      this.hasCache = false;
      return;
    }
    cache[0] = x;
    cache[1] = y;
    cache[2] = c;
    cache[3] = s;
    const xfA = this.bodyA.transform;
    const xfB = this.bodyB.transform;
    const nx = m.normalX;
    const ny = m.normalY;
    for (let i = 0; i < m.pointCount; i++) {
      const p = m.points[i]!;
      const half = 0.5 * p.separation;
      // Surface points: the manifold point is midway between them along the normal.
      const ax = p.x - half * nx - xfA.x;
      const ay = p.y - half * ny - xfA.y;
      const bx = p.x + half * nx - xfB.x;
      const by = p.y + half * ny - xfB.y;
      const k = 4 + 4 * i;
      cache[k] = xfA.c * ax + xfA.s * ay;
      cache[k + 1] = -xfA.s * ax + xfA.c * ay;
      cache[k + 2] = xfB.c * bx + xfB.s * by;
      cache[k + 3] = -xfB.s * bx + xfB.c * by;
    }
    cache[12] = xfA.c * nx + xfA.s * ny;
    cache[13] = -xfA.s * nx + xfA.c * ny;
    this.hasCache = true;
  }

  /** Moves the cached surface points with their bodies and measures the gap along the normal again. */
  private refreshFromCache(): void {
    const m = this.manifold;
    const cache = this.cache;
    const xfA = this.bodyA.transform;
    const xfB = this.bodyB.transform;
    const nx = xfA.c * cache[12]! - xfA.s * cache[13]!;
    const ny = xfA.s * cache[12]! + xfA.c * cache[13]!;
    m.normalX = nx;
    m.normalY = ny;
    for (let i = 0; i < m.pointCount; i++) {
      const k = 4 + 4 * i;
      const ax = xfA.c * cache[k]! - xfA.s * cache[k + 1]! + xfA.x;
      const ay = xfA.s * cache[k]! + xfA.c * cache[k + 1]! + xfA.y;
      const bx = xfB.c * cache[k + 2]! - xfB.s * cache[k + 3]! + xfB.x;
      const by = xfB.s * cache[k + 2]! + xfB.c * cache[k + 3]! + xfB.y;
      const p = m.points[i]!;
      p.separation = (bx - ax) * nx + (by - ay) * ny;
      p.x = 0.5 * (ax + bx);
      p.y = 0.5 * (ay + by);
      p.anchorAX = p.x - xfA.x;
      p.anchorAY = p.y - xfA.y;
      p.anchorBX = p.x - xfB.x;
      p.anchorBY = p.y - xfB.y;
    }
  }

  /** Keeps far speculative points only where the bodies approach along the normal fast enough. */
  private dropPassingPoints(dt: number): void {
    const m = this.manifold;
    const bodyA = this.bodyA;
    const bodyB = this.bodyB;
    const nx = m.normalX;
    const ny = m.normalY;
    let kept = 0;
    for (let i = 0; i < m.pointCount; i++) {
      const p = m.points[i]!;
      if (p.separation >= SPECULATIVE_DISTANCE) {
        const wA = bodyA.angularVelocityValue;
        const wB = bodyB.angularVelocityValue;
        const vx =
          bodyB.velocityX -
          wB * (p.y - bodyB.centerY) -
          (bodyA.velocityX - wA * (p.y - bodyA.centerY));
        const vy =
          bodyB.velocityY +
          wB * (p.x - bodyB.centerX) -
          (bodyA.velocityY + wA * (p.x - bodyA.centerX));
        const approach = -(vx * nx + vy * ny) * dt;
        if (p.separation >= SPECULATIVE_DISTANCE + 1.5 * approach) continue;
      }
      if (kept !== i) copyGeometry(m.points[kept]!, p);
      kept++;
    }
    m.pointCount = kept;
  }

  /** The body on the other side of the contact. */
  other(body: Body): Body {
    return body === this.bodyA ? this.bodyB : this.bodyA;
  }
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
