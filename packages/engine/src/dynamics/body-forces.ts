import { PhysicalError } from '../core/errors.ts';
import {
  describeValue,
  MAX_FORCE,
  optionalObject,
  requireRange,
  requireVector,
} from '../core/validate.ts';
import type { Vec2Like } from '../math/vec2.ts';
import type { Body } from './body.ts';
import { requireDynamic } from './body-options.ts';
import { Force, validateDuration, type ForceOptions, type TorqueOptions } from './force.ts';

// What acts on a body from outside: forces and torques with a duration (force.ts; summed into
// the body's numbers each step by Solver.gatherBodies) and impulses, which change its velocity
// at once. The Body methods of the same names call these.

/** @internal {@link Body.applyForce}. */
export function applyBodyForce(body: Body, force: Vec2Like, options: ForceOptions): Force {
  requireDynamic(body.type, 'applyForce');
  requireVector('force', force, MAX_FORCE);
  optionalObject(
    'options',
    options,
    "an object { duration?, point? }, for example { duration: 'constant' }",
  );
  const duration = validateDuration(options.duration ?? 'instant');
  if (options.point !== undefined) requireVector('point', options.point);
  const result = new Force(force.x, force.y, 0, duration);
  if (options.point !== undefined) {
    // Attach the point to the body so it turns with it.
    const local = body.getLocalPoint(options.point);
    result.localPointX = local.x;
    result.localPointY = local.y;
    result.hasPoint = true;
  }
  attachBodyForce(body, result);
  return result;
}

/** @internal {@link Body.applyTorque}. */
export function applyBodyTorque(body: Body, torque: number, options: TorqueOptions): Force {
  requireDynamic(body.type, 'applyTorque');
  requireRange('torque', torque, -MAX_FORCE, MAX_FORCE, 'N m');
  optionalObject(
    'options',
    options,
    "an object { duration? }, for example { duration: 'constant' }",
  );
  const result = new Force(0, 0, torque, validateDuration(options.duration ?? 'instant'));
  attachBodyForce(body, result);
  return result;
}

/** @internal {@link Body.removeForce}. */
export function removeBodyForce(body: Body, force: Force): void {
  if (!(force instanceof Force)) {
    throw new PhysicalError('force', `must be a Force, got ${describeValue(force)}.`);
  }
  const list = body.forceList;
  const index = list.indexOf(force);
  if (index < 0) return;
  list.splice(index, 1);
  force.onRemove = null;
  force.onChange = null;
}

/** @internal {@link Body.clearForces}. */
export function clearBodyForces(body: Body): void {
  for (const force of body.forceList) {
    force.onRemove = null;
    force.onChange = null;
  }
  body.forceList.length = 0;
}

/** @internal {@link Body.applyImpulse}: Δv = J / m, Δω = (r x J) / I. */
export function applyBodyImpulse(body: Body, impulse: Vec2Like, point?: Vec2Like): void {
  requireDynamic(body.type, 'applyImpulse');
  requireVector('impulse', impulse, MAX_FORCE);
  if (point !== undefined) requireVector('point', point);
  body.velocityX += body.invMass * impulse.x;
  body.velocityY += body.invMass * impulse.y;
  if (point !== undefined) {
    const rx = point.x - body.centerX;
    const ry = point.y - body.centerY;
    body.angularVelocityValue += body.invInertia * (rx * impulse.y - ry * impulse.x);
  }
  body.wake();
}

/** @internal {@link Body.applyAngularImpulse}: Δω = L / I. */
export function applyBodyAngularImpulse(body: Body, impulse: number): void {
  requireDynamic(body.type, 'applyAngularImpulse');
  requireRange('impulse', impulse, -MAX_FORCE, MAX_FORCE, 'N m s');
  body.angularVelocityValue += body.invInertia * impulse;
  body.wake();
}

/**
 * @internal A new force joins the body (applyForce and applyTorque end with it, a snapshot's forces
 * join with it): it removes itself and wakes the body through these.
 */
export function attachBodyForce(body: Body, force: Force): void {
  force.onRemove = (f) => body.removeForce(f);
  force.onChange = () => body.wake();
  body.forceList.push(force);
  body.wake();
}
