import { PhysicalError, readOnly } from '../core/errors.ts';
import {
  describeValue,
  MAX_DENSITY,
  MAX_FRICTION,
  MAX_RESTITUTION,
  MAX_SIZE,
  optionalBoolean,
  requireAngle,
  requireNonNegative,
  requireObject,
  requireSize,
  requireVector,
} from '../core/validate.ts';
import { AABB } from '../geometry/aabb.ts';
import { computeCapsuleAABB, makeCapsule, type Capsule } from '../geometry/capsule.ts';
import { computeCircleAABB, makeCircle, type Circle } from '../geometry/circle.ts';
import { makeBox, makeConvexPart, type Polygon } from '../geometry/polygon.ts';
import { computePolygonAABB } from '../geometry/polygon-queries.ts';
import { makePolygonParts } from '../geometry/polygon-decomposition.ts';
import { computeSegmentAABB, makeSegment, type Segment } from '../geometry/segment.ts';
import type { Transform } from '../math/transform.ts';
import type { Vec2Like } from '../math/vec2.ts';
import type { Body } from './body.ts';
import { filtersCollide, resolveFilter, type Filter, type FilterOptions } from './filter.ts';
import {
  createLocalShapeTable,
  FILTER_STRIDE,
  MATERIAL_STRIDE,
  SHAPE_STRIDE,
  type ShapeTable,
} from './shape-table.ts';

/** Sensor flag and collision filter, shared by every shape kind (and the body factories). */
export interface CollisionOptions {
  /**
   * A sensor reports `'sensorBegin'` and `'sensorEnd'` when another shape starts or stops
   * overlapping it, and never pushes or wakes anything. Default false. Sensors detect the
   * non-sensor shapes of other bodies of every type (static ones too); not other sensors.
   */
  readonly sensor?: boolean;
  /** Which shapes this one collides with (category and mask bits, group). Default: everything. */
  readonly filter?: FilterOptions;
}

/** Surface and mass properties shared by every shape kind. */
export interface MaterialOptions extends CollisionOptions {
  /** Mass per area (kg/m^2). Default 1. Must be > 0 on a dynamic body. */
  readonly density?: number;
  /** Coulomb friction coefficient, >= 0. Default 0.6. Two shapes mix as sqrt(fA * fB). */
  readonly friction?: number;
  /** Coefficient of restitution (bounciness), >= 0, usually 0..1. Default 0. Two shapes mix as max. */
  readonly restitution?: number;
}

/** A circle: the thesis's particle. */
export interface CircleShapeOptions extends MaterialOptions {
  readonly type: 'circle';
  /** Radius (m), > 0. */
  readonly radius: number;
  /** Centre relative to the body origin (m). Default (0, 0). */
  readonly offset?: Vec2Like;
}

/**
 * A polygon from its outline, relative to the body origin (m); either winding. Any simple
 * (non-self-intersecting) outline of 3 to 256 points works: a convex one with at most 8 corners
 * becomes one shape; any other is split into convex parts of at most 8 corners, each its own
 * {@link Shape} with this material (`body.shapes` lists them), whose mass, centre of mass and
 * inertia add up exactly to the outline's.
 */
export interface PolygonShapeOptions extends MaterialOptions {
  readonly type: 'polygon';
  /** 3 to 256 points of a simple outline (m, body-local). Self-intersecting lists are rejected. */
  readonly vertices: readonly Vec2Like[];
  /**
   * Rounding radius (m), default 0: the outline grows by it on every side, corners become arcs.
   * Only for a convex outline of at most 8 corners.
   */
  readonly radius?: number;
}

/**
 * A capsule (a pill): every point within `radius` of the segment from `center1` to `center2`
 * (body-local, m). Its length, end to end, is |center2 - center1| + 2 radius.
 */
export interface CapsuleShapeOptions extends MaterialOptions {
  readonly type: 'capsule';
  /** Centre of the first rounded end (m, body-local). */
  readonly center1: Vec2Like;
  /** Centre of the second rounded end (m, body-local); at least 0.005 m from center1. */
  readonly center2: Vec2Like;
  /** Radius (m), > 0: half the thickness. */
  readonly radius: number;
}

