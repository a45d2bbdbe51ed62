import type { BroadPhase } from '../collision/broad-phase.ts';
import { AABB, aabbOverlaps } from '../geometry/aabb.ts';
import { rayCastCircle } from '../geometry/circle.ts';
import { rayCastCapsule } from '../geometry/capsule.ts';
import { rayCastPolygon } from '../geometry/polygon.ts';
import { RayHit, RayInput } from '../geometry/ray.ts';
import { rayCastSegment } from '../geometry/segment.ts';
import type { Vec2 } from '../math/vec2.ts';
import type { Body } from '../dynamics/body.ts';
import type { Shape } from '../dynamics/shape.ts';
import { shapeContainsPoint } from './body-at-point.ts';

/** The first shape a ray hits. */
export interface RayCastHit {
  readonly body: Body;
  readonly shape: Shape;
  /** Where the ray enters the shape (m, world). */
  readonly point: Vec2;
  /** Surface normal there, unit, facing the ray's origin. */
  readonly normal: Vec2;
  /** Position along the ray, 0 at `from` and 1 at `to`. */
  readonly fraction: number;
}

/** Point, box and ray queries over the broad phase, tested exactly against the shapes. */
export class WorldQueries {
  private readonly box = new AABB();
  private readonly input = new RayInput();
  private readonly hit = new RayHit();
  private pointX = 0;
  private pointY = 0;
  private best: Shape | null = null;
  private bestFraction = 1;
  private readonly bestHit = new RayHit();
  private readonly found: Body[] = [];
  private allHits: RayCastHit[] | null = null;

  constructor(
    private readonly broadPhase: BroadPhase,
    private readonly shapes: readonly (Shape | null)[],
  ) {}

  bodyAt(x: number, y: number): Body | null {
    this.pointX = x;
    this.pointY = y;
    this.best = null;
    this.broadPhase.query(this.box.set(x, y, x, y), this.pointCallback);
    return this.best === null ? null : (this.best as Shape).body;
  }

  bodiesInAABB(minX: number, minY: number, maxX: number, maxY: number): Body[] {
    this.found.length = 0;
    this.broadPhase.query(this.box.set(minX, minY, maxX, maxY), this.boxCallback);
    const result = this.found.slice();
    result.sort((a, b) => a.worldIndex - b.worldIndex);
    return result;
  }

  /** Every shape the ray crosses, sorted by fraction (then world order), one hit per shape. */
  rayCastAll(fromX: number, fromY: number, toX: number, toY: number): RayCastHit[] {
    const input = this.input;
    input.originX = fromX;
    input.originY = fromY;
    input.translationX = toX - fromX;
    input.translationY = toY - fromY;
    input.maxFraction = 1;
    const hits: RayCastHit[] = [];
    this.allHits = hits;
    this.broadPhase.rayCast(input, this.rayAllCallback);
    this.allHits = null;
    hits.sort((a, b) => a.fraction - b.fraction || a.body.worldIndex - b.body.worldIndex);
    return hits;
  }

  rayCast(fromX: number, fromY: number, toX: number, toY: number): RayCastHit | null {
    const input = this.input;
    input.originX = fromX;
    input.originY = fromY;
    input.translationX = toX - fromX;
    input.translationY = toY - fromY;
    input.maxFraction = 1;
    this.best = null;
    this.bestFraction = 1;
    this.broadPhase.rayCast(input, this.rayCallback);
    const shape = this.best as Shape | null;
    if (shape === null) return null;
    const hit = this.bestHit;
    return {
      body: shape.body,
      shape,
      point: { x: hit.x, y: hit.y },
      normal: { x: hit.normalX, y: hit.normalY },
      fraction: hit.fraction,
    };
  }

  private readonly pointCallback = (_proxyKey: number, shapeId: number): boolean => {
    const shape = this.shapes[shapeId];
    if (shape === null || shape === undefined) return true;
    const inside = shapeContainsPoint(shape, this.pointX, this.pointY);
    // Prefer the body added last: it is drawn on top.
    if (inside && (this.best === null || shape.body.worldIndex > this.best.body.worldIndex)) {
      this.best = shape;
    }
    return true;
  };

  private readonly boxCallback = (_proxyKey: number, shapeId: number): boolean => {
    const shape = this.shapes[shapeId];
    if (shape === null || shape === undefined) return true;
    if (aabbOverlaps(shape.computeAABB(shape.body.transform), this.box)) {
      if (!this.found.includes(shape.body)) this.found.push(shape.body);
    }
    return true;
  };

  /** Ray against one shape into `this.hit`; sensors are not surfaces and are never hit. */
  private castShape(input: RayInput, shape: Shape | null | undefined): shape is Shape {
    if (shape === null || shape === undefined || shape.sensor) return false;
    const g = shape.geometry;
    const xf = shape.body.transform;
    const hit = this.hit;
    return g.kind === 'circle'
      ? rayCastCircle(g, xf, input, hit)
      : g.kind === 'polygon'
        ? rayCastPolygon(g, xf, input, hit)
        : g.kind === 'capsule'
          ? rayCastCapsule(g, xf, input, hit)
          : rayCastSegment(g, xf, input, hit);
  }

  private readonly rayAllCallback = (
    input: RayInput,
    _proxyKey: number,
    shapeId: number,
  ): number => {
    const shape = this.shapes[shapeId];
    if (!this.castShape(input, shape)) return -1;
    const hit = this.hit;
    this.allHits!.push({
      body: shape.body,
      shape,
      point: { x: hit.x, y: hit.y },
      normal: { x: hit.normalX, y: hit.normalY },
      fraction: hit.fraction,
    });
    return -1;
  };

  private readonly rayCallback = (input: RayInput, _proxyKey: number, shapeId: number): number => {
    const shape = this.shapes[shapeId];
    if (!this.castShape(input, shape)) return -1;
    const hit = this.hit;
    if (hit.fraction > this.bestFraction) return -1;
    this.best = shape;
    this.bestFraction = hit.fraction;
    const best = this.bestHit;
    best.fraction = hit.fraction;
    best.x = hit.x;
    best.y = hit.y;
    best.normalX = hit.normalX;
    best.normalY = hit.normalY;
    return hit.fraction;
  };
}
