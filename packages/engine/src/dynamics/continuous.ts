import type { BroadPhase } from '../collision/broad-phase.ts';
import { DistanceProxy } from '../collision/distance.ts';
import {
  Sweep,
  TimeOfImpactOutput,
  getSweepTransform,
  timeOfImpact,
} from '../collision/time-of-impact.ts';
import { LINEAR_SLOP } from '../core/constants.ts';
import { AABB } from '../geometry/aabb.ts';
import { Transform } from '../math/transform.ts';
import type { Body } from './body.ts';
import type { Shape } from './shape.ts';
import { setShapeProxy } from './shape-proxy.ts';

const STATIC_PROXY = 0;
const KINEMATIC_PROXY = 1;

/**
 * Continuous collision of fast bodies against static shapes (the tunneling the thesis names as
 * future work). After the solver moved a body from pose 0 to pose 1, if it moved more than half
 * its smallest extent, the sweep is tested against every static shape in the swept box with a
 * time of impact (conservative advancement; Catto, GDC 2013 "Continuous collision"), and the body
 * is moved back to the earliest hit. Its velocity is kept: next step the speculative contact
 * stops it exactly at the surface, and restitution makes it bounce.
 *
 * A body touching a surface at the start of the step gives a time of impact of zero against it
 * (sliding along the ground); as Box2D v3 does, that case retries with a small core circle at the
 * shape's centroid, which still catches a real pass-through but not sliding contact.
 *
 * Bullets (`body.bullet`) also sweep against kinematic and non-bullet dynamic bodies, as in Box2D
 * v3: the world runs them after every other body has its final pose, and each obstacle is held
 * still at that pose (its own motion this step is already done). Bullets ignore other bullets.
 * Sensors and filtered-out pairs never stop a sweep.
 */
export class ContinuousSolver {
  private readonly sweep = new Sweep();
  private readonly staticSweep = new Sweep();
  private readonly proxy = new DistanceProxy();
  private readonly coreProxy = new DistanceProxy();
  private readonly otherProxy = new DistanceProxy();
  private readonly output = new TimeOfImpactOutput();
  private readonly xf0 = new Transform();
  private readonly box = new AABB();
  private body: Body | null = null;
  private shape: Shape | null = null;
  private fraction = 1;
  private bullet = false;
  private shapes: readonly (Shape | null)[] = [];
  private readonly queryCallback = (proxyKey: number, shapeId: number): boolean =>
    this.testStaticShape(proxyKey, shapeId);

  /**
   * Sweeps a fast body against static shapes (and, for a bullet, against non-bullet moving ones);
   * moves it back to the first impact, if any. Returns true if it moved the body.
   */
  solve(
    body: Body,
    broadPhase: BroadPhase,
    shapes: readonly (Shape | null)[],
    bullet: boolean = false,
  ): boolean {
    this.bullet = bullet;
    if (!bullet) {
      // Each shape's box at any pose lies within maxExtent of the centre of mass, so a box around
      // both centres, that far out (and a slop more, for rounding), holds every box the sweeps
      // below would query. Where no static shape comes near it, none can be hit: most fast
      // bodies are in free flight (a ragdoll rain: 7,300 sweeps a step, 400 shapes tested).
      const box = this.box;
      const reach = body.maxExtent + LINEAR_SLOP;
      box.minX = Math.min(body.center0X, body.centerX) - reach;
      box.minY = Math.min(body.center0Y, body.centerY) - reach;
      box.maxX = Math.max(body.center0X, body.centerX) + reach;
      box.maxY = Math.max(body.center0Y, body.centerY) + reach;
      if (!broadPhase.overlapsStatic(box)) return false;
    }
    const sweep = this.sweep;
    sweep.localCenterX = body.localCenterX;
    sweep.localCenterY = body.localCenterY;
    sweep.c1X = body.center0X;
    sweep.c1Y = body.center0Y;
    sweep.c2X = body.centerX;
    sweep.c2Y = body.centerY;
    sweep.a1 = body.angle0;
    sweep.a2 = body.angleValue;
    // Through the sweep, not setFromCenter: V8 boxes the fractional arguments of a call it does
    // not inline (here and below, field writes rather than box.set), and this runs per fast body.
    const xf0 = getSweepTransform(sweep, 0, this.xf0);

    this.body = body;
    this.fraction = 1;
    this.shapes = shapes;
    for (const shape of body.shapeList) {
      if (shape.sensor) continue;
      this.shape = shape;
      // Swept box: the union of the boxes at the start and the end of the step.
      const box = this.box;
      const end = shape.computeAABB(body.transform);
      const endMinX = end.minX;
      const endMinY = end.minY;
      const endMaxX = end.maxX;
      const endMaxY = end.maxY;
      const start = shape.computeAABB(xf0);
      box.minX = Math.min(endMinX, start.minX);
      box.minY = Math.min(endMinY, start.minY);
      box.maxX = Math.max(endMaxX, start.maxX);
      box.maxY = Math.max(endMaxY, start.maxY);
      setShapeProxy(this.proxy, shape);
      // A non-bullet sweeps against static shapes only: the other trees need not be searched.
      broadPhase.query(box, this.queryCallback, !bullet);
    }
    // Leave the shape's tight box at the end pose; the caller refreshes it after a move anyway.
    for (const shape of body.shapeList) shape.computeAABB(body.transform);
    this.body = null;
    this.shape = null;

    if (this.fraction < 1) {
      const t = this.fraction;
      const angle = sweep.a1 + t * (sweep.a2 - sweep.a1);
      body.centerX = sweep.c1X + t * (sweep.c2X - sweep.c1X);
      body.centerY = sweep.c1Y + t * (sweep.c2Y - sweep.c1Y);
      body.angleValue = angle;
      body.transform.setFromCenter(
        body.centerX,
        body.centerY,
        angle,
        body.localCenterX,
        body.localCenterY,
      );
      return true;
    }
    return false;
  }

