import { PhysicalError } from '../core/errors.ts';
import { requireFinite, requireObject, requireSize } from '../core/validate.ts';
import { LINEAR_SLOP, MAX_POLYGON_VERTICES } from '../core/constants.ts';
import type { Vec2Like } from '../math/vec2.ts';
import { Body, type BodyOptions } from './body.ts';
import type { FilterOptions } from './filter.ts';
import type { MaterialOptions } from './shape.ts';
import { cosSin } from '../math/trigonometry.ts';

// The bodies the thesis's users reach for, one call each. Each takes the body options plus the
// shape's size and material, so `particle({ position, radius, restitution })` is the whole story.

type Common<UserData> = Omit<BodyOptions<UserData>, 'shapes'> & MaterialOptions;

/** Options of {@link particle}. */
export interface ParticleOptions<UserData = unknown> extends Common<UserData> {
  /** Radius (m), > 0. */
  readonly radius: number;
}

/** Options of {@link box}. */
export interface BoxOptions<UserData = unknown> extends Common<UserData> {
  /** Full width (m), > 0. */
  readonly width: number;
  /** Full height (m), > 0. */
  readonly height: number;
  /**
   * Rounds the corners (m), default 0: a rounded box, the shape of an app's buttons. The outline
   * grows by `radius` on every side, so the body is `width + 2 radius` wide (as Box2D's
   * b2MakeRoundedBox).
   */
  readonly radius?: number;
}

/** Options of {@link capsule}. */
export interface CapsuleOptions<UserData = unknown> extends Common<UserData> {
  /** Distance between the centres of the two rounded ends (m), >= 0.005; along the body's x axis. */
  readonly length: number;
  /** Radius of the rounded ends (m), > 0: the capsule is 2 radius thick, length + 2 radius long. */
  readonly radius: number;
}

/** Options of {@link regularPolygon}. */
export interface RegularPolygonOptions<UserData = unknown> extends Common<UserData> {
  /** Number of sides, 3 to 8. */
  readonly sides: number;
  /** Distance from the centre to each vertex (m), > 0. */
  readonly radius: number;
}

/** Options of {@link polygon}. */
export interface PolygonOptions<UserData = unknown> extends Common<UserData> {
  /**
   * 3 to 256 points of a simple (non-self-intersecting) outline, relative to `position` (m),
   * either winding, convex or concave.
   */
  readonly vertices: readonly Vec2Like[];
  /** Rounds the corners (m), default 0; only for a convex outline of at most 8 corners. */
  readonly radius?: number;
}

/** Options of {@link wall}. */
export interface WallOptions<UserData = unknown> extends Omit<
  Common<UserData>,
  'type' | 'density'
> {
  /** Start point (m), relative to `position` (world coordinates when `position` is omitted). */
  readonly from: Vec2Like;
  /** End point (m). */
  readonly to: Vec2Like;
  /** Collide only on the positive side (the side facing up for a left-to-right wall on a y-down screen). */
  readonly oneSided?: boolean;
  /** Walls are static unless made kinematic (a moving platform). */
  readonly type?: 'static' | 'kinematic';
}

function material(options: MaterialOptions): MaterialOptions {
  const result: {
    density?: number;
    friction?: number;
    restitution?: number;
    sensor?: boolean;
    filter?: FilterOptions;
  } = {};
  if (options.density !== undefined) result.density = options.density;
  if (options.friction !== undefined) result.friction = options.friction;
  if (options.restitution !== undefined) result.restitution = options.restitution;
  if (options.sensor !== undefined) result.sensor = options.sensor;
  if (options.filter !== undefined) result.filter = options.filter;
  return result;
}

/** A circle body: the thesis's particle. Dynamic unless `type` says otherwise. */
export function particle<UserData = unknown>(options: ParticleOptions<UserData>): Body<UserData> {
  requireObject('options', options, 'an object of particle options');
  return new Body<UserData>({
    ...options,
    shapes: [{ type: 'circle', radius: options.radius, ...material(options) }],
  });
}

