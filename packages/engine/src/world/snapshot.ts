import { exportBroadPhaseState, importBroadPhaseState } from '../collision/broad-phase-state.ts';
import type { BroadPhase, BroadPhaseState } from '../collision/broad-phase.ts';
import { checkTreeState, type TreeState } from '../collision/dynamic-tree.ts';
import { PhysicalError } from '../core/errors.ts';
import { Body, type BodyType } from '../dynamics/body.ts';
import {
  BOUNCING_STEPS,
  CONTACT_STRIDE,
  FRICTION,
  HAS_CACHE,
  POINT_COUNT,
  RESTITUTION,
} from '../dynamics/contact-data.ts';
import type { Contact } from '../dynamics/contact.ts';
import type { ContactManager } from '../dynamics/contact-manager.ts';
import type { Duration } from '../dynamics/force.ts';
import type { Islands } from '../dynamics/island.ts';
import type { Sensors } from '../dynamics/sensor.ts';
import { CONVEX_PART, type Shape, type ShapeOptions } from '../dynamics/shape.ts';
import type { ShapeTable } from '../dynamics/shape-table.ts';
import type { Joint } from '../dynamics/joints/joint.ts';
import { buildJoint, readJoint, saveJoint, type JointPlan } from './joint-snapshot.ts';
import {
  arr,
  bool,
  describe,
  enc,
  encAll,
  fail,
  field,
  finite,
  finites,
  int,
  MAX_ID,
  nonNegative,
  num,
  obj,
  positive,
  ranged,
  type Obj,
  type SnapshotValue,
} from './snapshot-values.ts';
import type { ResolvedWorldOptions } from './world-options.ts';
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
  MAX_TIME_STEP,
  MIN_TIME_STEP,
} from '../core/validate.ts';
import { World } from './world.ts';

// World snapshots: everything that decides future steps, as plain JSON-compatible data, so that
// restoring and stepping gives bit-for-bit the states of never having saved.
//
// What that takes beyond the bodies' poses and velocities: the exact transform (cosine and sine
// are not recomputed from the angle: the solver integrates them), the centre of mass and the
// step-start pose, sleep timers and island stamps, forces with the time they have left, every
// contact in list order with its manifold, warm-start impulses and reuse cache, each body's
// contact list order (removals swap-remove through it), the broad phase's three trees node by
// node (their shape decides the order in which new pairs, hence contacts, are found), shape ids
// and the free-id stack, the sensors' overlap lists, the step counters, and every joint in list
// order with its frames, settings and warm-start impulses (joint-snapshot.ts). Numbers are
// written as snapshot-values.ts describes (-0 and infinities survive JSON).
//
// Not saved: listeners, userData and the Force objects an app holds (the restored world has new
// ones, in the same order: world.bodies[i] is the body that was at i, body.forces[j] and
// world.joints[k] likewise).
//
// takeSnapshot and restoreSnapshot are free functions, not World methods, so that an app that
// never calls them bundles neither this code nor every joint kind joint-snapshot.ts imports.

export type { SnapshotNumber, SnapshotValue } from './snapshot-values.ts';

/** The format name every snapshot carries. */
export const SNAPSHOT_FORMAT = 'physical-world';
/**
 * The snapshot layout this version writes. It also reads version 1, whose contacts lack the
 * count of steps in a row they bounced (read as 0).
 */
export const SNAPSHOT_VERSION = 2;

/**
 * A saved world ({@link takeSnapshot}): plain data, safe for `JSON.stringify`. Its sections are
 * `settings`, `world` (counters), `bodies` (with their shapes and forces), `contacts`, `sensors`,
 * `broadPhase` and `joints`. Treat the contents as opaque: the layout may change with `version`.
 */
export interface WorldSnapshot {
  readonly format: typeof SNAPSHOT_FORMAT;
  readonly version: 1 | typeof SNAPSHOT_VERSION;
  readonly settings: Readonly<Record<string, SnapshotValue>>;
  readonly world: Readonly<Record<string, SnapshotValue>>;
  readonly bodies: readonly Readonly<Record<string, SnapshotValue>>[];
  readonly contacts: readonly Readonly<Record<string, SnapshotValue>>[];
  readonly sensors: readonly Readonly<Record<string, SnapshotValue>>[];
  readonly broadPhase: Readonly<Record<string, SnapshotValue>>;
  /** The joints, in `world.joints` order, their bodies named by index in `bodies`. */
  readonly joints: readonly Readonly<Record<string, SnapshotValue>>[];
}

