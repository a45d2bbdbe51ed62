import { exportBroadPhaseState } from '../collision/broad-phase-state.ts';
import type { TreeState } from '../collision/dynamic-tree-state.ts';
import type { Body } from '../dynamics/body.ts';
import { CONTACT_STRIDE } from '../dynamics/contact-data.ts';
import type { ContactManager } from '../dynamics/contact-manager.ts';
import type { Shape } from '../dynamics/shape.ts';
import { AABB } from '../geometry/aabb.ts';
import { saveJoint } from './joint-snapshot.ts';
import {
  SNAPSHOT_FORMAT,
  SNAPSHOT_VERSION,
  type WorldInternals,
  type WorldSnapshot,
} from './snapshot-format.ts';
import { enc, encAll, type SnapshotValue } from './snapshot-values.ts';

// Saving a world: every section as plain JSON-compatible data (see snapshot.ts for what is saved
// and why), numbers encoded as snapshot-values.ts describes.

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
  const box = new AABB();
  return {
    id: shape.id,
    proxyKey: shape.proxyKey,
    geometry: saveGeometry(shape),
    density: enc(shape.density),
    friction: enc(shape.friction),
    restitution: enc(shape.restitution),
    sensor: shape.sensor,
    filter: [shape.categoryBits, shape.maskBits, shape.groupIndex],
    aabb: encodeBox(shape.readTightBox(box)),
    fatAABB: encodeBox(shape.readFatBox(box)),
  };
}

function saveBody(body: Body, contacts: ContactManager): Record<string, SnapshotValue> {
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
    contacts: contactList(body, contacts),
  };
}

/** The slots of a body's contacts, in the order of its contact list (contact-edges.ts). */
function contactList(body: Body, contacts: ContactManager): number[] {
  const edges = contacts.edges;
  const list: number[] = [];
  for (let key = edges.first(body.worldIndex); key >= 0; key = edges.next[key]!) {
    list.push(key >> 1);
  }
  return list;
}

function saveContact(slot: number, contacts: ContactManager): Record<string, SnapshotValue> {
  // The contact's numbers (manifold, warm-start impulses, reuse cache) are one slot of the
  // contact data: saved whole, in the slot's own layout (see dynamics/contact-data.ts).
  const base = slot * CONTACT_STRIDE;
  const shapes = contacts.slots.shapes;
  return {
    shapes: [shapes[2 * slot]!, shapes[2 * slot + 1]!],
    touching: contacts.touching(slot),
    data: encAll(contacts.slots.data.subarray(base, base + CONTACT_STRIDE)),
  };
}

function saveTree(tree: TreeState): SnapshotValue {
  return { ...tree, boxes: encAll(tree.boxes) };
}

/** @internal Writes a world's state as a snapshot. */
export function saveWorld(w: WorldInternals): WorldSnapshot {
  const s = w.settings;
  const manager = w.contactManager;
  const contactSlots = Array.from({ length: manager.count }, (_, slot) => slot);
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
    bodies: w.bodies.map((b) => saveBody(b, manager)),
    contacts: contactSlots.map((slot) => saveContact(slot, manager)),
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

function encodeBox(box: AABB): SnapshotValue {
  return encAll([box.minX, box.minY, box.maxX, box.maxY]);
}
