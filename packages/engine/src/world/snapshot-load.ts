import { importBroadPhaseState } from '../collision/broad-phase-state.ts';
import type { BroadPhaseState } from '../collision/broad-phase.ts';
import { checkTreeState, type TreeState } from '../collision/dynamic-tree-state.ts';
import {
  BOUNCING_STEPS,
  CONTACT_STRIDE,
  FRICTION,
  HAS_CACHE,
  NORMAL_X,
  NORMAL_Y,
  POINT_COUNT,
  RESTITUTION,
} from '../dynamics/contact-data.ts';
import type { Shape } from '../dynamics/shape.ts';
import { MAX_TIME_STEP, MIN_TIME_STEP } from '../core/validate.ts';
import { buildJoint, readJoint, type JointPlan } from './joint-snapshot.ts';
import { SNAPSHOT_FORMAT, SNAPSHOT_VERSION, type WorldInternals } from './snapshot-format.ts';
import { readBody, readSettings } from './snapshot-read-body.ts';
import {
  arr,
  bool,
  describe,
  fail,
  field,
  finites,
  int,
  MAX_ID,
  num,
  obj,
  positive,
  ranged,
  SAVED_COORDINATE,
  SAVED_IMPULSE,
} from './snapshot-values.ts';

// Loading a snapshot into a new, empty world: every section read and checked, then every
// cross-reference (ids, indices, lists, trees) checked, and only then the world's tables filled.

function readTree(path: string, v: unknown): TreeState {
  const o = obj(path, v);
  const ints = (key: string): number[] =>
    arr(`${path}.${key}`, field(o, path, key)).map((x) => (typeof x === 'number' ? x : NaN));
  const state: TreeState = {
    capacity: int(`${path}.capacity`, field(o, path, 'capacity'), 2, 1 << 26),
    root: int(`${path}.root`, field(o, path, 'root'), -1, 1 << 26),
    freeList: int(`${path}.freeList`, field(o, path, 'freeList'), -1, 1 << 26),
    leafCount: int(`${path}.leafCount`, field(o, path, 'leafCount'), 0, 1 << 26),
    // Free nodes may hold anything the tree left there, infinities included; a live box is
    // within the saved coordinate range.
    boxes: arr(`${path}.boxes`, field(o, path, 'boxes')).map((x, i) => {
      const value = num(`${path}.boxes[${i}]`, x);
      if (Number.isFinite(value) && Math.abs(value) > SAVED_COORDINATE) {
        fail(`${path}.boxes[${i}]`, `must be within ${SAVED_COORDINATE} m, got ${value}.`);
      }
      return value;
    }),
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
 * @internal Loads a snapshot into a newly made, empty world. Validates every section and every reference
 * before it returns; on error it throws a PhysicalError naming the field, and the caller drops
 * the half-built world.
 */
export function loadWorld(w: WorldInternals, snapshot: unknown): void {
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
  const contactLists: number[][] = [];
  bodyEntries.forEach((entry, i) => {
    const path = `bodies[${i}]`;
    const { body, contacts } = readBody(path, obj(path, entry));
    // Bodies join at the end of the list with the next id and leave by splice, so the ids of a
    // world's bodies ascend: entries out of order (two swapped) are not a world's.
    const previous = i > 0 ? w.bodies[i - 1]!.id : -1;
    if (body.id >= w.nextBodyId || body.id <= previous) {
      fail(
        `${path}.id`,
        `must be above the previous body's id (${previous}) and below world.nextBodyId (${w.nextBodyId}), got ${body.id}.`,
      );
    }
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
    w.placeBody(body, i);
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
  /** The slot of each saved contact (its index: contacts are restored in order). */
  const contacts: number[] = [];
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
    // Both bodies may be non-dynamic: a body the app made static by writing `body.type` keeps
    // its contacts until they end.
    if (a.body === b.body || a.sensor || b.sensor) {
      fail(`${path}.shapes`, 'must be two non-sensor shapes of different bodies.');
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
    const touching = bool(`${path}.touching`, field(o, path, 'touching'));
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
    if (touching !== values[POINT_COUNT]! > 0) {
      fail(
        `${path}.touching`,
        `must be ${values[POINT_COUNT]! > 0}: data holds ${values[POINT_COUNT]} points.`,
      );
    }
    if (values[FRICTION]! < 0 || values[RESTITUTION]! < 0) {
      fail(`${path}.data`, 'has a negative friction or restitution.');
    }
    values.forEach((x, k) => {
      if (Math.abs(x) > SAVED_IMPULSE) {
        fail(`${path}.data[${k}]`, `must be at most ${SAVED_IMPULSE} in size, got ${x}.`);
      }
    });
    // The narrow phase writes a unit normal with every manifold point.
    const nx = values[NORMAL_X]!;
    const ny = values[NORMAL_Y]!;
    const normal = Math.sqrt(nx * nx + ny * ny);
    if (values[POINT_COUNT]! > 0 && !(Math.abs(normal - 1) <= 1e-6)) {
      fail(`${path}.data[${NORMAL_X}]`, `must hold a unit normal, got one of length ${normal}.`);
    }
    w.contactManager.slots.data.set(values, contact * CONTACT_STRIDE);
    contacts.push(contact);
  });

  // Each body's contact list, in its saved order: exactly the contacts that name the body.
  const seen = new Uint8Array(contacts.length);
  const slotBodies = w.contactManager.slots.bodies;
  const edgeLists: number[][] = [];
  w.bodies.forEach((body, i) => {
    const list = contactLists[i]!;
    const keys: number[] = [];
    list.forEach((index, k) => {
      const contact = contacts[index];
      const side =
        contact === undefined
          ? 0
          : slotBodies[2 * contact] === body.worldIndex
            ? 1
            : slotBodies[2 * contact + 1] === body.worldIndex
              ? 2
              : 0;
      if (contact === undefined || side === 0 || (seen[index]! & side) !== 0) {
        fail(
          `bodies[${i}].contacts[${k}]`,
          `must be a contact of this body, listed once; got ${index}.`,
        );
      }
      seen[index]! |= side;
      keys.push(2 * contact + side - 1);
    });
    edgeLists.push(keys);
  });
  seen.forEach((flags, index) => {
    if (flags !== 3)
      fail(`contacts[${index}]`, 'is missing from the contact list of one of its bodies.');
  });
  // Linked at the lists' heads, last first, so each list reads in its saved order.
  for (const keys of edgeLists) {
    for (let k = keys.length - 1; k >= 0; k--) w.contactManager.edges.pushEdge(keys[k]!);
  }

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
  // Each body's shape chain, which the kernel's finalize walks (wasm/shape-bounds.ts).
  for (const body of w.bodies) w.linkShapes(body);
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
