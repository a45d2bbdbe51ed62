import { MAX_TIME_STEP } from '../core/validate.ts';
import type { Body } from '../dynamics/body.ts';
import { DistanceJoint, DISTANCE_STATE } from '../dynamics/joints/distance-joint.ts';
import {
  JOINT_MAX,
  type Joint,
  type JointState,
  type JointStateLayout,
  type JointType,
  type JointValueKind,
} from '../dynamics/joints/joint.ts';
import { exportJointState, importJointState, JOINT_STATE } from '../dynamics/joints/joint-state.ts';
import { MouseJoint, MOUSE_STATE } from '../dynamics/joints/mouse-joint.ts';
import { PrismaticJoint, PRISMATIC_STATE } from '../dynamics/joints/prismatic-joint.ts';
import { RevoluteJoint, REVOLUTE_STATE } from '../dynamics/joints/revolute-joint.ts';
import { WeldJoint, WELD_STATE } from '../dynamics/joints/weld-joint.ts';
import {
  bool,
  describe,
  enc,
  encAll,
  fail,
  field,
  finites,
  int,
  num,
  obj,
  positive,
  ranged,
  bounded,
  SAVED_COORDINATE,
  SAVED_IMPULSE,
  SAVED_REACTION,
  type SnapshotValue,
} from './snapshot-values.ts';
import { hypot } from '../math/hypot.ts';

// Joints in world snapshots: one entry per joint, in world.joints order. An entry names its
// bodies by index in the snapshot's bodies (a mouse joint has one, `body`), then lists its kind's
// layout (each joint file's *_STATE: frames, settings, warm-start impulses) and the last step's
// reaction. Each body's joint list is not saved: it is always the body's joints in world order
// (joints join at the end of both lists and leave both by splice), so the loader rebuilds it.

const LAYOUTS: Readonly<Record<JointType, JointStateLayout>> = {
  revolute: REVOLUTE_STATE,
  prismatic: PRISMATIC_STATE,
  distance: DISTANCE_STATE,
  weld: WELD_STATE,
  mouse: MOUSE_STATE,
};

const TYPES = Object.keys(LAYOUTS) as JointType[];

/** A unit axis saved by a snapshot is the rotation of a normalised one: 1 within rounding. */
const UNIT_TOLERANCE = 1e-9;

/** Every saved value of a joint kind, its own first, then those all joints save. */
function fieldsOf(type: JointType): [string, JointValueKind][] {
  return [...Object.entries(LAYOUTS[type].fields), ...Object.entries(JOINT_STATE.fields)];
}

/** @internal A joint as a snapshot saves it (its bodies by their index in world.bodies). */
export function saveJoint(joint: Joint): Record<string, SnapshotValue> {
  const out: Record<string, SnapshotValue> = { type: joint.type };
  if (joint.type === 'mouse') {
    out['body'] = joint.bodyB.worldIndex;
  } else {
    out['bodyA'] = joint.bodyA.worldIndex;
    out['bodyB'] = joint.bodyB.worldIndex;
    out['collideConnected'] = joint.collideConnected;
  }
  const state = exportJointState(joint);
  const fields = fieldsOf(joint.type);
  if (Object.keys(state).length !== fields.length) {
    // A joint kind saves a value its layout does not list: a bug here, not bad input.
    throw new Error(`The ${joint.type} joint's state and its snapshot layout disagree.`);
  }
  for (const [key] of fields) {
    const value = state[key]!;
    out[key] =
      typeof value === 'boolean' ? value : typeof value === 'number' ? enc(value) : encAll(value);
  }
  return out;
}

/** @internal A checked joint entry, ready to build once the whole snapshot is checked. */
export interface JointPlan {
  readonly type: JointType;
  readonly bodyA: number;
  readonly bodyB: number;
  readonly collideConnected: boolean;
  readonly state: JointState;
}

/**
 * The largest size a saved joint value may have: the setters' limit for a setting, the reach of
 * a saved world for an impulse or reaction, and the saved coordinate range for the rest (anchors,
 * lengths, angles, targets).
 */
function limitOf(key: string): number {
  const max = JOINT_MAX[key];
  if (max !== undefined) return max;
  if (key === 'subStepDuration') return MAX_TIME_STEP;
  if (key.startsWith('reaction')) return SAVED_REACTION;
  if (key === 'impulse' || key.endsWith('Impulse')) return SAVED_IMPULSE;
  return SAVED_COORDINATE;
}