/** A rectangle body of `width` x `height` metres, centred on its position. */
export function box<UserData = unknown>(options: BoxOptions<UserData>): Body<UserData> {
  requireObject('options', options, 'an object of box options');
  return new Body<UserData>({
    ...options,
    shapes: [
      {
        type: 'box',
        width: options.width,
        height: options.height,
        radius: options.radius ?? 0,
        ...material(options),
      },
    ],
  });
}

/**
 * A capsule body (a pill): two half discs of `radius` joined by a rectangle, the centres of the
 * ends `length` apart along the body's x axis (horizontal until `angle` turns it), centred on its
 * position. Mass and inertia are exact.
 */
export function capsule<UserData = unknown>(options: CapsuleOptions<UserData>): Body<UserData> {
  requireObject('options', options, 'an object of capsule options');
  const length = requireFinite('length', options.length);
  if (!(length >= LINEAR_SLOP)) {
    throw new PhysicalError(
      'length',
      `must be at least ${LINEAR_SLOP} m (the distance between the end centres), got ${length}. ` +
        'For a round body use particle().',
    );
  }
  const half = 0.5 * length;
  return new Body<UserData>({
    ...options,
    shapes: [
      {
        type: 'capsule',
        center1: { x: -half, y: 0 },
        center2: { x: half, y: 0 },
        radius: options.radius,
        ...material(options),
      },
    ],
  });
}

/**
 * A regular polygon with `sides` sides (3 to 8) and circumradius `radius`, centred on its
 * position, with a vertex at angle 0 (on the +x axis) before the body's rotation.
 */
export function regularPolygon<UserData = unknown>(
  options: RegularPolygonOptions<UserData>,
): Body<UserData> {
  requireObject('options', options, 'an object of regularPolygon options');
  const sides = requireFinite('sides', options.sides);
  if (!Number.isInteger(sides) || sides < 3 || sides > MAX_POLYGON_VERTICES) {
    throw new PhysicalError(
      'sides',
      `must be a whole number from 3 to ${MAX_POLYGON_VERTICES}, got ${sides}.`,
    );
  }
  const radius = requireSize('radius', options.radius);
  const vertices: Vec2Like[] = [];
  const rotation = new Float64Array(2);
  for (let i = 0; i < sides; i++) {
    cosSin((2 * Math.PI * i) / sides, rotation);
    vertices.push({ x: radius * rotation[0]!, y: radius * rotation[1]! });
  }
  return new Body<UserData>({
    ...options,
    shapes: [{ type: 'polygon', vertices, ...material(options) }],
  });
}

/**
 * A polygon body from its outline (relative to `position`, which stays the body origin). Any
 * simple outline works: a concave one, or one with more than 8 corners, becomes several convex
 * shapes on the one body (`body.shapes` lists them) with exactly the outline's mass, centre of
 * mass and inertia. A self-intersecting outline is an error.
 */
export function polygon<UserData = unknown>(options: PolygonOptions<UserData>): Body<UserData> {
  requireObject('options', options, 'an object of polygon options');
  return new Body<UserData>({
    ...options,
    shapes: [
      {
        type: 'polygon',
        vertices: options.vertices,
        radius: options.radius ?? 0,
        ...material(options),
      },
    ],
  });
}

/**
 * A wall: a static segment from `from` to `to`. Without `position`, the points are world
 * coordinates.
 */
export function wall<UserData = unknown>(options: WallOptions<UserData>): Body<UserData> {
  requireObject('options', options, 'an object of wall options');
  return new Body<UserData>({
    ...options,
    type: options.type ?? 'static',
    shapes: [
      {
        type: 'segment',
        from: options.from,
        to: options.to,
        oneSided: options.oneSided ?? false,
        ...material(options),
      },
    ],
  });
}
