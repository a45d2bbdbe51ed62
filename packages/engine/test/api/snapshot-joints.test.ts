import { describe, expect, it } from 'vitest';
import {
  DistanceJoint,
  PhysicalError,
  RevoluteJoint,
  World,
  box,
  capsule,
  distanceJoint,
  mouseJoint,
  particle,
  polygon,
  prismaticJoint,
  restoreSnapshot,
  revoluteJoint,
  takeSnapshot,
  wall,
  weldJoint,
  type MouseJoint,
  type WorldSnapshot,
} from '@physical/engine';

// Snapshots of worlds with joints: every joint kind comes back with its frames, settings and
// warm-start impulses, so the copy steps bit-for-bit like the original; a bad joint entry names
// its field.

const DT = 1 / 60;

/** Index of the mouse joint in scene().joints, and where its target goes at step i. */
function dragTarget(i: number): { x: number; y: number } {
  return { x: 6 + 2 * Math.sin(i / 40), y: -5 + Math.cos(i / 55) };
}

/**
 * Every joint kind at work: a pendulum chain of capsules on revolutes (motor and limits), a
 * slider with a motor, a damped spring, a soft weld, a dragged box, beside a pyramid, capsules
 * and a concave L.
 */
function scene(): World {
  const world = new World();
  world.add(wall({ from: { x: -30, y: 0 }, to: { x: 30, y: 0 } }));
  for (let row = 0; row < 6; row++) {
    for (let i = 0; i < 6 - row; i++) {
      world.add(
        box({ position: { x: -12 + i * 1.02 + row * 0.51, y: -0.5 - row }, width: 1, height: 1 }),
      );
    }
  }
  for (let i = 0; i < 4; i++) {
    world.add(
      capsule({ position: { x: -10 + i * 0.7, y: -9 - i }, length: 0.8, radius: 0.2, angle: i }),
    );
  }
  world.add(
    polygon({
      position: { x: -4, y: -3 },
      vertices: [
        { x: 0, y: 0 },
        { x: 2, y: 0 },
        { x: 2, y: -0.5 },
        { x: 0.5, y: -0.5 },
        { x: 0.5, y: -2 },
        { x: 0, y: -2 },
      ],
    }),
  );

  // Pendulum chain: the first hinge driven by a motor (free to turn: against a limit the limit
  // would absorb the motor's warm start), the others limited, one with a torsion spring.
  const pivot = world.add(
    box({ type: 'static', position: { x: 0, y: -12 }, width: 0.2, height: 0.2 }),
  );
  let previous = pivot;
  for (let i = 0; i < 5; i++) {
    const link = world.add(
      capsule({ position: { x: 0.5 + i, y: -12 }, length: 0.8, radius: 0.1, angle: 0 }),
    );
    world.addJoint(
      revoluteJoint({
        bodyA: previous,
        bodyB: link,
        anchor: { x: i, y: -12 },
        enableLimit: i > 0,
        lowerAngle: -0.6 - 0.1 * i,
        upperAngle: 0.5 + 0.1 * i,
        enableMotor: i === 0,
        motorSpeed: 1.5,
        maxMotorTorque: 400,
        enableSpring: i === 3,
        hertz: 2,
        dampingRatio: 0.3,
      }),
    );
    previous = link;
  }

  // A slider driven against its upper limit.
  const rail = world.add(
    box({ type: 'static', position: { x: 10, y: -8 }, width: 0.2, height: 0.2 }),
  );
  const carriage = world.add(box({ position: { x: 10, y: -8 }, width: 0.6, height: 0.3 }));
  world.addJoint(
    prismaticJoint({
      bodyA: rail,
      bodyB: carriage,
      anchor: { x: 10, y: -8 },
      axis: { x: 1, y: -0.2 },
      enableLimit: true,
      lower: -1,
      upper: 2,
      enableMotor: true,
      motorSpeed: 1,
      maxMotorForce: 30,
    }),
  );

  // A damped spring with a length range, and a rope between two balls (they may collide).
  const hook = world.add(particle({ type: 'static', position: { x: 14, y: -10 }, radius: 0.1 }));
  const weight = world.add(box({ position: { x: 14.5, y: -8 }, width: 0.5, height: 0.5 }));
  world.addJoint(
    distanceJoint({
      bodyA: hook,
      bodyB: weight,
      anchorA: { x: 14, y: -10 },
      anchorB: { x: 14.5, y: -8.25 },
      length: 1.5,
      minLength: 1,
      maxLength: 2.5,
      enableSpring: true,
      hertz: 1.5,
      dampingRatio: 0.2,
    }),
  );
  const ballA = world.add(particle({ position: { x: 17, y: -6 }, radius: 0.3 }));
  const ballB = world.add(particle({ position: { x: 18, y: -6 }, radius: 0.3 }));
  world.addJoint(
    distanceJoint({
      bodyA: ballA,
      bodyB: ballB,
      anchorA: { x: 17, y: -6 },
      anchorB: { x: 18, y: -6 },
      enableSpring: true,
      hertz: 0,
      maxLength: 1.2,
      collideConnected: true,
    }),
  );

  // A soft weld: a springy board on a post.
  const post = world.add(
    box({ type: 'static', position: { x: 3, y: -4 }, width: 0.3, height: 0.3 }),
  );
  const board = world.add(box({ position: { x: 4.2, y: -4 }, width: 2, height: 0.15 }));
  world.addJoint(
    weldJoint({
      bodyA: post,
      bodyB: board,
      anchor: { x: 3.2, y: -4 },
      linearHertz: 8,
      angularHertz: 3,
      dampingRatio: 0.4,
    }),
  );

  // A box dragged by the mouse.
  const dragged = world.add(box({ position: { x: 6, y: -2 }, width: 0.8, height: 0.5 }));
  world.addJoint(
    mouseJoint({ body: dragged, target: { x: 6.2, y: -2.1 }, maxForce: 300, hertz: 4 }),
  );
  return world;
}

