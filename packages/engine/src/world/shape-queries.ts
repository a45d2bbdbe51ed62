import type { BroadPhase } from '../collision/broad-phase.ts';
import {
  DistanceOutput,
  DistanceProxy,
  coreResult,
  gjkCores,
  shapeDistance,
} from '../collision/distance.ts';
import {
  Sweep,
  TimeOfImpactOutput,
  getSweepTransform,
  timeOfImpact,
} from '../collision/time-of-impact.ts';
import { requireAngle, requireObject, requireVector } from '../core/validate.ts';
import { AABB } from '../geometry/aabb.ts';
import { computeCapsuleAABB } from '../geometry/capsule.ts';
import { computeCircleAABB } from '../geometry/circle.ts';
import { computePolygonAABB } from '../geometry/polygon-queries.ts';
import { computeSegmentAABB } from '../geometry/segment.ts';
import { Transform } from '../math/transform.ts';
import type { Vec2, Vec2Like } from '../math/vec2.ts';
import type { Body } from '../dynamics/body.ts';
import { setGeometryProxy, setShapeProxy } from '../dynamics/shape-proxy.ts';
import {
  createGeometries,
  type Geometry,
  type Shape,
  type ShapeOptions,
} from '../dynamics/shape.ts';
import { hypot } from '../math/hypot.ts';

/** Where a query shape is placed: position of its origin (m) and rotation (rad, default 0). */
export interface QueryPose {
  readonly position: Vec2Like;
  readonly angle?: number;
}

/** The first shape a swept shape hits ({@link World.shapeCast}). */
export interface ShapeCastHit {
  readonly body: Body;
  readonly shape: Shape;
  /**
   * Fraction of the translation travelled before the hit, 0..1. The cast stops within
   * LINEAR_SLOP (0.005 m) of the surface, as the engine's continuous collision does; 0 when the
   * shape overlaps something at its start.
   */
  readonly fraction: number;
  /** Contact point on the hit shape's surface (m, world). */
  readonly point: Vec2;
  /** Unit surface normal of the hit shape there, facing the cast shape. */
  readonly normal: Vec2;
}

/**
 * Shape casts (a convex shape swept along a straight line) and shape overlaps over the broad
 * phase. Both run GJK against each candidate the trees report: the cast by conservative
 * advancement (time-of-impact.ts), the overlap by distance (0 when touching or overlapping).
 * Sensor shapes are not reported: they are not surfaces.
 */
export class ShapeQueries {
  private readonly castProxy = new DistanceProxy();
  private readonly otherProxy = new DistanceProxy();
  private readonly castSweep = new Sweep();
  private readonly otherSweep = new Sweep();
  private readonly toi = new TimeOfImpactOutput();
  private readonly distance = new DistanceOutput();
  private readonly xf = new Transform();
  private readonly xfOther = new Transform();
  private readonly box = new AABB();
  private readonly scratch = new AABB();
  private best: Shape | null = null;
  private bestFraction = 1;
  /** The part of the cast shape being swept, and the part that made the best hit. */
  private current: Geometry | null = null;
  private bestGeometry: Geometry | null = null;
  private readonly found: Body[] = [];

  constructor(
    private readonly broadPhase: BroadPhase,
    private readonly shapes: readonly (Shape | null)[],
  ) {}

  shapeCast(options: ShapeOptions, pose: QueryPose, translation: Vec2Like): ShapeCastHit | null {
    // A concave polygon outline makes several convex parts: each is swept, the earliest hit wins.
    const geometries = createGeometries(options, 'shape');
    const angle = readPose(pose);
    requireVector('translation', translation);
    this.best = null;
    this.bestFraction = 1;
    this.bestGeometry = null;
    for (const geometry of geometries) this.castPart(geometry, pose, angle, translation);
    const shape = this.best as Shape | null;
    if (shape === null) return null;
    const xf = this.xf.set(pose.position.x, pose.position.y, angle);
    const sweep = this.castSweep;
    this.setSweep(xf, angle, translation);
    setGeometryProxy(this.castProxy, this.bestGeometry!);
    // Contact point and normal at the hit pose.
    const fraction = this.bestFraction;
    getSweepTransform(sweep, fraction, this.xf);
    setShapeProxy(this.otherProxy, shape);
    // The cores are apart at a hit (the time of impact keeps them LINEAR_SLOP apart or more):
    // the normal joins their closest points, and the point is the hit shape's surface point.
    const coreDistance = gjkCores(this.otherProxy, shape.body.transform, this.castProxy, this.xf);
    let nx = 0;
    let ny = 0;
    if (coreDistance > 1e-12) {
      nx = (coreResult.pointBX - coreResult.pointAX) / coreDistance;
      ny = (coreResult.pointBY - coreResult.pointAY) / coreDistance;
    } else {
      // Cores overlap (a start inside a shape): the best normal is against the motion.
      const length = hypot(translation.x, translation.y);
      if (length > 0) {
        nx = -translation.x / length;
        ny = -translation.y / length;
      }
    }
    const radius = this.otherProxy.radius;
    const pointX = coreResult.pointAX + radius * nx;
    const pointY = coreResult.pointAY + radius * ny;
    return {
      body: shape.body,
      shape,
      fraction,
      point: { x: pointX, y: pointY },
      normal: { x: nx, y: ny },
    };
  }