/** A box (rectangle), the most common polygon. */
export interface BoxShapeOptions extends MaterialOptions {
  readonly type: 'box';
  /** Full width along the body's x axis (m), > 0. */
  readonly width: number;
  /** Full height along the body's y axis (m), > 0. */
  readonly height: number;
  /** Centre relative to the body origin (m). Default (0, 0). */
  readonly offset?: Vec2Like;
  /** Rotation relative to the body (rad). Default 0. */
  readonly angle?: number;
  /** Rounding radius (m), default 0: the box grows by it on every side, corners become arcs. */
  readonly radius?: number;
}

/**
 * A line segment from `from` to `to` (m, body-local): the thesis's wall. It has no area, so it
 * belongs on a static or kinematic body. A one-sided segment collides only with shapes on its
 * positive side: on a y-down screen, the side that faces up when the segment runs left to right.
 */
export interface SegmentShapeOptions extends MaterialOptions {
  readonly type: 'segment';
  readonly from: Vec2Like;
  readonly to: Vec2Like;
  /** Default false (both sides collide). */
  readonly oneSided?: boolean;
}

/** Describes one shape of a body. */
export type ShapeOptions =
  | CircleShapeOptions
  | PolygonShapeOptions
  | BoxShapeOptions
  | SegmentShapeOptions
  | CapsuleShapeOptions;

/** The geometry of a shape, in its body's frame. */
export type Geometry = Circle | Polygon | Segment | Capsule;

/**
 * A shape attached to a body: geometry plus material. Created from {@link ShapeOptions} by the
 * body; read its properties, or change the material at any time.
 */
