import { PhysicalError } from '../core/errors.ts';
import { Body, type BodyType } from '../dynamics/body.ts';
import { attachBodyForce } from '../dynamics/body-forces.ts';
import { Force, type Duration } from '../dynamics/force.ts';
import { AABB } from '../geometry/aabb.ts';
import { CONVEX_PART, type Shape, type ShapeOptions } from '../dynamics/shape.ts';
import {
  MAX_ACCELERATION,
  MAX_DAMPING,
  MAX_DAMPING_RATIO,
  MAX_DENSITY,
  MAX_DURATION,
  MAX_FORCE,
  MAX_FRICTION,
  MAX_GRAVITY_SCALE,
  MAX_HERTZ,
  MAX_INERTIA,
  MAX_MASS,
  MAX_RESTITUTION,
  MAX_SPEED,
} from '../core/validate.ts';
import {
  arr,
  bool,
  describe,
  fail,
  field,
  finite,
  finites,
  int,
  MAX_ID,
  num,
  obj,
  positive,
  ranged,
  bounded,
  SAVED_ANGLE,
  SAVED_ANGULAR_SPEED,
  SAVED_COORDINATE,
  SAVED_DURATION,
  SAVED_IMPULSE,
  SAVED_SPEED,
  type Obj,
} from './snapshot-values.ts';
import type { ResolvedWorldOptions } from './world-options.ts';

// Reading a snapshot's settings and bodies (with their shapes and forces): every value checked
// as the factories and setters check it, each PhysicalError naming its field.

const BODY_TYPES: readonly BodyType[] = ['static', 'kinematic', 'dynamic'];

/** @internal The world settings a snapshot holds. */
export function readSettings(s: Obj): ResolvedWorldOptions {
  const p = 'settings';
  const gravity = finites(`${p}.gravity`, field(s, p, 'gravity'), 2).map((g, i) =>
    ranged(`${p}.gravity[${i}]`, g, -MAX_ACCELERATION, MAX_ACCELERATION),
  );
  return {
    gravityX: gravity[0]!,
    gravityY: gravity[1]!,
    subSteps: int(`${p}.subSteps`, field(s, p, 'subSteps'), 1, 64),
    restitutionThreshold: ranged(
      `${p}.restitutionThreshold`,
      field(s, p, 'restitutionThreshold'),
      0,
      MAX_SPEED,
    ),
    contactHertz: ranged(
      `${p}.contactHertz`,
      positive(`${p}.contactHertz`, field(s, p, 'contactHertz')),
      0,
      MAX_HERTZ,
    ),
    contactDampingRatio: ranged(
      `${p}.contactDampingRatio`,
      field(s, p, 'contactDampingRatio'),
      0,
      MAX_DAMPING_RATIO,
    ),
    maxContactPushSpeed: ranged(
      `${p}.maxContactPushSpeed`,
      positive(`${p}.maxContactPushSpeed`, field(s, p, 'maxContactPushSpeed')),
      0,
      MAX_SPEED,
    ),
    maxLinearSpeed: ranged(
      `${p}.maxLinearSpeed`,
      positive(`${p}.maxLinearSpeed`, field(s, p, 'maxLinearSpeed')),
      0,
      MAX_SPEED,
    ),
    enableSleep: bool(`${p}.enableSleep`, field(s, p, 'enableSleep')),
    timeToSleep: ranged(`${p}.timeToSleep`, field(s, p, 'timeToSleep'), 0, MAX_DURATION),
    enableContinuous: bool(`${p}.enableContinuous`, field(s, p, 'enableContinuous')),
  };
}

