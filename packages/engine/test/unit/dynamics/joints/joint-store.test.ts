import { describe, expect, it } from 'vitest';
import {
  World,
  box,
  particle,
  restoreSnapshot,
  revoluteJoint,
  takeSnapshot,
  type Body,
  type RevoluteJoint,
} from '@physical/engine';
import { exportJointState } from '../../../../src/dynamics/joints/joint-state.ts';
import type { JointStore } from '../../../../src/dynamics/joints/joint-store.ts';
import type { SolverMemory } from '../../../../src/dynamics/solver-memory.ts';

/** The world's solver memory (internal). */
function memoryOf(world: World): SolverMemory {
  return (world as unknown as { solver: { memory: SolverMemory } }).solver.memory;
}

// A joint's numbers live in one record: its kind's store in its world (the handle and the solver
// passes read and write the same numbers, nothing is copied back after a step), or a store of its
// own outside a world. Leaving a world moves the record out and the kind's last record into its
// place; neither joint may lose or swap a number.

const DT = 1 / 60;

/** The store behind a joint (internal). */
function storeOf(joint: RevoluteJoint): JointStore {
  return (joint as unknown as { store: JointStore }).store;
}

function pendulums(world: World, count: number): { ground: Body; hinges: RevoluteJoint[] } {
  const ground = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
  const hinges: RevoluteJoint[] = [];
  for (let i = 0; i < count; i++) {
    const bob = world.add(particle({ position: { x: 1 + i, y: 0.5 * i }, radius: 0.1 }));
    hinges.push(
      world.addJoint(
        revoluteJoint({
          bodyA: ground,
          bodyB: bob,
          anchor: { x: 0, y: 0.5 * i },
          enableMotor: true,
          motorSpeed: i + 1,
          maxMotorTorque: 10 * (i + 1),
        }),
      ),
    );
  }
  return { ground, hinges };
}

describe('joint store', () => {
  it("keeps a solved joint's numbers in its kind's store, where the handle reads them", () => {
    const world = new World({ enableSleep: false });
    const { hinges } = pendulums(world, 3);
    const before = storeOf(hinges[0]!);
    expect(before.local).toBe(true);
    world.step(DT);
    // All three joined one store, the world's revolute store.
    const store = storeOf(hinges[0]!);
    expect(store.local).toBe(false);
    expect(storeOf(hinges[1]!)).toBe(store);
    expect(storeOf(hinges[2]!)).toBe(store);
    // A setter writes the record the passes read: the motor's torque follows a new limit in the
    // very next step, and the handle reads what the step left (the torque is at its bound).
    hinges[1]!.maxMotorTorque = 3;
    world.step(DT);
    expect(Math.abs(hinges[1]!.motorTorque)).toBeLessThanOrEqual(3 + 1e-9);
    expect(Math.abs(hinges[1]!.motorTorque)).toBeGreaterThan(0);
  });

  it("keeps the world's records in its solver memory, across the memory's moves", () => {
    const world = new World({ enableSleep: false });
    const { hinges } = pendulums(world, 3);
    world.step(DT);
    const memory = memoryOf(world);
    expect(storeOf(hinges[0]!)).toBe(memory.jointStore);
    const saved = hinges.map((hinge) => JSON.stringify(exportJointState(hinge)));
    // Forty more hinges outgrow the first room for records: the memory moves, the handles'
    // numbers with it.
    const firstView = memory.jointStore.data;
    const more = pendulums(world, 40).hinges;
    memory.reserveJoints(world.joints.length, world.joints.length);
    expect(memory.jointStore.data).not.toBe(firstView);
    expect(hinges.map((hinge) => JSON.stringify(exportJointState(hinge)))).toEqual(saved);
    world.step(DT);
    expect(storeOf(more[39]!)).toBe(memory.jointStore);
    expect(memory.jointStore.count).toBe(43);
    // Each step lists its active joints, kind by kind, with their bodies' state offsets.
    // (A world adopts its joints in its order: the last one's record is the 43rd.)
    expect(memory.jointActive[3 * 42]).toBe(42 * memory.jointStore.stride);
    expect(hinges[1]!.motorSpeed).toBe(2);
  });

  it('moves a leaving joint out with all its numbers, and the last joint into its place', () => {
    const world = new World({ enableSleep: false });
    const { hinges } = pendulums(world, 3);
    for (let i = 0; i < 20; i++) world.step(DT);
    const saved = hinges.map((hinge) => JSON.stringify(exportJointState(hinge)));
    world.removeJoint(hinges[0]!);
    // The removed joint has a store of its own, with the same settings, impulses and reaction.
    expect(storeOf(hinges[0]!).local).toBe(true);
    expect(JSON.stringify(exportJointState(hinges[0]!))).toBe(saved[0]);
    // The others read their own numbers still (the last one moved into the first slot).
    expect(JSON.stringify(exportJointState(hinges[1]!))).toBe(saved[1]);
    expect(JSON.stringify(exportJointState(hinges[2]!))).toBe(saved[2]);
    expect(hinges[2]!.motorSpeed).toBe(3);
    // A setting written outside the world stays with the joint when it joins another world.
    hinges[0]!.motorSpeed = -4;
    const other = new World({ enableSleep: false });
    const ground = other.add(box({ type: 'static', width: 0.2, height: 0.2 }));
    const bob = other.add(particle({ position: { x: 1, y: 0 }, radius: 0.1 }));
    const moved = other.addJoint(
      revoluteJoint({ bodyA: ground, bodyB: bob, anchor: { x: 0, y: 0 } }),
    );
    other.step(DT);
    expect(moved.motorSpeed).toBe(0);
    // The first world goes on with two joints, each with its own motor.
    for (let i = 0; i < 20; i++) world.step(DT);
    expect(hinges[1]!.motorSpeed).toBe(2);
    expect(hinges[2]!.maxMotorTorque).toBe(30);
    expect(hinges[0]!.motorSpeed).toBe(-4);
  });

  it("solves in the world's joint order, whatever slots the store moved", () => {
    // A chain: each link hangs from the one before, so the order the joints are solved in shows.
    const world = new World({ enableSleep: false });
    const ground = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
    const links: Body[] = [];
    const hinges: RevoluteJoint[] = [];
    for (let i = 0; i < 5; i++) {
      links.push(world.add(particle({ position: { x: 0.5 * (i + 1), y: 0 }, radius: 0.1 })));
      const bodyA = i === 0 ? ground : links[i - 1]!;
      hinges.push(
        world.addJoint(revoluteJoint({ bodyA, bodyB: links[i]!, anchor: { x: 0.5 * i, y: 0 } })),
      );
    }
    for (let i = 0; i < 10; i++) world.step(DT);
    // Out goes the second hinge: the last record moves into its slot, so the store's order is
    // no longer the world's. A world restored from a snapshot now has its records in the
    // world's order; both must step alike, bit for bit.
    world.removeJoint(hinges[1]!);
    const restored = restoreSnapshot(takeSnapshot(world));
    for (let i = 0; i < 30; i++) {
      world.step(DT);
      restored.step(DT);
    }
    const state = (w: World): number[] =>
      w.bodies.flatMap((b) => [b.position.x, b.position.y, b.angle, b.linearVelocity.x]);
    expect(state(restored)).toEqual(state(world));
    expect(restored.joints.map((j) => j.reactionForce.y)).toEqual(
      world.joints.map((j) => j.reactionForce.y),
    );
  });
});