export class Shape {
  /** @internal Behind {@link body}. */
  bodyValue: Body;
  /** The body this shape belongs to. */
  get body(): Body {
    return this.bodyValue;
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set body(_value: never) {
    readOnly('body', 'a shape stays on the body it was made for');
  }
  /**
   * @internal Where this shape's numbers and geometry live (shape-table.ts): the world's table,
   * at row {@link row} (its id), or a table of its own outside a world. The one copy: every
   * getter and setter below reads and writes it. Read `table.data` at each access (it is
   * replaced when the table grows).
   */
  table: ShapeTable;
  /** @internal This shape's row in {@link table}: its id in a world, 0 outside. */
  row = 0;
  /** @internal Index in the world's sensor list, -1 when not a sensor in a world. */
  sensorIndex = -1;
  /** @internal World-local id, -1 outside a world. */
  id = -1;
  /** @internal Broad-phase proxy key, -1 outside a world. */
  proxyKey = -1;

  /**
   * `geometry` is built from `options` unless given (a part of a split polygon). Shapes are made
   * by {@link Body.addShape} and the body factories; one made here is on no body's list.
   * `field`, a string, names the shape in error messages (`shapes[0]`).
   */
  constructor(body: Body, options: ShapeOptions, field: string, geometry?: Geometry) {
    this.bodyValue = body;
    requireObject(field, options, 'a shape description object');
    const density = requireNonNegative(`${field}.density`, options.density ?? 1, MAX_DENSITY);
    const friction = requireFriction(`${field}.friction`, options.friction ?? 0.6);
    const restitution = requireRestitution(`${field}.restitution`, options.restitution ?? 0);
    const table = createLocalShapeTable(geometry ?? createGeometries(options, field)[0]!);
    this.table = table;
    const sensor = optionalBoolean(`${field}.sensor`, options.sensor, false);
    const filter = resolveFilter(`${field}.filter`, options.filter);
    table.materials[0] = density;
    table.materials[1] = friction;
    table.materials[2] = restitution;
    table.filters[3] = sensor ? 1 : 0;
    this.setFilter(filter);
  }

  /** Geometry in the body's frame (read-only: build a new shape to change it). */
  get geometry(): Geometry {
    return this.table.geometries[this.row]!;
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set geometry(_value: never) {
    readOnly('geometry', 'build a new shape to change it');
  }

  /** Mass per area (kg/m^2). Read-only: a shape keeps the density it was built with. */
  get density(): number {
    // The material row's columns: shape-table.ts's MATERIAL_DENSITY, _FRICTION, _RESTITUTION.
    return this.table.materials[this.row * MATERIAL_STRIDE]!;
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set density(_value: never) {
    readOnly('density', 'a shape keeps the density it was built with (add a new shape)');
  }

  /** True for a sensor: it reports overlaps and never collides. Fixed at creation. */
  get sensor(): boolean {
    return this.table.filters[this.row * FILTER_STRIDE + 3] === 1;
  }
  /** @internal Read-only: a write (from plain JavaScript) throws a PhysicalError. */
  set sensor(_value: never) {
    readOnly('sensor', 'a shape is a sensor or not from its creation (add a new shape)');
  }

  /** Coulomb friction coefficient, 0 to 100. Two shapes mix as sqrt(fA * fB). */
  get friction(): number {
    return this.table.materials[this.row * MATERIAL_STRIDE + 1]!;
  }

  set friction(value: number) {
    this.table.materials[this.row * MATERIAL_STRIDE + 1] = requireFriction('friction', value);
  }

  /** Coefficient of restitution (bounciness), 0 to 10, usually 0..1. Two shapes mix as max. */
  get restitution(): number {
    return this.table.materials[this.row * MATERIAL_STRIDE + 2]!;
  }

  set restitution(value: number) {
    this.table.materials[this.row * MATERIAL_STRIDE + 2] = requireRestitution('restitution', value);
  }

  /** @internal Category bits (unsigned; see {@link filter}). */
  get categoryBits(): number {
    return this.table.filters[this.row * FILTER_STRIDE]! >>> 0;
  }
  /** @internal Mask bits (unsigned). */
  get maskBits(): number {
    return this.table.filters[this.row * FILTER_STRIDE + 1]! >>> 0;
  }
  /** @internal Group. */
  get groupIndex(): number {
    return this.table.filters[this.row * FILTER_STRIDE + 2]!;
  }

  /**
   * The collision filter: category and mask bits, and group (see {@link FilterOptions}). Setting
   * it applies from the next step: contacts the new filter forbids end now, and newly allowed
   * pairs are found by the next step.
   */
  get filter(): Filter {
    return { category: this.categoryBits, mask: this.maskBits, group: this.groupIndex };
  }

  set filter(value: FilterOptions) {
    const filter = resolveFilter('filter', value);
    this.body.host?.requireUnlocked('filter');
    this.setFilter(filter);
    this.body.host?.shapeFilterChanged(this);
  }

  /** Whether this shape and `other` pass each other's filters (sensors aside). */
  collidesWith(other: Shape): boolean {
    requireObject('other', other, 'a shape');
    return filtersCollide(this, other);
  }

  private setFilter(filter: Filter): void {
    const f = this.table.filters;
    const p = this.row * FILTER_STRIDE;
    f[p] = filter.category;
    f[p + 1] = filter.mask;
    f[p + 2] = filter.group;
  }

  /** The shape's bounding box in world coordinates (m), at the body's current pose. */
  getBounds(
    out: { minX: number; minY: number; maxX: number; maxY: number } = {
      minX: 0,
      minY: 0,
      maxX: 0,
      maxY: 0,
    },
  ): { minX: number; minY: number; maxX: number; maxY: number } {
    requireObject('out', out, 'an object');
    const box = this.computeAABB(this.body.transform);
    out.minX = box.minX;
    out.minY = box.minY;
    out.maxX = box.maxX;
    out.maxY = box.maxY;
    return out;
  }

  /**
   * @internal Recomputes the tight box for a transform and stores it as this shape's. The box
   * returned is shared scratch: valid until the next call on any shape.
   */
  computeAABB(xf: Transform): AABB {
    const g = this.geometry;
    const box = scratchBox;
    if (g.kind === 'circle') computeCircleAABB(g, xf, box);
    else if (g.kind === 'polygon') computePolygonAABB(g, xf, box);
    else if (g.kind === 'capsule') computeCapsuleAABB(g, xf, box);
    else computeSegmentAABB(g, xf, box);
    this.table.setTight(this.row, box);
    return box;
  }

  /** @internal Reads the tight box last stored (m) into `out`. */
  readTightBox(out: AABB): AABB {
    const d = this.table.data;
    const p = this.row * SHAPE_STRIDE;
    return out.set(d[p]!, d[p + 1]!, d[p + 2]!, d[p + 3]!);
  }

  /** @internal Reads the broad phase's fat box (m) into `out`. */
  readFatBox(out: AABB): AABB {
    const d = this.table.data;
    const p = this.row * SHAPE_STRIDE + 4;
    return out.set(d[p]!, d[p + 1]!, d[p + 2]!, d[p + 3]!);
  }

  /** @internal Stores the tight box (a snapshot's). */
  setTightBox(box: AABB): void {
    this.table.setTight(this.row, box);
  }

  /** @internal Stores the broad phase's fat box, just read from its proxy. */
  setFatBox(box: AABB): void {
    this.table.setFat(this.row, box);
  }

  /**
   * @internal Moves this shape's numbers into a world's table at row {@link id} (set first), or
   * out of it into a table of its own (null).
   */
  attachTable(table: ShapeTable | null): void {
    const old = this.table;
    const oldRow = this.row;
    if (table === null) {
      const local = createLocalShapeTable(old.geometries[oldRow]!);
      local.copyRow(old, oldRow, 0);
      old.geometries[oldRow] = null;
      this.table = local;
      this.row = 0;
      return;
    }
    table.copyRow(old, oldRow, this.id);
    if (old !== table) old.geometries[oldRow] = null;
    this.table = table;
    this.row = this.id;
  }
}

/** computeAABB's result: written by each call, read before the next. */
const scratchBox = new AABB();

/**
 * @internal The geometry of each shape that `options` makes: one, or the convex parts of a split
 * polygon outline.
 */
export function createGeometries(options: ShapeOptions, field: string): Geometry[] {
  requireObject(field, options, 'a shape description object');
  if (options.type === 'polygon') {
    if (!Array.isArray(options.vertices)) {
      throw new PhysicalError(
        `${field}.vertices`,
        `must be an array of points { x, y } (m), got ${describeValue(options.vertices)}.`,
      );
    }
    const radius = requireNonNegative(`${field}.radius`, options.radius ?? 0, MAX_SIZE);
    if ((options as { [CONVEX_PART]?: boolean })[CONVEX_PART] === true) {
      return [makeConvexPart(options.vertices, radius, field)];
    }
    return makePolygonParts(options.vertices, radius, field);
  }
  return [createGeometry(options, field)];
}

/**
 * @internal Marks polygon options as one saved convex part (a snapshot's): built exactly as given,
 * checked for convexity but not cleaned or split.
 */
export const CONVEX_PART: unique symbol = Symbol('convexPart');

/**
 * @internal Validates a shape description that makes one geometry (every kind but a polygon
 * outline, which may make several: see {@link createGeometries}) and builds it (body frame).
 */
export function createGeometry(options: ShapeOptions, field: string): Geometry {
  requireObject(field, options, 'a shape description object');
  switch (options.type) {
    case 'circle': {
      const offset = options.offset ?? ORIGIN;
      requireVector(`${field}.offset`, offset);
      return makeCircle(offset.x, offset.y, options.radius, field);
    }
    case 'capsule': {
      requireVector(`${field}.center1`, options.center1);
      requireVector(`${field}.center2`, options.center2);
      return makeCapsule(
        options.center1.x,
        options.center1.y,
        options.center2.x,
        options.center2.y,
        options.radius,
        field,
      );
    }
    case 'box': {
      const offset = options.offset ?? ORIGIN;
      requireVector(`${field}.offset`, offset);
      const width = requireSize(`${field}.width`, options.width);
      const height = requireSize(`${field}.height`, options.height);
      return makeBox(
        width / 2,
        height / 2,
        offset.x,
        offset.y,
        requireAngle(`${field}.angle`, options.angle ?? 0),
        requireNonNegative(`${field}.radius`, options.radius ?? 0, MAX_SIZE),
        field,
      );
    }
    case 'segment': {
      requireVector(`${field}.from`, options.from);
      requireVector(`${field}.to`, options.to);
      return makeSegment(
        options.from.x,
        options.from.y,
        options.to.x,
        options.to.y,
        optionalBoolean(`${field}.oneSided`, options.oneSided, false),
        field,
      );
    }
    default:
      throw new PhysicalError(
        `${field}.type`,
        `must be 'circle', 'polygon', 'box', 'capsule' or 'segment', got ${describeValue((options as { type?: unknown }).type)}.`,
      );
  }
}

const ORIGIN: Vec2Like = { x: 0, y: 0 };

function requireFriction(field: string, value: number): number {
  return requireNonNegative(field, value, MAX_FRICTION);
}

function requireRestitution(field: string, value: number): number {
  return requireNonNegative(field, value, MAX_RESTITUTION);
}