/** @internal The parts of a world a snapshot reads and writes. */
export interface WorldInternals {
  readonly world: World;
  readonly settings: ResolvedWorldOptions;
  readonly bodies: Body[];
  readonly joints: Joint[];
  readonly broadPhase: BroadPhase;
  readonly islands: Islands;
  readonly contactManager: ContactManager;
  readonly sensors: Sensors;
  readonly shapesById: (Shape | null)[];
  readonly shapeTable: ShapeTable;
  readonly freeShapeIds: number[];
  nextBodyId: number;
  stepCount: number;
  lastStep: number;
}

/**
 * Saves everything that decides the world's future as plain, JSON-compatible data: restoring it
 * with {@link restoreSnapshot} and stepping gives bit-for-bit the states this world reaches.
 * Listeners, `userData` and the app's Force objects are not saved. Not allowed during a step:
 * from a listener it throws a PhysicalError.
 *
 * @example
 * const saved = JSON.stringify(takeSnapshot(world));
 * // later, or elsewhere
 * const copy = restoreSnapshot(JSON.parse(saved));
 */
export function takeSnapshot(world: World): WorldSnapshot {
  if (!(world instanceof World)) {
    throw new PhysicalError('world', `must be a World, got ${describe(world)}.`);
  }
  if (world.isStepping) {
    throw new PhysicalError(
      'snapshot',
      'cannot be taken while the world is stepping (from a listener); take it after step().',
    );
  }
  return saveWorld(world.internals());
}

/**
 * A new world from a {@link takeSnapshot} result (a parsed JSON copy is fine), its bodies in the
 * saved order. Checks the whole snapshot first: a wrong format or version, a missing or
 * non-numeric field or a broken reference throws a PhysicalError naming the field
 * (`snapshot.bodies[2].angle`), and no world is returned.
 *
 * @example
 * const checkpoint = takeSnapshot(world);
 * world.step();
 * const rewound = restoreSnapshot(checkpoint); // the world as it was before that step
 */
export function restoreSnapshot(snapshot: WorldSnapshot): World {
  const world = new World();
  loadWorld(world.internals(), snapshot);
  return world;
}

// ------------------------------------------------------------------ saving

function saveGeometry(shape: Shape): SnapshotValue {
  const g = shape.geometry;
  if (g.kind === 'circle') {
    return { kind: 'circle', center: encAll([g.centerX, g.centerY]), radius: enc(g.radius) };
  }
  if (g.kind === 'polygon') {
    return {
      kind: 'polygon',
      vertices: encAll(g.vertices, 2 * g.count),
      normals: encAll(g.normals, 2 * g.count),
      centroid: encAll([g.centroidX, g.centroidY]),
      radius: enc(g.radius),
    };
  }
  if (g.kind === 'capsule') {
    return {
      kind: 'capsule',
      center1: encAll([g.x1, g.y1]),
      center2: encAll([g.x2, g.y2]),
      radius: enc(g.radius),
    };
  }
  return {
    kind: 'segment',
    from: encAll([g.x1, g.y1]),
    to: encAll([g.x2, g.y2]),
    oneSided: g.oneSided,
  };
}

function saveShape(shape: Shape): SnapshotValue {
  return {
    id: shape.id,
    proxyKey: shape.proxyKey,
    geometry: saveGeometry(shape),
    density: enc(shape.density),
    friction: enc(shape.friction),
    restitution: enc(shape.restitution),
    sensor: shape.sensor,
    filter: [shape.categoryBits, shape.maskBits, shape.groupIndex],
    aabb: encAll([shape.aabb.minX, shape.aabb.minY, shape.aabb.maxX, shape.aabb.maxY]),
    fatAABB: encAll([
      shape.fatAABB.minX,
      shape.fatAABB.minY,
      shape.fatAABB.maxX,
      shape.fatAABB.maxY,
    ]),
  };
}