function readValue(
  path: string,
  kind: JointValueKind,
  v: unknown,
  max: number,
): number | boolean | number[] {
  switch (kind) {
    case 'boolean':
      return bool(path, v);
    case 'finite':
      return ranged(path, v, -max, max);
    case 'nonNegative':
      return ranged(path, v, 0, max);
    case 'positive':
      return ranged(path, positive(path, v), 0, max);
    case 'nonNegativeOrInfinity': {
      const x = num(path, v);
      if (x === Infinity) return x;
      return ranged(path, x, 0, max);
    }
    case 'vector':
      return bounded(path, v, 2, max);
    case 'unitVector': {
      const xy = finites(path, v, 2);
      const length = hypot(xy[0]!, xy[1]!);
      if (!(Math.abs(length - 1) <= UNIT_TOLERANCE)) {
        fail(path, `must be a unit vector, got one of length ${length}.`);
      }
      return xy;
    }
  }
}

/**
 * @internal Checks one saved joint against the restored bodies, without building anything: its
 * type, body indices (two different bodies, one of them dynamic; a mouse joint's body dynamic),
 * every value of its layout, and its ordered pairs (limits, length range).
 */
export function readJoint(path: string, entry: unknown, bodies: readonly Body[]): JointPlan {
  const o = obj(path, entry);
  const typeValue = field(o, path, 'type');
  if (!TYPES.includes(typeValue as JointType)) {
    fail(
      `${path}.type`,
      `must be one of ${TYPES.map((t) => `'${t}'`).join(', ')}, got ${describe(typeValue)}.`,
    );
  }
  const type = typeValue as JointType;
  const last = bodies.length - 1;
  let bodyA: number;
  let bodyB: number;
  let collideConnected = false;
  // The bodies of a joint may be of any type, as the API allows (a weld between two static
  // bodies rests until one moves). A mouse joint is made on a dynamic body only.
  if (type === 'mouse') {
    bodyA = bodyB = int(`${path}.body`, field(o, path, 'body'), 0, last);
    if (bodies[bodyA]!.type !== 'dynamic') {
      fail(`${path}.body`, `must be a dynamic body, got the ${bodies[bodyA]!.type} body ${bodyA}.`);
    }
  } else {
    bodyA = int(`${path}.bodyA`, field(o, path, 'bodyA'), 0, last);
    bodyB = int(`${path}.bodyB`, field(o, path, 'bodyB'), 0, last);
    if (bodyA === bodyB) fail(`${path}.bodyB`, `must be a different body from bodyA (${bodyA}).`);
    collideConnected = bool(`${path}.collideConnected`, field(o, path, 'collideConnected'));
  }
  const state: JointState = {};
  for (const [key, kind] of fieldsOf(type)) {
    // A user setting (stiffness, damping, motor, limits) within the range its setter allows.
    state[key] = readValue(`${path}.${key}`, kind, field(o, path, key), limitOf(key));
  }
  for (const [lower, upper] of LAYOUTS[type].ordered) {
    if ((state[lower] as number) > (state[upper] as number)) {
      fail(
        `${path}.${lower}`,
        `must not exceed ${upper} (${String(state[upper])}), got ${String(state[lower])}.`,
      );
    }
  }
  return { type, bodyA, bodyB, collideConnected, state };
}

/** @internal Builds a checked joint on the restored bodies (not yet in the world's lists). */
export function buildJoint(plan: JointPlan, bodies: readonly Body[]): Joint {
  const bodyA = bodies[plan.bodyA]!;
  const bodyB = bodies[plan.bodyB]!;
  // The constructors need world points; any will do, importJointState then writes the saved frames.
  const origin = { x: 0, y: 0 };
  const common = { bodyA, bodyB, collideConnected: plan.collideConnected };
  let joint: Joint;
  switch (plan.type) {
    case 'revolute':
      joint = new RevoluteJoint({ ...common, anchor: origin });
      break;
    case 'prismatic':
      joint = new PrismaticJoint({ ...common, anchor: origin, axis: { x: 1, y: 0 } });
      break;
    case 'distance':
      joint = new DistanceJoint({ ...common, anchorA: origin, anchorB: origin });
      break;
    case 'weld':
      joint = new WeldJoint({ ...common, anchor: origin });
      break;
    case 'mouse':
      joint = new MouseJoint({ body: bodyB, target: origin });
      break;
  }
  importJointState(joint, plan.state);
  return joint;
}
