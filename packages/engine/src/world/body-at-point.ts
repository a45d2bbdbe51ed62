import { PhysicalError } from '../core/errors.ts';
import { requireObject, requireVector } from '../core/validate.ts';
import { capsuleContainsPoint } from '../geometry/capsule.ts';
import { circleContainsPoint } from '../geometry/circle.ts';
import { polygonContainsPoint } from '../geometry/polygon-queries.ts';
import type { Vec2Like } from '../math/vec2.ts';
import type { Body } from '../dynamics/body.ts';
import type { Shape } from '../dynamics/shape.ts';

/** @internal Whether a world point (m) is inside a shape at its body's pose (segments: never). */
export function shapeContainsPoint(shape: Shape, x: number, y: number): boolean {
  const g = shape.geometry;
  const xf = shape.body.transform;
  return g.kind === 'circle'
    ? circleContainsPoint(g, xf, x, y)
    : g.kind === 'polygon'
      ? polygonContainsPoint(g, xf, x, y)
      : g.kind === 'capsule' && capsuleContainsPoint(g, xf, x, y);
}

/**
 * The body of `bodies` with a shape under a world point (m), or null; the last in the list when
 * several are (it is drawn on top). `World.bodyAt` answers the same from its broad phase; this
 * tests every body, for a page that keeps copies of bodies without a `World` (a worker world's
 * page side). Throws a PhysicalError naming `point` when it is not a finite vector, `bodies` when it
 * is not an array and `bodies[i]` when an entry is not a body.
 */
export function bodyAtPoint(bodies: readonly Body[], point: Vec2Like): Body | null {
  if (!Array.isArray(bodies)) {
    throw new PhysicalError('bodies', 'must be an array.');
  }
  requireVector('point', point);
  for (let i = bodies.length - 1; i >= 0; i--) {
    const body = bodies[i]!;
    requireObject(`bodies[${i}]`, body, 'a Body');
    for (const shape of body.shapes) if (shapeContainsPoint(shape, point.x, point.y)) return body;
  }
  return null;
}
