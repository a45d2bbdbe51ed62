import { collideCircles } from '../collision/collide-circles.ts';
import { collidePolygonAndCircle } from '../collision/collide-polygon-circle.ts';
import { collidePolygons } from '../collision/collide-polygons.ts';
import { collideSegmentAndCircle } from '../collision/collide-segment-circle.ts';
import { collideSegmentAndPolygon } from '../collision/collide-segment-polygon.ts';
import { Manifold, type ManifoldPoint } from '../collision/manifold.ts';
import { SPECULATIVE_DISTANCE } from '../core/constants.ts';
import type { Circle } from '../geometry/circle.ts';
import type { Polygon } from '../geometry/polygon.ts';
import type { Segment } from '../geometry/segment.ts';
import type { Body } from './body.ts';
import type { Shape } from './shape.ts';

// The narrow-phase table: which collide function handles a pair of shape kinds, with shape A the
// higher-ranked kind (segment > polygon > circle). One switch here instead of registration by
// import side effects.
const PAIR_CIRCLES = 0;
const PAIR_POLYGON_CIRCLE = 1;
const PAIR_POLYGONS = 2;
const PAIR_SEGMENT_CIRCLE = 3;
const PAIR_SEGMENT_POLYGON = 4;

const KIND_RANK = { circle: 0, polygon: 1, segment: 2 } as const;

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
  /** The manifold has at least one point (possibly speculative). */
  touching = false;
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
    this.manifold.pointCount = 0;
    const kindA = a.geometry.kind;
    const kindB = b.geometry.kind;
    if (kindA === 'circle') this.pairKind = PAIR_CIRCLES;
    else if (kindA === 'polygon')
      this.pairKind = kindB === 'circle' ? PAIR_POLYGON_CIRCLE : PAIR_POLYGONS;
    else this.pairKind = kindB === 'circle' ? PAIR_SEGMENT_CIRCLE : PAIR_SEGMENT_POLYGON;
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
    const m = this.manifold;
    const p0 = m.points[0];
    const p1 = m.points[1];
    const oldCount = m.pointCount;
    const id0 = p0.id;
    const id1 = p1.id;
    const normal0 = p0.normalImpulse;
    const tangent0 = p0.tangentImpulse;
    const normal1 = p1.normalImpulse;
    const tangent1 = p1.tangentImpulse;

    const a = this.shapeA.geometry;
    const b = this.shapeB.geometry;
    const bodyA = this.bodyA;
    const bodyB = this.bodyB;
    const xfA = bodyA.transform;
    const xfB = bodyB.transform;
    // Bound on how much the gap can close this step: relative speed plus rotation at the rim.
    const dvx = bodyB.velocityX - bodyA.velocityX;
    const dvy = bodyB.velocityY - bodyA.velocityY;
    const reach =
      dt *
      (Math.sqrt(dvx * dvx + dvy * dvy) +
        Math.abs(bodyA.angularVelocityValue) * bodyA.maxExtent +
        Math.abs(bodyB.angularVelocityValue) * bodyB.maxExtent);
    const margin = SPECULATIVE_DISTANCE + reach;
    switch (this.pairKind) {
      case PAIR_CIRCLES:
        collideCircles(a as Circle, xfA, b as Circle, xfB, m, margin);
        break;
      case PAIR_POLYGON_CIRCLE:
        collidePolygonAndCircle(a as Polygon, xfA, b as Circle, xfB, m, margin);
        break;
      case PAIR_POLYGONS:
        collidePolygons(a as Polygon, xfA, b as Polygon, xfB, m, margin);
        break;
      case PAIR_SEGMENT_CIRCLE:
        collideSegmentAndCircle(a as Segment, xfA, b as Circle, xfB, m, margin);
        break;
      default:
        collideSegmentAndPolygon(a as Segment, xfA, b as Polygon, xfB, m, margin);
        break;
    }
    if (reach > 0 && m.pointCount > 0) this.dropPassingPoints(dt);

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
    this.touching = m.pointCount > 0;
    return this.touching;
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