function saveBody(body: Body, contactIndex: Map<Contact, number>): Record<string, SnapshotValue> {
  const xf = body.transform;
  return {
    id: body.id,
    type: body.type,
    transform: encAll([xf.x, xf.y, xf.c, xf.s]),
    angle: enc(body.angleValue),
    center: encAll([body.centerX, body.centerY]),
    start: encAll([body.center0X, body.center0Y, body.angle0]),
    velocity: encAll([body.velocityX, body.velocityY, body.angularVelocityValue]),
    // These start as -0 (a double for V8, see body.ts); + 0 saves them as 0. Their sign never
    // matters: forces are summed again each step, the others are compared or added to.
    applied: encAll([body.forceX + 0, body.forceY + 0, body.torqueValue + 0]),
    massOverride: enc(body.massOverride + 0),
    inertiaOverride: enc(body.inertiaOverride + 0),
    gravityScale: enc(body.gravityScaleValue),
    linearDamping: enc(body.linearDampingValue),
    angularDamping: enc(body.angularDampingValue),
    drag: enc(body.dragValue),
    fixedRotation: body.fixedRotationValue,
    allowSleep: body.allowSleepValue,
    bullet: body.bulletValue,
    awake: body.awake,
    sleepTime: enc(body.sleepTime + 0),
    islandStamp: body.islandStamp,
    shapes: body.shapeList.map(saveShape),
    forces: body.forceList.map((f) => ({
      vector: encAll([f.x, f.y]),
      torque: enc(f.torque),
      point: f.hasPoint ? encAll([f.localPointX, f.localPointY]) : null,
      duration: typeof f.duration === 'number' ? enc(f.duration) : f.duration,
      remaining: enc(f.remaining),
    })),
    contacts: body.contacts.map((c) => contactIndex.get(c)!),
  };
}

function saveContact(contact: Contact, data: Float64Array): Record<string, SnapshotValue> {
  // The contact's numbers (manifold, warm-start impulses, reuse cache) are one slot of the
  // contact data: saved whole, in the slot's own layout (see dynamics/contact-data.ts).
  const base = contact.index * CONTACT_STRIDE;
  return {
    shapes: [contact.shapeA.id, contact.shapeB.id],
    touching: contact.touching,
    data: encAll(data.subarray(base, base + CONTACT_STRIDE)),
  };
}

function saveTree(tree: TreeState): SnapshotValue {
  return { ...tree, boxes: encAll(tree.boxes) };
}

/** Writes a world's state as a snapshot. */
function saveWorld(w: WorldInternals): WorldSnapshot {
  const s = w.settings;
  const contactIndex = new Map<Contact, number>();
  w.contactManager.contacts.forEach((c, i) => contactIndex.set(c, i));
  const broadPhase = exportBroadPhaseState(w.broadPhase);
  return {
    format: SNAPSHOT_FORMAT,
    version: SNAPSHOT_VERSION,
    settings: {
      gravity: encAll([s.gravityX, s.gravityY]),
      subSteps: s.subSteps,
      restitutionThreshold: enc(s.restitutionThreshold),
      contactHertz: enc(s.contactHertz),
      contactDampingRatio: enc(s.contactDampingRatio),
      maxContactPushSpeed: enc(s.maxContactPushSpeed),
      maxLinearSpeed: enc(s.maxLinearSpeed),
      enableSleep: s.enableSleep,
      timeToSleep: enc(s.timeToSleep),
      enableContinuous: s.enableContinuous,
    },
    world: {
      steps: w.stepCount,
      lastStep: enc(w.lastStep),
      nextBodyId: w.nextBodyId,
      islandStamp: w.islands.stamp,
      shapeSlots: w.shapesById.length,
      freeShapeIds: w.freeShapeIds.slice(),
    },
    bodies: w.bodies.map((b) => saveBody(b, contactIndex)),
    contacts: w.contactManager.contacts.map((c) => saveContact(c, w.contactManager.slots.data)),
    sensors: w.sensors.shapes.map((shape, i) => ({
      shape: shape.id,
      visitors: w.sensors.overlaps[i]!.map((v) => v.id),
    })),
    broadPhase: {
      trees: broadPhase.trees.map(saveTree),
      moved: broadPhase.moved.slice(),
    },
    joints: w.joints.map(saveJoint),
  };
}

// ------------------------------------------------------------------ reading

const BODY_TYPES: readonly BodyType[] = ['static', 'kinematic', 'dynamic'];
const PROXY_TYPE: Record<BodyType, number> = { static: 0, kinematic: 1, dynamic: 2 };