function mouseOf(world: World): MouseJoint {
  return world.joints.find((j) => j.type === 'mouse') as MouseJoint;
}

/** Bodies' poses, velocities and sleep, and every joint's reaction, as numbers. */
function state(world: World): number[] {
  const out: number[] = [];
  for (const b of world.bodies) {
    out.push(b.position.x, b.position.y, b.angle);
    out.push(b.linearVelocity.x, b.linearVelocity.y, b.angularVelocity, b.isAwake ? 1 : 0);
  }
  for (const j of world.joints) out.push(j.reactionForce.x, j.reactionForce.y, j.reactionTorque);
  return out;
}

function firstDifference(a: number[], b: number[]): number {
  if (a.length !== b.length) return -2;
  return a.findIndex((x, i) => !Object.is(x, b[i]));
}

function copyOf(world: World): World {
  return restoreSnapshot(JSON.parse(JSON.stringify(takeSnapshot(world))) as WorldSnapshot);
}

describe('snapshots with joints', () => {
  it('restores every joint kind: 1,000 steps later bodies and reactions agree bit for bit', () => {
    const original = scene();
    for (let i = 0; i < 90; i++) {
      mouseOf(original).target = dragTarget(i);
      original.step(DT);
    }
    const copy = copyOf(original);
    expect(copy.joints.map((j) => j.type)).toEqual(original.joints.map((j) => j.type));
    copy.joints.forEach((joint, k) => {
      const saved = original.joints[k]!;
      expect(joint.world).toBe(copy);
      expect(copy.bodies.indexOf(joint.bodyA)).toBe(original.bodies.indexOf(saved.bodyA));
      expect(copy.bodies.indexOf(joint.bodyB)).toBe(original.bodies.indexOf(saved.bodyB));
      expect(joint.collideConnected).toBe(saved.collideConnected);
    });
    copy.bodies.forEach((body, i) => {
      const joints = original.bodies[i]!.joints.map((j) => original.joints.indexOf(j));
      expect(body.joints.map((j) => copy.joints.indexOf(j))).toEqual(joints);
    });
    // The motor pushes at its limit and the joints carry impulses: there is state to lose.
    expect(original.joints.some((j) => j.reactionTorque !== 0)).toBe(true);
    expect(firstDifference(state(copy), state(original))).toBe(-1);

    // Compared after every step: a lost warm start can heal within a few steps (soft rows
    // converge to the same impulses), so a check every so often could miss it.
    let firstBadStep = -1;
    for (let i = 90; i < 1090; i++) {
      mouseOf(original).target = dragTarget(i);
      mouseOf(copy).target = dragTarget(i);
      original.step(DT);
      copy.step(DT);
      if (firstBadStep < 0 && firstDifference(state(copy), state(original)) >= 0) firstBadStep = i;
    }
    expect(firstBadStep).toBe(-1);
    expect(JSON.stringify(takeSnapshot(copy))).toBe(JSON.stringify(takeSnapshot(original)));
  }, 30_000);

  it('keeps a joint the app changed, a motor torque read before any step, a sleeping rope', () => {
    const world = new World({ subSteps: 6 }); // not the default 4: the sub-step is saved too
    const ground = world.add(
      box({ type: 'static', position: { x: 0, y: 0 }, width: 0.2, height: 0.2 }),
    );
    const arm = world.add(box({ position: { x: 1, y: 0 }, width: 2, height: 0.2 }));
    const hinge = world.addJoint(
      revoluteJoint({ bodyA: ground, bodyB: arm, anchor: { x: 0, y: 0 }, enableLimit: true }),
    );
    for (let i = 0; i < 20; i++) world.step(DT);
    hinge.enableLimit = false;
    hinge.setLimits(-1, 1);
    hinge.enableMotor = true;
    hinge.motorSpeed = -2;
    hinge.maxMotorTorque = 50;
    const sleeper = world.add(
      box({ position: { x: -3, y: 0 }, width: 0.3, height: 0.3, asleep: true }),
    );
    const rope = world.addJoint(
      distanceJoint({
        bodyA: ground,
        bodyB: sleeper,
        anchorA: { x: 0, y: 0 },
        anchorB: { x: -3, y: 0 },
        enableSpring: true,
        maxLength: 3,
      }),
    );
    sleeper.sleep();
    for (let i = 0; i < 10; i++) world.step(DT);
    expect(sleeper.isAwake).toBe(false);
    expect(hinge.motorTorque).not.toBe(0);

    const copy = copyOf(world);
    const copiedHinge = copy.joints[0];
    const copiedRope = copy.joints[1];
    if (!(copiedHinge instanceof RevoluteJoint) || !(copiedRope instanceof DistanceJoint)) {
      throw new Error(`restored joints ${copiedHinge?.type}, ${copiedRope?.type}`);
    }
    expect([copiedHinge.enableLimit, copiedHinge.lowerAngle, copiedHinge.upperAngle]).toEqual([
      false,
      -1,
      1,
    ]);
    expect([copiedHinge.motorSpeed, copiedHinge.maxMotorTorque]).toEqual([-2, 50]);
    expect(copiedHinge.motorTorque).toBe(hinge.motorTorque);
    expect(copiedRope.maxLength).toBe(rope.maxLength);
    expect(copiedRope.bodyB.isAwake).toBe(false);
    let firstBadStep = -1;
    for (let i = 0; i < 120; i++) {
      world.step(DT);
      copy.step(DT);
      if (firstBadStep < 0 && firstDifference(state(copy), state(world)) >= 0) firstBadStep = i;
    }
    expect(firstBadStep).toBe(-1);
    expect(copiedHinge.motorTorque).toBe(hinge.motorTorque);
  });

  it('a restored joint still works as a joint: removing a body removes it', () => {
    const copy = copyOf(scene());
    const link = copy.joints[1]!.bodyA;
    const before = copy.joints.length;
    copy.remove(link);
    expect(copy.joints.length).toBe(before - 2);
    expect(copy.joints.every((j) => j.bodyA !== link && j.bodyB !== link)).toBe(true);
  });
});

