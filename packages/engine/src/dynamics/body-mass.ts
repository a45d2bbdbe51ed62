import { PhysicalError } from '../core/errors.ts';
import { MAX_MASS, MIN_INERTIA, MIN_MASS } from '../core/validate.ts';
import { computeCapsuleMass } from '../geometry/capsule.ts';
import { computeCircleMass } from '../geometry/circle.ts';
import { MassData } from '../geometry/mass-data.ts';
import { computePolygonMass } from '../geometry/polygon-mass.ts';
import { hypot } from '../math/hypot.ts';
import type { Body } from './body.ts';
import type { Shape } from './shape.ts';

// A body's mass properties from its shapes: mass, centre of mass and rotational inertia (the
// parallel-axis theorem combines the shapes about their common centre), the overrides an app
// set, and the extents sleep and continuous collision use. Written into the body's numbers
// (body-memory.ts) through its accessors.

/** @internal A body's mass properties, computed before they are installed. */
export interface MassResult {
  mass: number;
  inertia: number;
  centerX: number;
  centerY: number;
}

const scratchMass = new MassData();

/**
 * @internal Mass, centre of mass and inertia of a list of shapes (parallel-axis theorem to combine them
 * about the common centre), then the overrides; throws, changing nothing, when a dynamic body
 * would get no valid mass. Callers compute first and commit only a valid result.
 */
export function computeBodyMass(
  body: Body,
  shapes: readonly Shape[],
  massOverride: number = body.massOverride,
  inertiaOverride: number = body.inertiaOverride,
  fixedRotation: boolean = body.fixedRotationValue,
): MassResult {
  const result: MassResult = { mass: 0, inertia: 0, centerX: 0, centerY: 0 };
  if (body.type !== 'dynamic') return result;
  let mass = 0;
  let cx = 0;
  let cy = 0;
  let inertiaAtOrigin = 0;
  for (let i = 0; i < shapes.length; i++) {
    const shape = shapes[i]!;
    const g = shape.geometry;
    if (g.kind === 'segment') {
      throw new PhysicalError(
        `shapes[${i}]`,
        'a segment has no area and so no mass: put walls on a static or kinematic body.',
      );
    }
    if (shape.density <= 0 && massOverride === 0) {
      throw new PhysicalError(
        `shapes[${i}].density`,
        `must be greater than zero on a dynamic body, got ${shape.density} (or set the body's mass).`,
      );
    }
    const data =
      g.kind === 'circle'
        ? computeCircleMass(g, shape.density, scratchMass)
        : g.kind === 'capsule'
          ? computeCapsuleMass(g, shape.density, scratchMass)
          : computePolygonMass(g, shape.density, scratchMass);
    mass += data.mass;
    cx += data.mass * data.centerX;
    cy += data.mass * data.centerY;
    inertiaAtOrigin +=
      data.rotationalInertia +
      data.mass * (data.centerX * data.centerX + data.centerY * data.centerY);
  }
  if (mass > 0) {
    cx /= mass;
    cy /= mass;
  }
  let inertia = inertiaAtOrigin - mass * (cx * cx + cy * cy);
  if (massOverride > 0) {
    // Same shape, different density: inertia scales with mass. A point mass has none.
    inertia = mass > 0 ? (inertia * massOverride) / mass : 0;
    mass = massOverride;
  }
  if (!(mass > 0)) {
    throw new PhysicalError(
      'mass',
      'a dynamic body needs a positive mass: give it a shape with density > 0, or set `mass`.',
    );
  }
  if (mass < MIN_MASS || mass > MAX_MASS || !Number.isFinite(cx) || !Number.isFinite(cy)) {
    throw new PhysicalError(
      'mass',
      `must be from ${MIN_MASS} to ${MAX_MASS} kg; the shapes and density give ${mass}. ` +
        'Change the density or the sizes, or set `mass`.',
    );
  }
  if (inertiaOverride > 0) inertia = inertiaOverride;
  result.mass = mass;
  result.centerX = cx;
  result.centerY = cy;
  // Below the smallest inertia the rotation would be numerically free: treat it as none.
  if (!fixedRotation && inertia >= MIN_INERTIA && Number.isFinite(inertia)) {
    result.inertia = inertia;
  }
  return result;
}

/** @internal Installs a mass computed by {@link computeBodyMass} for the body's shapes and settings. */
export function commitBodyMass(body: Body, data: MassResult): void {
  body.massValue = data.mass;
  body.invMass = data.mass > 0 ? 1 / data.mass : 0;
  body.inertiaValue = data.inertia;
  body.invInertia = data.inertia > 0 ? 1 / data.inertia : 0;
  body.localCenterX = data.centerX;
  body.localCenterY = data.centerY;
  body.syncCenter();
  computeExtents(body);
}

/** Largest and smallest reach of the shapes from the centre of mass, for sleep and continuous collision. */
function computeExtents(body: Body): void {
  let maxExtent = 0;
  let minExtent = Infinity;
  const cx = body.localCenterX;
  const cy = body.localCenterY;
  for (const shape of body.shapeList) {
    const g = shape.geometry;
    if (g.kind === 'circle') {
      const d = hypot(g.centerX - cx, g.centerY - cy);
      maxExtent = Math.max(maxExtent, d + g.radius);
      minExtent = Math.min(minExtent, g.radius);
    } else if (g.kind === 'polygon') {
      let inner = Infinity;
      for (let i = 0; i < g.count; i++) {
        const vx = g.vertices[2 * i]!;
        const vy = g.vertices[2 * i + 1]!;
        maxExtent = Math.max(maxExtent, hypot(vx - cx, vy - cy) + g.radius);
        // Distance from the centroid to each edge: the polygon's inradius bound.
        const d =
          (vx - g.centroidX) * g.normals[2 * i]! + (vy - g.centroidY) * g.normals[2 * i + 1]!;
        inner = Math.min(inner, d);
      }
      minExtent = Math.min(minExtent, inner + g.radius);
    } else if (g.kind === 'capsule') {
      maxExtent = Math.max(
        maxExtent,
        hypot(g.x1 - cx, g.y1 - cy) + g.radius,
        hypot(g.x2 - cx, g.y2 - cy) + g.radius,
      );
      minExtent = Math.min(minExtent, g.radius);
    } else {
      maxExtent = Math.max(maxExtent, hypot(g.x1 - cx, g.y1 - cy), hypot(g.x2 - cx, g.y2 - cy));
      minExtent = 0;
    }
  }
  body.maxExtent = maxExtent;
  body.minExtent = minExtent === Infinity ? 0 : minExtent;
  body.originReach = maxExtent + hypot(cx, cy);
}