// ------------------------------------------------------------------ loading

function readSettings(s: Obj): ResolvedWorldOptions {
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

function readBox(
  path: string,
  v: unknown,
  box: { set(a: number, b: number, c: number, d: number): unknown },
): void {
  const b = finites(path, v, 4);
  box.set(b[0]!, b[1]!, b[2]!, b[3]!);
}

function readBody(path: string, o: Obj): { body: Body; contacts: number[] } {
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
  built.forEach((b, i) => {
    const shape = body.shapeList[i]!;
    if (b.exact !== null) applyExactPolygon(`${b.sp}.geometry`, shape, b.exact);
    readBox(`${b.sp}.aabb`, field(b.so, b.sp, 'aabb'), shape.aabb);
    readBox(`${b.sp}.fatAABB`, field(b.so, b.sp, 'fatAABB'), shape.fatAABB);
    shape.id = int(`${b.sp}.id`, field(b.so, b.sp, 'id'), 0, MAX_ID);
    shape.proxyKey = int(`${b.sp}.proxyKey`, field(b.so, b.sp, 'proxyKey'), 0, 0x7fffffff);
    if ((shape.proxyKey & 3) !== PROXY_TYPE[type]) {
      fail(`${b.sp}.proxyKey`, `does not belong to a ${type} body's tree.`);
    }
  });
  // The mass was computed from the shapes again (the same arithmetic); polygons may have been
  // rewritten with their exact numbers just now, so compute it once more from those.
  body.updateMassData();

  const xf = finites(`${path}.transform`, field(o, path, 'transform'), 4);
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
  body.angleValue = finite(`${path}.angle`, field(o, path, 'angle'));
  const center = finites(`${path}.center`, field(o, path, 'center'), 2);
  body.centerX = center[0]!;
  body.centerY = center[1]!;
  const start = finites(`${path}.start`, field(o, path, 'start'), 3);
  body.center0X = start[0]!;
  body.center0Y = start[1]!;
  body.angle0 = start[2]!;
  const velocity = finites(`${path}.velocity`, field(o, path, 'velocity'), 3);
  body.velocityX = velocity[0]!;
  body.velocityY = velocity[1]!;
  body.angularVelocityValue = velocity[2]!;
  const applied = finites(`${path}.applied`, field(o, path, 'applied'), 3);
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

  const forces = arr(`${path}.forces`, field(o, path, 'forces'));
  if (forces.length > 0 && type !== 'dynamic')
    fail(`${path}.forces`, `must be empty on a ${type} body.`);
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
    if (remaining !== Infinity && !Number.isFinite(remaining))
      fail(`${fp}.remaining`, 'must be finite or Infinity.');
    const point = field(fo, fp, 'point');
    if (remaining !== Infinity && remaining < 0 && (duration !== 'instant' || remaining !== -1))
      fail(
        `${fp}.remaining`,
        `must be zero or more (or -1 for an instant force), got ${remaining}.`,
      );
    const force = body.applyForce({ x: 0, y: 0 }, { duration });
    force.xValue = vector[0]!;
    force.yValue = vector[1]!;
    force.torqueValue = torque;
    force.remainingValue = remaining;
    if (point !== null) {
      const local = finites(`${fp}.point`, point, 2);
      force.localPointX = local[0]!;
      force.localPointY = local[1]!;
      force.hasPoint = true;
    }
  });
  // Set after the forces: attaching a force wakes the body.
  body.awake = bool(`${path}.awake`, field(o, path, 'awake'));
  if (type === 'static' && body.awake) fail(`${path}.awake`, 'must be false on a static body.');
  body.sleepTime = nonNegative(`${path}.sleepTime`, field(o, path, 'sleepTime'));
  const contacts = arr(`${path}.contacts`, field(o, path, 'contacts')).map((c, i) =>
    int(`${path}.contacts[${i}]`, c, 0, MAX_ID),
  );
  return { body, contacts };
}