describe('bad joint snapshots', () => {
  type Entry = Record<string, unknown>;
  type Snap = Record<string, unknown> & { joints: Entry[]; bodies: Entry[]; contacts: Entry[] };
  function good(): Snap {
    const world = scene();
    for (let i = 0; i < 30; i++) world.step(DT);
    return JSON.parse(JSON.stringify(takeSnapshot(world))) as Snap;
  }
  const saved = good();
  function fresh(): Snap {
    return structuredClone(saved);
  }
  function load(snap: unknown): () => World {
    return () => restoreSnapshot(snap as WorldSnapshot);
  }
  const index = (type: string): number => saved.joints.findIndex((j) => j['type'] === type);

  it('names a wrong joint type', () => {
    const snap = fresh();
    snap.joints[2]!['type'] = 'rope';
    expect(load(snap)).toThrow(/snapshot\.joints\[2\]\.type: must be one of .*got 'rope'/);
    const notObject = fresh();
    notObject.joints[1] = 7 as unknown as Entry;
    expect(load(notObject)).toThrow(/snapshot\.joints\[1\]: must be an object/);
  });

  it('names a bad body index', () => {
    const out = fresh();
    out.joints[3]!['bodyA'] = 9999;
    expect(load(out)).toThrow(/snapshot\.joints\[3\]\.bodyA: must be a whole number from 0 to/);
    const same = fresh();
    same.joints[0]!['bodyB'] = same.joints[0]!['bodyA'];
    expect(load(same)).toThrow(/snapshot\.joints\[0\]\.bodyB: must be a different body/);
    const mouse = fresh();
    mouse.joints[index('mouse')]!['body'] = 0;
    expect(load(mouse)).toThrow(
      new RegExp(`snapshot\\.joints\\[${index('mouse')}\\]\\.body: must be a dynamic body`),
    );
  });

  it('names a NaN, a number JSON turned into null, and a value out of range', () => {
    const nan = fresh();
    nan.joints[0]!['lowerAngle'] = Number.NaN;
    expect(load(nan)).toThrow(/snapshot\.joints\[0\]\.lowerAngle: must be a number, got NaN/);
    const nulled = fresh();
    (nulled.joints[1]!['linearImpulse'] as unknown[])[1] = null;
    expect(load(nulled)).toThrow(
      /snapshot\.joints\[1\]\.linearImpulse\[1\]: must be a number, got null/,
    );
    const order = fresh();
    order.joints[0]!['lowerAngle'] = 1;
    order.joints[0]!['upperAngle'] = 0.5;
    expect(load(order)).toThrow(/snapshot\.joints\[0\]\.lowerAngle: must not exceed upperAngle/);
    const spring = fresh();
    spring.joints[index('distance')]!['length'] = 3;
    expect(load(spring)).toThrow(/\.length: must not exceed maxLength \(2\.5\), got 3/);
    const axis = fresh();
    axis.joints[index('prismatic')]!['localAxis'] = [2, 0];
    expect(load(axis)).toThrow(/\.localAxis: must be a unit vector/);
    const impulse = fresh();
    impulse.joints[0]!['lowerImpulse'] = -1;
    expect(load(impulse)).toThrow(/snapshot\.joints\[0\]\.lowerImpulse: must be from 0 to/);
    const flag = fresh();
    flag.joints[0]!['enableMotor'] = 1;
    expect(load(flag)).toThrow(/snapshot\.joints\[0\]\.enableMotor: must be true or false/);
  });

  it('names every missing field of every joint kind', () => {
    let checked = 0;
    saved.joints.forEach((joint, k) => {
      for (const key of Object.keys(joint)) {
        const snap = fresh();
        snap.joints[k] = Object.fromEntries(Object.entries(joint).filter(([name]) => name !== key));
        expect(load(snap)).toThrow(`snapshot.joints[${k}].${key}: is missing.`);
        checked++;
      }
    });
    // Every kind saved more than its bodies: frames, settings, impulses, reaction.
    expect(checked).toBeGreaterThan(5 * 10);
    const noSection = fresh() as Record<string, unknown>;
    delete noSection['joints'];
    expect(load(noSection)).toThrow('snapshot.joints: is missing.');
  });

  it('rejects a contact between bodies a joint keeps apart', () => {
    const snap = fresh();
    const bodyOfShape = new Map<number, number>();
    snap.bodies.forEach((body, i) => {
      for (const shape of body['shapes'] as Entry[]) bodyOfShape.set(shape['id'] as number, i);
    });
    const [a, b] = (snap.contacts[0]!['shapes'] as number[]).map((id) => bodyOfShape.get(id)!);
    snap.joints.push({ ...structuredClone(snap.joints[index('weld')]!), bodyA: a, bodyB: b });
    expect(load(snap)).toThrow(/snapshot\.contacts\[0\]\.shapes: joins bodies that joints\[\d+\]/);
  });

  it('throws before building anything, and leaves the snapshot as it was', () => {
    const snap = fresh();
    const last = snap.joints.length - 1;
    snap.joints[last]!['hertz'] = 0; // a mouse joint's hertz must be above zero
    const text = JSON.stringify(snap);
    let error: unknown = null;
    let world: World | null = null;
    try {
      world = restoreSnapshot(snap as unknown as WorldSnapshot);
    } catch (e) {
      error = e;
    }
    expect(world).toBeNull();
    expect(error).toBeInstanceOf(PhysicalError);
    expect((error as PhysicalError).field).toBe(`snapshot.joints[${last}].hertz`);
    expect(JSON.stringify(snap)).toBe(text);
  });
});