  /** Sweeps one convex part of the cast shape, keeping the best hit over all parts so far. */
  private castPart(
    geometry: Geometry,
    pose: QueryPose,
    angle: number,
    translation: Vec2Like,
  ): void {
    const xf = this.xf.set(pose.position.x, pose.position.y, angle);
    setGeometryProxy(this.castProxy, geometry);
    this.setSweep(xf, angle, translation);
    const start = geometryAABB(geometry, xf, this.scratch);
    this.box.set(
      start.minX + Math.min(0, translation.x),
      start.minY + Math.min(0, translation.y),
      start.maxX + Math.max(0, translation.x),
      start.maxY + Math.max(0, translation.y),
    );
    this.current = geometry;
    this.broadPhase.query(this.box, this.castCallback);
    this.current = null;
  }

  private setSweep(xf: Transform, angle: number, translation: Vec2Like): void {
    const sweep = this.castSweep;
    sweep.localCenterX = 0;
    sweep.localCenterY = 0;
    sweep.c1X = xf.x;
    sweep.c1Y = xf.y;
    sweep.c2X = xf.x + translation.x;
    sweep.c2Y = xf.y + translation.y;
    sweep.a1 = angle;
    sweep.a2 = angle;
  }

  overlapShape(options: ShapeOptions, pose: QueryPose): Body[] {
    const geometries = createGeometries(options, 'shape');
    const angle = readPose(pose);
    const xf = this.xf.set(pose.position.x, pose.position.y, angle);
    this.found.length = 0;
    for (const geometry of geometries) {
      setGeometryProxy(this.castProxy, geometry);
      const box = geometryAABB(geometry, xf, this.scratch);
      this.box.set(box.minX, box.minY, box.maxX, box.maxY);
      this.broadPhase.query(this.box, this.overlapCallback);
    }
    const result = this.found.slice();
    result.sort((a, b) => a.worldIndex - b.worldIndex);
    return result;
  }

  private readonly castCallback = (_proxyKey: number, shapeId: number): boolean => {
    const other = this.shapes[shapeId];
    if (other === null || other === undefined || other.sensor) return true;
    setShapeProxy(this.otherProxy, other);
    const body = other.body;
    const sweep = this.otherSweep;
    sweep.localCenterX = 0;
    sweep.localCenterY = 0;
    sweep.c1X = sweep.c2X = body.transform.x;
    sweep.c1Y = sweep.c2Y = body.transform.y;
    sweep.a1 = sweep.a2 = body.angleValue;
    const out = this.toi;
    timeOfImpact(this.otherProxy, sweep, this.castProxy, this.castSweep, this.bestFraction, out);
    if (out.state !== 'hit' && out.state !== 'overlapped') return true;
    const better =
      this.best === null ||
      out.fraction < this.bestFraction ||
      (out.fraction === this.bestFraction && body.worldIndex < this.best.body.worldIndex);
    if (better) {
      this.best = other;
      this.bestFraction = out.fraction;
      this.bestGeometry = this.current;
    }
    return true;
  };

  private readonly overlapCallback = (_proxyKey: number, shapeId: number): boolean => {
    const other = this.shapes[shapeId];
    if (other === null || other === undefined || other.sensor) return true;
    if (this.found.includes(other.body)) return true;
    setShapeProxy(this.otherProxy, other);
    const xfOther = this.xfOther.copy(other.body.transform);
    if (shapeDistance(this.otherProxy, xfOther, this.castProxy, this.xf, this.distance) === 0) {
      this.found.push(other.body);
    }
    return true;
  };
}

function readPose(pose: QueryPose): number {
  requireObject('pose', pose, '{ position: { x, y }, angle? }');
  requireVector('pose.position', pose.position);
  return requireAngle('pose.angle', pose.angle ?? 0);
}

function geometryAABB(g: Geometry, xf: Transform, out: AABB): AABB {
  if (g.kind === 'circle') return computeCircleAABB(g, xf, out);
  if (g.kind === 'polygon') return computePolygonAABB(g, xf, out);
  if (g.kind === 'capsule') return computeCapsuleAABB(g, xf, out);
  return computeSegmentAABB(g, xf, out);
}