function readTree(path: string, v: unknown): TreeState {
  const o = obj(path, v);
  const ints = (key: string): number[] =>
    arr(`${path}.${key}`, field(o, path, key)).map((x) => (typeof x === 'number' ? x : NaN));
  const state: TreeState = {
    capacity: int(`${path}.capacity`, field(o, path, 'capacity'), 2, 1 << 26),
    root: int(`${path}.root`, field(o, path, 'root'), -1, 1 << 26),
    freeList: int(`${path}.freeList`, field(o, path, 'freeList'), -1, 1 << 26),
    leafCount: int(`${path}.leafCount`, field(o, path, 'leafCount'), 0, 1 << 26),
    boxes: arr(`${path}.boxes`, field(o, path, 'boxes')).map((x, i) =>
      num(`${path}.boxes[${i}]`, x),
    ),
    child1: ints('child1'),
    child2: ints('child2'),
    parent: ints('parent'),
    heights: ints('heights'),
    userData: ints('userData'),
  };
  const problem = checkTreeState(state);
  if (problem !== null) fail(path, `is not a valid tree: ${problem}.`);
  return state;
}

/**
 * Loads a snapshot into a newly made, empty world. Validates every section and every reference
 * before it returns; on error it throws a PhysicalError naming the field, and the caller drops
 * the half-built world.
 */
