import { describe, expect, it } from 'vitest';
import {
  World,
  box,
  restoreSnapshot,
  revoluteJoint,
  takeSnapshot,
  wall,
  weldJoint,
  type Body,
  type WorldSnapshot,
} from '@physical/engine';
import { physicalErrorOf } from './expect-physical-error.ts';

// Issue #31, "Restoring snapshots": values a world never holds (a 1e300 centre, a 4.7e219 joint
// impulse from one flipped byte, two body entries swapped), undefined and holes that a structured
// clone carries, are refused with a PhysicalError naming the field; and every state the API can
// make (a weld between two static bodies, a body whose type the app wrote) restores.

type Entry = Record<string, unknown>;
type Snap = { bodies: Entry[]; joints: Entry[]; broadPhase: Entry; contacts: Entry[] };

/** A hinged arm on a post, resting on the ground, after 60 steps: contacts, joints, impulses. */
function saved(): Snap {
  const world = new World();
  world.add(wall({ from: { x: -10, y: 0 }, to: { x: 10, y: 0 } }));
  const post = world.add(
    box({ type: 'static', position: { x: 0, y: -2 }, width: 0.2, height: 0.2 }),
  );
  const arm = world.add(box({ position: { x: 1, y: -2 }, width: 2, height: 0.2 }));
  world.addJoint(revoluteJoint({ bodyA: post, bodyB: arm, anchor: { x: 0, y: -2 } }));
  world.add(box({ position: { x: -3, y: -0.5 }, width: 1, height: 1 }));
  for (let i = 0; i < 60; i++) world.step();
  return JSON.parse(JSON.stringify(takeSnapshot(world))) as Snap;
}

const good = saved();
const fresh = (): Snap => structuredClone(good);

function fieldOf(snap: unknown): string {
  return physicalErrorOf(() => restoreSnapshot(snap as WorldSnapshot)).field;
}

describe('restore validates like the factories', () => {
  it('refuses a centre of 1e300 and a joint impulse of 4.7e219, naming them', () => {
    const centre = fresh();
    (centre.bodies[2]!['center'] as number[])[0] = 1e300;
    expect(fieldOf(centre)).toBe('snapshot.bodies[2].center[0]');
    const impulse = fresh();
    (impulse.joints[0]!['linearImpulse'] as number[])[1] = 4.7e219;
    expect(fieldOf(impulse)).toBe('snapshot.joints[0].linearImpulse[1]');
    const spin = fresh();
    (spin.bodies[2]!['velocity'] as number[])[2] = 1e200;
    expect(fieldOf(spin)).toBe('snapshot.bodies[2].velocity[2]');
    const angle = fresh();
    angle.bodies[2]!['angle'] = -1e300;
    expect(fieldOf(angle)).toBe('snapshot.bodies[2].angle');
    const contact = fresh();
    (contact.contacts[0]!['data'] as number[])[30] = 1e250;
    expect(fieldOf(contact)).toBe('snapshot.contacts[0].data[30]');
  });

  it('refuses two body entries swapped (ids must ascend, as in every world)', () => {
    const snap = fresh();
    [snap.bodies[2], snap.bodies[3]] = [snap.bodies[3]!, snap.bodies[2]!];
    expect(fieldOf(snap)).toBe('snapshot.bodies[3].id');
  });

  it('refuses undefined and holes, which a structured clone keeps (no TypeError)', () => {
    const undef = fresh();
    (undef.bodies[2]!['transform'] as unknown[])[1] = undefined;
    expect(fieldOf(structuredClone(undef))).toBe('snapshot.bodies[2].transform[1]');
    const hole = fresh();
    delete (hole.bodies[2]!['velocity'] as unknown[])[0];
    expect(fieldOf(structuredClone(hole))).toBe('snapshot.bodies[2].velocity[0]');
    const trees = fresh();
    delete (trees.broadPhase['trees'] as unknown[])[1];
    expect(fieldOf(structuredClone(trees))).toBe('snapshot.broadPhase.trees[1]');
    const bodies = fresh();
    delete (bodies.bodies as unknown[])[1];
    expect(fieldOf(structuredClone(bodies))).toBe('snapshot.bodies[1]');
  });

  it("restores the world's own snapshot of a weld between two static bodies", () => {
    const world = new World();
    const a = world.add(box({ type: 'static', position: { x: 0, y: 0 }, width: 1, height: 1 }));
    const b = world.add(box({ type: 'static', position: { x: 1, y: 0 }, width: 1, height: 1 }));
    world.addJoint(weldJoint({ bodyA: a, bodyB: b, anchor: { x: 0.5, y: 0 } }));
    world.step();
    const copy = restoreSnapshot(structuredClone(takeSnapshot(world)));
    expect(copy.joints.map((j) => j.type)).toEqual(['weld']);
    copy.step();
    expect(JSON.stringify(takeSnapshot(copy))).toBe(
      JSON.stringify((world.step(), takeSnapshot(world))),
    );
  });

  it("restores the world's own snapshot after the app wrote body.type (if it can)", () => {
    const world = new World();
    world.add(wall({ from: { x: -5, y: 0 }, to: { x: 5, y: 0 } }));
    const body = world.add(box({ position: { x: 0, y: -0.49 }, width: 1, height: 1 }));
    body.applyForce({ x: 1, y: 0 }, { duration: 'constant' });
    world.step();
    try {
      // Read-only in the typings; plain JavaScript may still write it (issue #31).
      (body as { type: Body['type'] }).type = 'static';
    } catch {
      return; // the write is refused: the state cannot be made, nothing to restore
    }
    world.step();
    const copy = restoreSnapshot(structuredClone(takeSnapshot(world)));
    for (let i = 0; i < 30; i++) {
      world.step();
      copy.step();
    }
    expect(JSON.stringify(takeSnapshot(copy))).toBe(JSON.stringify(takeSnapshot(world)));
  });
});