  private testStaticShape(proxyKey: number, shapeId: number): boolean {
    const type = proxyKey & 3;
    if (type !== STATIC_PROXY && !this.bullet) return true;
    const other = this.shapes[shapeId];
    const body = this.body!;
    const shape = this.shape!;
    if (other === null || other === undefined || other.body === body) return true;
    if (other.sensor || !shape.collidesWith(other)) return true;
    if (type > KINEMATIC_PROXY && other.body.bulletValue) return true;
    const g = other.geometry;
    if (g.kind === 'segment' && g.oneSided) {
      // A one-sided wall stops only what comes from its positive side.
      const xf = other.body.transform;
      const ex = g.x2 - g.x1;
      const ey = g.y2 - g.y1;
      const nx = xf.c * ey + xf.s * ex;
      const ny = xf.s * ey - xf.c * ex;
      const px = xf.c * g.x1 - xf.s * g.y1 + xf.x;
      const py = xf.s * g.x1 + xf.c * g.y1 + xf.y;
      if ((body.center0X - px) * nx + (body.center0Y - py) * ny < 0) return true;
    }
    setShapeProxy(this.otherProxy, other);
    const staticSweep = this.staticSweep;
    const oxf = other.body.transform;
    staticSweep.localCenterX = 0;
    staticSweep.localCenterY = 0;
    staticSweep.c1X = staticSweep.c2X = oxf.x;
    staticSweep.c1Y = staticSweep.c2Y = oxf.y;
    staticSweep.a1 = staticSweep.a2 = other.body.angleValue;

    const output = this.output;
    timeOfImpact(this.otherProxy, staticSweep, this.proxy, this.sweep, this.fraction, output);
    if (output.fraction > 0 && output.fraction < this.fraction && output.state === 'hit') {
      this.fraction = output.fraction;
    } else if (output.fraction === 0) {
      setCoreProxy(this.coreProxy, shape);
      timeOfImpact(this.otherProxy, staticSweep, this.coreProxy, this.sweep, this.fraction, output);
      if (output.fraction > 0 && output.fraction < this.fraction && output.state === 'hit') {
        this.fraction = output.fraction;
      }
    }
    return true;
  }
}

/** A small circle at the shape's centroid: a quarter of its smallest extent. */
function setCoreProxy(proxy: DistanceProxy, shape: Shape): void {
  const g = shape.geometry;
  let x: number;
  let y: number;
  let radius = 0;
  if (g.kind === 'circle') {
    x = g.centerX;
    y = g.centerY;
    radius = 0.25 * g.radius;
  } else if (g.kind === 'polygon') {
    x = g.centroidX;
    y = g.centroidY;
    let inner = Infinity;
    for (let i = 0; i < g.count; i++) {
      const d =
        (g.vertices[2 * i]! - x) * g.normals[2 * i]! +
        (g.vertices[2 * i + 1]! - y) * g.normals[2 * i + 1]!;
      inner = Math.min(inner, d);
    }
    radius = 0.25 * (inner + g.radius);
  } else if (g.kind === 'capsule') {
    x = 0.5 * (g.x1 + g.x2);
    y = 0.5 * (g.y1 + g.y2);
    radius = 0.25 * g.radius;
  } else {
    x = 0.5 * (g.x1 + g.x2);
    y = 0.5 * (g.y1 + g.y2);
  }
  proxy.count = 1;
  proxy.vertices[0] = x;
  proxy.vertices[1] = y;
  proxy.radius = radius;
}