function loadWorld(w: WorldInternals, snapshot: unknown): void {
  const root = obj('', snapshot);
  const format = root['format'];
  if (format !== SNAPSHOT_FORMAT) {
    fail(
      'format',
      `must be '${SNAPSHOT_FORMAT}' (this is not a Physical world snapshot), got ${describe(format)}.`,
    );
  }
  const version = root['version'];
  if (version !== SNAPSHOT_VERSION && version !== 1) {
    fail(
      'version',
      `must be 1 or ${SNAPSHOT_VERSION}, the versions this Physical reads; got ${describe(version)}.`,
    );
  }
  Object.assign(w.settings, readSettings(obj('settings', field(root, '', 'settings'))));

  const counters = obj('world', field(root, '', 'world'));
  w.stepCount = int('world.steps', field(counters, 'world', 'steps'), 0, Number.MAX_SAFE_INTEGER);
  w.lastStep = ranged(
    'world.lastStep',
    positive('world.lastStep', field(counters, 'world', 'lastStep')),
    MIN_TIME_STEP,
    MAX_TIME_STEP,
  );
  w.nextBodyId = int('world.nextBodyId', field(counters, 'world', 'nextBodyId'), 0, MAX_ID);
  w.islands.stamp = int(
    'world.islandStamp',
    field(counters, 'world', 'islandStamp'),
    0,
    Number.MAX_SAFE_INTEGER,
  );
  const slots = int('world.shapeSlots', field(counters, 'world', 'shapeSlots'), 0, MAX_ID);
  const free = arr('world.freeShapeIds', field(counters, 'world', 'freeShapeIds')).map((v, i) =>
    int(`world.freeShapeIds[${i}]`, v, 0, slots - 1),
  );

  // Bodies and shapes.
  const bodyEntries = arr('bodies', field(root, '', 'bodies'));
  const shapes: (Shape | null)[] = new Array<Shape | null>(slots).fill(null);
  const bodyIds = new Set<number>();
  const contactLists: number[][] = [];
  bodyEntries.forEach((entry, i) => {
    const path = `bodies[${i}]`;
    const { body, contacts } = readBody(path, obj(path, entry));
    if (body.id >= w.nextBodyId || bodyIds.has(body.id)) {
      fail(
        `${path}.id`,
        `must be unique and below world.nextBodyId (${w.nextBodyId}), got ${body.id}.`,
      );
    }
    bodyIds.add(body.id);
    body.shapeList.forEach((shape, j) => {
      if (shape.id >= slots || shapes[shape.id] !== null) {
        fail(
          `${path}.shapes[${j}].id`,
          `must be unique and below world.shapeSlots (${slots}), got ${shape.id}.`,
        );
      }
      shapes[shape.id] = shape;
    });
    body.worldRef = w.world;
    body.worldIndex = i;
    body.removalPending = false;
    body.solverIndex = 0;
    w.bodies.push(body);
    contactLists.push(contacts);
  });
  const freeSet = new Set(free);
  if (freeSet.size !== free.length) fail('world.freeShapeIds', 'lists an id twice.');
  for (let id = 0; id < slots; id++) {
    if ((shapes[id] === null) !== freeSet.has(id)) {
      fail('world.freeShapeIds', `must list exactly the unused shape ids; id ${id} is wrong.`);
    }
  }

  // Joints: checked now, built once everything is checked.
  const joints: JointPlan[] = arr('joints', field(root, '', 'joints')).map((entry, i) =>
    readJoint(`joints[${i}]`, entry, w.bodies),
  );
  // Bodies a joint keeps from colliding (collideConnected false) can have no contact.
  const jointBetween = new Map<string, number>();
  joints.forEach((joint, i) => {
    if (joint.collideConnected || joint.bodyA === joint.bodyB) return;
    const key = pairKey(joint.bodyA, joint.bodyB);
    if (!jointBetween.has(key)) jointBetween.set(key, i);
  });

  // Broad phase: trees, and every shape's leaf.
  const bp = obj('broadPhase', field(root, '', 'broadPhase'));
  const trees = arr('broadPhase.trees', field(bp, 'broadPhase', 'trees'), 3).map((t, i) =>
    readTree(`broadPhase.trees[${i}]`, t),
  ) as unknown as BroadPhaseState['trees'];
  const leaves = [0, 0, 0];
  for (const shape of shapes) {
    if (shape === null) continue;
    const tree = trees[shape.proxyKey & 3];
    const leaf = shape.proxyKey >> 2;
    leaves[shape.proxyKey & 3]!++;
    if (
      leaf >= tree.capacity ||
      tree.userData[leaf] !== shape.id ||
      tree.heights[leaf] !== 0 ||
      tree.child1[leaf] !== -1
    ) {
      fail('broadPhase.trees', `has no leaf for shape ${shape.id} at proxy key ${shape.proxyKey}.`);
    }
  }
  trees.forEach((tree, i) => {
    if (tree.leafCount !== leaves[i]) {
      fail(
        `broadPhase.trees[${i}].leafCount`,
        `is ${tree.leafCount}, but ${leaves[i]} shapes live in it.`,
      );
    }
  });
  const moved = arr('broadPhase.moved', field(bp, 'broadPhase', 'moved')).map((v, i) =>
    int(`broadPhase.moved[${i}]`, v, -1, 0x7fffffff),
  );
  const liveKeys = new Set(shapes.filter((s) => s !== null).map((s) => s!.proxyKey));
  const movedSet = new Set<number>();
  moved.forEach((key, i) => {
    if (key === -1) return;
    if (!liveKeys.has(key) || movedSet.has(key)) {
      fail(`broadPhase.moved[${i}]`, `must be the key of a live proxy, listed once; got ${key}.`);
    }
    movedSet.add(key);
  });

  // Contacts.
  const contactEntries = arr('contacts', field(root, '', 'contacts'));
  const contacts: Contact[] = [];
  const pairs = new Set<string>();
  contactEntries.forEach((entry, i) => {
    const path = `contacts[${i}]`;
    const o = obj(path, entry);
    const ids = arr(`${path}.shapes`, field(o, path, 'shapes'), 2).map((v, k) =>
      int(`${path}.shapes[${k}]`, v, 0, MAX_ID),
    );
    const a = shapes[ids[0]!] ?? null;
    const b = shapes[ids[1]!] ?? null;
    if (a === null || b === null)
      fail(`${path}.shapes`, `refers to a shape that does not exist (${ids.join(', ')}).`);
    if (
      a.body === b.body ||
      a.sensor ||
      b.sensor ||
      (a.body.type !== 'dynamic' && b.body.type !== 'dynamic')
    ) {
      fail(
        `${path}.shapes`,
        'must be two non-sensor shapes of different bodies, one of them dynamic.',
      );
    }
    const joint = jointBetween.get(pairKey(a.body.worldIndex, b.body.worldIndex));
    if (joint !== undefined) {
      fail(
        `${path}.shapes`,
        `joins bodies that joints[${joint}] keeps from colliding (its collideConnected is false).`,
      );
    }
    const key = pairKey(ids[0]!, ids[1]!);
    if (pairs.has(key)) fail(`${path}.shapes`, 'repeats a pair of shapes.');
    pairs.add(key);
    const contact = w.contactManager.restoreContact(a, b);
    contact.touching = bool(`${path}.touching`, field(o, path, 'touching'));
    const values = finites(
      `${path}.data`,
      field(o, path, 'data'),
      version === 1 ? CONTACT_STRIDE - 1 : CONTACT_STRIDE,
    );
    // Version 1 had no BOUNCING_STEPS slot: a contact read from it has not been bouncing.
    if (version === 1) values.splice(BOUNCING_STEPS, 0, 0);
    int(`${path}.data[${BOUNCING_STEPS}]`, values[BOUNCING_STEPS], 0, Number.MAX_SAFE_INTEGER);
    int(`${path}.data[${POINT_COUNT}]`, values[POINT_COUNT], 0, 2);
    int(`${path}.data[${HAS_CACHE}]`, values[HAS_CACHE], 0, 1);
    // The solver takes a contact with manifold points as touching (contact-solver.ts).
    if (contact.touching !== values[POINT_COUNT]! > 0) {
      fail(
        `${path}.touching`,
        `must be ${values[POINT_COUNT]! > 0}: data holds ${values[POINT_COUNT]} points.`,
      );
    }
    if (values[FRICTION]! < 0 || values[RESTITUTION]! < 0) {
      fail(`${path}.data`, 'has a negative friction or restitution.');
    }
    w.contactManager.slots.data.set(values, contact.index * CONTACT_STRIDE);
    contacts.push(contact);
  });

  // Each body's contact list, in its saved order: exactly the contacts that name the body.
  const seen = new Uint8Array(contacts.length);
  w.bodies.forEach((body, i) => {
    const list = contactLists[i]!;
    list.forEach((index, k) => {
      const contact = contacts[index];
      const side =
        contact === undefined ? 0 : contact.bodyA === body ? 1 : contact.bodyB === body ? 2 : 0;
      if (contact === undefined || side === 0 || (seen[index]! & side) !== 0) {
        fail(
          `bodies[${i}].contacts[${k}]`,
          `must be a contact of this body, listed once; got ${index}.`,
        );
      }
      seen[index]! |= side;
      if (side === 1) contact.indexInA = body.contacts.length;
      else contact.indexInB = body.contacts.length;
      body.contacts.push(contact);
    });
  });
  seen.forEach((flags, index) => {
    if (flags !== 3)
      fail(`contacts[${index}]`, 'is missing from the contact list of one of its bodies.');
  });

  // Sensors, in their saved order, with their overlaps.
  const sensorEntries = arr('sensors', field(root, '', 'sensors'));
  sensorEntries.forEach((entry, i) => {
    const path = `sensors[${i}]`;
    const o = obj(path, entry);
    const id = int(`${path}.shape`, field(o, path, 'shape'), 0, MAX_ID);
    const shape = shapes[id] ?? null;
    if (shape === null || !shape.sensor || shape.sensorIndex >= 0) {
      fail(`${path}.shape`, `must name a sensor shape, once; got ${id}.`);
    }
    w.sensors.add(shape);
    const list = w.sensors.overlaps[shape.sensorIndex]!;
    arr(`${path}.visitors`, field(o, path, 'visitors')).forEach((v, k) => {
      const visitor = shapes[int(`${path}.visitors[${k}]`, v, 0, MAX_ID)] ?? null;
      if (visitor === null || visitor.sensor || list.includes(visitor)) {
        fail(`${path}.visitors[${k}]`, 'must name a non-sensor shape, once.');
      }
      list.push(visitor);
    });
  });
  for (const shape of shapes) {
    if (shape !== null && shape.sensor && shape.sensorIndex < 0) {
      fail('sensors', `is missing sensor shape ${shape.id}.`);
    }
  }

  // Everything checked: install the shape table and the broad phase.
  for (let id = 0; id < slots; id++) {
    const shape = shapes[id] ?? null;
    w.shapesById.push(shape);
    shape?.attachTable(w.shapeTable);
  }
  w.freeShapeIds.push(...free);
  importBroadPhaseState(w.broadPhase, { trees, moved });
  // Joints, in their saved order; each body's list holds its joints in that same order.
  joints.forEach((plan, i) => {
    const joint = buildJoint(plan, w.bodies);
    joint.worldRef = w.world;
    joint.worldIndex = i;
    joint.removalPending = false;
    w.joints.push(joint);
    joint.bodyA.jointList.push(joint);
    if (joint.bodyB !== joint.bodyA) joint.bodyB.jointList.push(joint);
  });
}

function pairKey(a: number, b: number): string {
  return a < b ? `${a},${b}` : `${b},${a}`;
}