/** Shape options that rebuild the saved geometry (validated by the geometry builders). */
function geometryOptions(path: string, g: Obj): { options: ShapeOptions; exact: number[] | null } {
  const kind = field(g, path, 'kind');
  if (kind === 'circle') {
    const center = finites(`${path}.center`, field(g, path, 'center'), 2);
    return {
      options: {
        type: 'circle',
        radius: finite(`${path}.radius`, field(g, path, 'radius')),
        offset: { x: center[0]!, y: center[1]! },
      },
      exact: null,
    };
  }
  if (kind === 'polygon') {
    const vertices = arr(`${path}.vertices`, field(g, path, 'vertices'));
    if (vertices.length % 2 !== 0 || vertices.length < 6 || vertices.length > 16) {
      fail(
        `${path}.vertices`,
        `must hold 3 to 8 points as x, y pairs, got ${vertices.length} numbers.`,
      );
    }
    const xy = vertices.map((v, i) => finite(`${path}.vertices[${i}]`, v));
    const normals = finites(`${path}.normals`, field(g, path, 'normals'), xy.length);
    const centroid = finites(`${path}.centroid`, field(g, path, 'centroid'), 2);
    const points = [];
    for (let i = 0; i < xy.length; i += 2) points.push({ x: xy[i]!, y: xy[i + 1]! });
    return {
      options: {
        type: 'polygon',
        vertices: points,
        radius: finite(`${path}.radius`, field(g, path, 'radius')),
        // A saved part comes back exactly (see makeConvexPart), not cleaned as an outline.
        [CONVEX_PART]: true,
      } as ShapeOptions,
      exact: [...xy, ...normals, ...centroid],
    };
  }
  if (kind === 'segment') {
    const from = finites(`${path}.from`, field(g, path, 'from'), 2);
    const to = finites(`${path}.to`, field(g, path, 'to'), 2);
    return {
      options: {
        type: 'segment',
        from: { x: from[0]!, y: from[1]! },
        to: { x: to[0]!, y: to[1]! },
        oneSided: bool(`${path}.oneSided`, field(g, path, 'oneSided')),
      },
      exact: null,
    };
  }
  if (kind === 'capsule') {
    const center1 = finites(`${path}.center1`, field(g, path, 'center1'), 2);
    const center2 = finites(`${path}.center2`, field(g, path, 'center2'), 2);
    return {
      options: {
        type: 'capsule',
        center1: { x: center1[0]!, y: center1[1]! },
        center2: { x: center2[0]!, y: center2[1]! },
        radius: finite(`${path}.radius`, field(g, path, 'radius')),
      },
      exact: null,
    };
  }
  return fail(
    `${path}.kind`,
    `must be 'circle', 'polygon', 'capsule' or 'segment', got ${describe(kind)}.`,
  );
}

/** Writes a polygon's exact saved numbers over the rebuilt one, if they describe the same shape. */
function applyExactPolygon(path: string, shape: Shape, exact: number[]): void {
  const g = shape.geometry;
  if (g.kind !== 'polygon') return;
  const n = (exact.length - 2) / 4;
  if (g.count !== n) {
    fail(
      `${path}.vertices`,
      `is not a clean convex polygon (it rebuilds with ${g.count} vertices).`,
    );
  }
  const rebuilt = [
    ...g.vertices.subarray(0, 2 * n),
    ...g.normals.subarray(0, 2 * n),
    g.centroidX,
    g.centroidY,
  ];
  for (let i = 0; i < rebuilt.length; i++) {
    if (Math.abs(rebuilt[i]! - exact[i]!) > 1e-9 * (1 + Math.abs(exact[i]!))) {
      fail(path, 'normals or centroid do not match the vertices.');
    }
  }
  for (let i = 0; i < 2 * n; i++) {
    g.vertices[i] = exact[i]!;
    g.normals[i] = exact[2 * n + i]!;
  }
  g.centroidX = exact[4 * n]!;
  g.centroidY = exact[4 * n + 1]!;
}

function readBox(path: string, v: unknown, box: AABB): AABB {
  const b = bounded(path, v, 4, SAVED_COORDINATE);
  if (b[0]! > b[2]! || b[1]! > b[3]!) fail(path, 'must hold minX, minY, maxX, maxY in order.');
  return box.set(b[0]!, b[1]!, b[2]!, b[3]!);
}

/** @internal A body of a snapshot, built and checked; its contact list is checked by the loader. */
export function readBody(path: string, o: Obj): { body: Body; contacts: number[] } {
  const typeValue = field(o, path, 'type');
  if (!BODY_TYPES.includes(typeValue as BodyType)) {
    fail(`${path}.type`, `must be 'dynamic', 'static' or 'kinematic', got ${describe(typeValue)}.`);
  }
  const type = typeValue as BodyType;
  const shapeList = arr(`${path}.shapes`, field(o, path, 'shapes'));
  const built = shapeList.map((s, i) => {
    const sp = `${path}.shapes[${i}]`;
    const so = obj(sp, s);
    const geometry = geometryOptions(
      `${sp}.geometry`,
      obj(`${sp}.geometry`, field(so, sp, 'geometry')),
    );
    const filter = arr(`${sp}.filter`, field(so, sp, 'filter'), 3);
    const options = {
      ...geometry.options,
      density: ranged(`${sp}.density`, field(so, sp, 'density'), 0, MAX_DENSITY),
      friction: ranged(`${sp}.friction`, field(so, sp, 'friction'), 0, MAX_FRICTION),
      restitution: ranged(`${sp}.restitution`, field(so, sp, 'restitution'), 0, MAX_RESTITUTION),
      sensor: bool(`${sp}.sensor`, field(so, sp, 'sensor')),
      filter: {
        category: filter[0] as number,
        mask: filter[1] as number,
        group: filter[2] as number,
      },
    } as ShapeOptions;
    return { so, sp, options, exact: geometry.exact };
  });
  const massOverride = ranged(`${path}.massOverride`, field(o, path, 'massOverride'), 0, MAX_MASS);
  const inertiaOverride = ranged(
    `${path}.inertiaOverride`,
    field(o, path, 'inertiaOverride'),
    0,
    MAX_INERTIA,
  );
  const fixedRotation = bool(`${path}.fixedRotation`, field(o, path, 'fixedRotation'));
  let body: Body;
  try {
    body = new Body({
      type,
      shapes: built.map((b) => b.options),
      fixedRotation,
      ...(massOverride > 0 ? { mass: massOverride } : {}),
      ...(inertiaOverride > 0 ? { inertia: inertiaOverride } : {}),
    });
  } catch (error) {
    if (error instanceof PhysicalError) {
      // The builders name fields like 'shapes[0].radius': put them under this body.
      fail(`${path}.${error.field}`, error.message.slice(error.field.length + 2));
    }
    throw error;
  }
  const box = new AABB();
  built.forEach((b, i) => {
    const shape = body.shapeList[i]!;
    if (b.exact !== null) applyExactPolygon(`${b.sp}.geometry`, shape, b.exact);
    shape.setTightBox(readBox(`${b.sp}.aabb`, field(b.so, b.sp, 'aabb'), box));
    shape.setFatBox(readBox(`${b.sp}.fatAABB`, field(b.so, b.sp, 'fatAABB'), box));
    shape.id = int(`${b.sp}.id`, field(b.so, b.sp, 'id'), 0, MAX_ID);
    shape.proxyKey = int(`${b.sp}.proxyKey`, field(b.so, b.sp, 'proxyKey'), 0, 0x7fffffff);
    // The key names the tree (its low two bits, 3 is none); a body whose type the app wrote
    // keeps its proxies in the tree of its old type, so any tree is taken.
    if ((shape.proxyKey & 3) === 3) fail(`${b.sp}.proxyKey`, 'names no tree.');
  });
  // The mass was computed from the shapes again (the same arithmetic); polygons may have been
  // rewritten with their exact numbers just now, so compute it once more from those.
  body.updateMassData();

  const xf = finites(`${path}.transform`, field(o, path, 'transform'), 4);
  ranged(`${path}.transform[0]`, xf[0], -SAVED_COORDINATE, SAVED_COORDINATE);
  ranged(`${path}.transform[1]`, xf[1], -SAVED_COORDINATE, SAVED_COORDINATE);
  // The saved cosine and sine are used as they are (the solver integrates them), so they must
  // be a rotation: a unit vector, within what integration and normalization leave.
  if (Math.abs(xf[2]! * xf[2]! + xf[3]! * xf[3]! - 1) > 1e-6) {
    fail(
      `${path}.transform`,
      `must hold a rotation (cos^2 + sin^2 = 1), got cos ${xf[2]} and sin ${xf[3]}.`,
    );
  }
  body.transform.x = xf[0]!;
  body.transform.y = xf[1]!;
  body.transform.c = xf[2]!;
  body.transform.s = xf[3]!;
  body.angleValue = ranged(`${path}.angle`, field(o, path, 'angle'), -SAVED_ANGLE, SAVED_ANGLE);
  const center = bounded(`${path}.center`, field(o, path, 'center'), 2, SAVED_COORDINATE);
  body.centerX = center[0]!;
  body.centerY = center[1]!;
  const start = finites(`${path}.start`, field(o, path, 'start'), 3);
  ranged(`${path}.start[0]`, start[0], -SAVED_COORDINATE, SAVED_COORDINATE);
  ranged(`${path}.start[1]`, start[1], -SAVED_COORDINATE, SAVED_COORDINATE);
  ranged(`${path}.start[2]`, start[2], -SAVED_ANGLE, SAVED_ANGLE);
  body.center0X = start[0]!;
  body.center0Y = start[1]!;
  body.angle0 = start[2]!;
  const velocity = finites(`${path}.velocity`, field(o, path, 'velocity'), 3);
  ranged(`${path}.velocity[0]`, velocity[0], -SAVED_SPEED, SAVED_SPEED);
  ranged(`${path}.velocity[1]`, velocity[1], -SAVED_SPEED, SAVED_SPEED);
  ranged(`${path}.velocity[2]`, velocity[2], -SAVED_ANGULAR_SPEED, SAVED_ANGULAR_SPEED);
  body.velocityX = velocity[0]!;
  body.velocityY = velocity[1]!;
  body.angularVelocityValue = velocity[2]!;
  const applied = bounded(`${path}.applied`, field(o, path, 'applied'), 3, SAVED_IMPULSE);
  body.forceX = applied[0]!;
  body.forceY = applied[1]!;
  body.torqueValue = applied[2]!;
  body.gravityScaleValue = ranged(
    `${path}.gravityScale`,
    field(o, path, 'gravityScale'),
    -MAX_GRAVITY_SCALE,
    MAX_GRAVITY_SCALE,
  );
  body.linearDampingValue = ranged(
    `${path}.linearDamping`,
    field(o, path, 'linearDamping'),
    0,
    MAX_DAMPING,
  );
  body.angularDampingValue = ranged(
    `${path}.angularDamping`,
    field(o, path, 'angularDamping'),
    0,
    MAX_DAMPING,
  );
  body.dragValue = ranged(`${path}.drag`, field(o, path, 'drag'), 0, MAX_DAMPING);
  body.allowSleepValue = bool(`${path}.allowSleep`, field(o, path, 'allowSleep'));
  body.bulletValue = bool(`${path}.bullet`, field(o, path, 'bullet'));
  body.id = int(`${path}.id`, field(o, path, 'id'), 0, MAX_ID);
  body.islandStamp = int(
    `${path}.islandStamp`,
    field(o, path, 'islandStamp'),
    0,
    Number.MAX_SAFE_INTEGER,
  );

  // A body the app made static or kinematic by writing `body.type` keeps its forces (unused):
  // the snapshot takes every state the API can make, so the world's own snapshot restores.
  const forces = arr(`${path}.forces`, field(o, path, 'forces'));
  forces.forEach((f, i) => {
    const fp = `${path}.forces[${i}]`;
    const fo = obj(fp, f);
    const vector = finites(`${fp}.vector`, field(fo, fp, 'vector'), 2).map((v, k) =>
      ranged(`${fp}.vector[${k}]`, v, -MAX_FORCE, MAX_FORCE),
    );
    const torque = ranged(`${fp}.torque`, field(fo, fp, 'torque'), -MAX_FORCE, MAX_FORCE);
    const durationValue = field(fo, fp, 'duration');
    let duration: Duration;
    if (durationValue === 'constant' || durationValue === 'instant') duration = durationValue;
    else duration = ranged(`${fp}.duration`, durationValue, Number.MIN_VALUE, MAX_DURATION);
    const remaining = num(`${fp}.remaining`, field(fo, fp, 'remaining'));
    if (remaining !== Infinity && !(Math.abs(remaining) <= MAX_DURATION))
      fail(`${fp}.remaining`, `must be Infinity or from -1 to ${MAX_DURATION}, got ${remaining}.`);
    const point = field(fo, fp, 'point');
    if (remaining !== Infinity && remaining < 0 && (duration !== 'instant' || remaining !== -1))
      fail(
        `${fp}.remaining`,
        `must be zero or more (or -1 for an instant force), got ${remaining}.`,
      );
    const force = new Force(0, 0, 0, duration);
    // Body.applyForce refuses non-dynamic bodies; a restored body takes its saved forces as they
    // were (attachBodyForce is what applyForce ends with).
    attachBodyForce(body, force);
    force.xValue = vector[0]!;
    force.yValue = vector[1]!;
    force.torqueValue = torque;
    force.remainingValue = remaining;
    if (point !== null) {
      const local = bounded(`${fp}.point`, point, 2, SAVED_COORDINATE);
      force.localPointX = local[0]!;
      force.localPointY = local[1]!;
      force.hasPoint = true;
    }
  });
  // Set after the forces: attaching a force wakes the body.
  body.awake = bool(`${path}.awake`, field(o, path, 'awake'));
  body.sleepTime = ranged(`${path}.sleepTime`, field(o, path, 'sleepTime'), 0, SAVED_DURATION);
  const contacts = arr(`${path}.contacts`, field(o, path, 'contacts')).map((c, i) =>
    int(`${path}.contacts[${i}]`, c, 0, MAX_ID),
  );
  return { body, contacts };
}
