import { beforeEach, describe, expect, it } from 'vitest';
import { PUBLIC_MEMBERS } from './public-members.ts';
import {
  Body,
  Force,
  PhysicalError,
  Shape,
  World,
  bodyAtPoint,
  box,
  capsule,
  checkJointOptions,
  checkQueryBox,
  checkRay,
  checkTimeStep,
  checkWorldOptions,
  checkWorldSetting,
  distanceJoint,
  mouseJoint,
  particle,
  polygon,
  prismaticJoint,
  regularPolygon,
  restoreSnapshot,
  revoluteJoint,
  takeSnapshot,
  wall,
  weldJoint,
  type DistanceJoint,
  type Joint,
  type MouseJoint,
  type PrismaticJoint,
  type RevoluteJoint,
  type WeldJoint,
  type WorldSnapshot,
} from '@physical/engine';

// The audit of every public entry of @physical/engine (src/index.ts) against bad input, as a
// class: every constructor, factory, method, setter and option is driven with every bad value
// below, and each call must either throw a PhysicalError whose message starts with the field it
// names, or be accepted with documented, well-defined results. In both cases the world is still
// usable: nothing the fixture added is lost, every public number stays finite, and 60 steps run
// without an exception or a NaN. Tables, not instances: a new entry belongs in a table here.

/** Every kind of bad value a caller can hand over from plain JavaScript. */
const BAD_VALUES: readonly [string, unknown][] = [
  ['NaN', NaN],
  ['Infinity', Infinity],
  ['-Infinity', -Infinity],
  ['-0', -0],
  ['-1', -1],
  ['0', 0],
  ['1e300', 1e300],
  ['-1e300', -1e300],
  ["'a'", 'a'],
  ["'1'", '1'],
  ['null', null],
  ['undefined', undefined],
  ['{}', {}],
  ['[]', []],
  ['true', true],
  ['1n', 1n],
  ['a symbol', Symbol('bad')],
  ['a function', () => 1],
  ['{ x: NaN, y: 0 }', { x: NaN, y: 0 }],
  ['{ x: 1 }', { x: 1 }],
  ["{ x: '1', y: 0 }", { x: '1', y: 0 }],
  ['{ x: 1e300, y: 0 }', { x: 1e300, y: 0 }],
  ['[1, 2]', [1, 2]],
];

/** The world every case starts from: one of everything, each in a known state. */
interface Fixture {
  readonly world: World;
  readonly ground: Body;
  readonly crate: Body;
  readonly ball: Body;
  readonly bob: Body;
  readonly hinge: RevoluteJoint;
  readonly slider: PrismaticJoint;
  readonly rope: DistanceJoint;
  readonly weld: WeldJoint;
  readonly drag: MouseJoint;
  readonly push: Force;
  readonly twist: Force;
  /** A body of another world, a removed body and a body never added. */
  readonly foreign: () => Body;
  readonly removed: Body;
  readonly loose: Body;
}

function fixture(): Fixture {
  const world = new World({ gravity: { x: 0, y: 10 } });
  const ground = world.add(box({ type: 'static', position: { x: 0, y: 5 }, width: 20, height: 1 }));
  const crate = world.add(box({ position: { x: -2, y: 4 }, width: 1, height: 1 }));
  const ball = world.add(particle({ position: { x: 2, y: 4 }, radius: 0.5 }));
  const bob = world.add(particle({ position: { x: 0, y: 1 }, radius: 0.25 }));
  const post = world.add(box({ position: { x: 5, y: 2 }, width: 0.5, height: 0.5 }));
  const hinge = world.addJoint(
    revoluteJoint({ bodyA: ground, bodyB: bob, anchor: { x: 0, y: 0 } }),
  );
  const slider = world.addJoint(
    prismaticJoint({
      bodyA: ground,
      bodyB: post,
      anchor: { x: 5, y: 2 },
      axis: { x: 0, y: 1 },
      enableLimit: true,
      lower: -1,
      upper: 1,
    }),
  );
  const rope = world.addJoint(
    distanceJoint({ bodyA: crate, bodyB: ball, anchorA: { x: -2, y: 4 }, anchorB: { x: 2, y: 4 } }),
  );
  const weld = world.addJoint(weldJoint({ bodyA: post, bodyB: ground, anchor: { x: 5, y: 2 } }));
  const drag = world.addJoint(mouseJoint({ body: crate, target: { x: -2, y: 3 } }));
  const push = crate.applyForce({ x: 1, y: 0 });
  const twist = ball.applyTorque(0.5);
  let stranger: Body | null = null;
  const foreign = () => (stranger ??= new World().add(particle({ radius: 0.5 })));
  const removed = world.add(particle({ position: { x: 8, y: 0 }, radius: 0.5 }));
  world.remove(removed);
  const loose = particle({ radius: 0.5 });
  for (let i = 0; i < 5; i++) world.step();
  return {
    world,
    ground,
    crate,
    ball,
    bob,
    hinge,
    slider,
    rope,
    weld,
    drag,
    push,
    twist,
    foreign,
    removed,
    loose,
  };
}

/** What the fixture holds, to show that a refused or accepted bad call lost nothing. */
function inventory(world: World): string {
  return [
    world.bodies.length,
    world.joints.length,
    ...world.bodies.map((b) => `${b.shapes.length}/${b.forces.length}/${b.joints.length}`),
  ].join(' ');
}

function finiteVector(v: { x: number; y: number }): boolean {
  return Number.isFinite(v.x) && Number.isFinite(v.y);
}

/** Every public number of the world, its bodies, shapes, forces and joints that is not finite. */
function nonFinite(world: World): string[] {
  const bad: string[] = [];
  if (!finiteVector(world.gravity)) bad.push('world.gravity');
  if (!Number.isInteger(world.subSteps) || world.subSteps < 1) bad.push('world.subSteps');
  if (!Number.isFinite(world.restitutionThreshold)) bad.push('world.restitutionThreshold');
  world.bodies.forEach((body, i) => {
    const numbers: Record<string, number> = {
      angle: body.angle,
      angularVelocity: body.angularVelocity,
      mass: body.mass,
      inertia: body.inertia,
      gravityScale: body.gravityScale,
      linearDamping: body.linearDamping,
      angularDamping: body.angularDamping,
      drag: body.drag,
      kineticEnergy: body.kineticEnergy,
    };
    for (const [name, value] of Object.entries(numbers)) {
      if (typeof value !== 'number' || !Number.isFinite(value)) bad.push(`bodies[${i}].${name}`);
    }
    if (!finiteVector(body.position)) bad.push(`bodies[${i}].position`);
    if (!finiteVector(body.linearVelocity)) bad.push(`bodies[${i}].linearVelocity`);
    if (!finiteVector(body.centerOfMass)) bad.push(`bodies[${i}].centerOfMass`);
    body.shapes.forEach((shape, k) => {
      for (const value of [shape.friction, shape.restitution, shape.density]) {
        if (typeof value !== 'number' || !Number.isFinite(value)) {
          bad.push(`bodies[${i}].shapes[${k}]`);
        }
      }
    });
    body.forces.forEach((force, k) => {
      if (![force.x, force.y, force.torque].every(Number.isFinite)) {
        bad.push(`bodies[${i}].forces[${k}]`);
      }
    });
  });
  world.joints.forEach((joint, i) => {
    if (!finiteVector(joint.reactionForce) || !Number.isFinite(joint.reactionTorque)) {
      bad.push(`joints[${i}].reaction`);
    }
    if (!finiteVector(joint.anchorA) || !finiteVector(joint.anchorB)) {
      bad.push(`joints[${i}].anchors`);
    }
  });
  return bad;
}

/**
 * The fixture the next case runs on: a refused call changes nothing (checked below), so the
 * cases of one test share it until a call is accepted. Each test starts from a fresh one.
 */
let current: Fixture | null = null;
beforeEach(() => {
  current = null;
});

/**
 * Runs `call` on the fixture and checks the contract: a PhysicalError that names a field in
 * its message, or an accepted call after which `accepted` (if given) holds; then nothing is lost
 * and the world steps 60 times, finite. Returns what happened, for the table's own assertions.
 */
function audit(
  call: (f: Fixture) => unknown,
  accepted?: (f: Fixture, result: unknown) => void,
): 'refused' | 'accepted' {
  const f = (current ??= fixture());
  const before = inventory(f.world);
  let outcome: 'refused' | 'accepted' = 'accepted';
  let result: unknown = undefined;
  try {
    result = call(f);
  } catch (error) {
    if (!(error instanceof PhysicalError)) {
      throw new Error(`threw ${String(error)} instead of a PhysicalError`, { cause: error });
    }
    expect(error.field.length).toBeGreaterThan(0);
    expect(error.message.startsWith(`${error.field}: `)).toBe(true);
    outcome = 'refused';
  }
  if (outcome === 'refused') expect(inventory(f.world)).toBe(before);
  else {
    current = null;
    accepted?.(f, result);
  }
  expect(nonFinite(f.world)).toEqual([]);
  const kept = [...f.world.bodies];
  for (let i = 0; i < 60; i++) f.world.step();
  expect(nonFinite(f.world)).toEqual([]);
  for (const body of kept) expect(f.world.has(body)).toBe(true);
  return outcome;
}

/** The object of the fixture on which each class's public members are driven. */
const TARGETS: Record<string, ((f: Fixture) => object) | null> = {
  World: (f) => f.world,
  Body: (f) => f.crate,
  Shape: (f) => f.crate.shapes[0]!,
  Force: (f) => f.push,
  Joint: (f) => f.hinge,
  RevoluteJoint: (f) => f.hinge,
  PrismaticJoint: (f) => f.slider,
  DistanceJoint: (f) => f.rope,
  WeldJoint: (f) => f.weld,
  MouseJoint: (f) => f.drag,
  // An error's own field, and the classes with no public members.
  PhysicalError: null,
  BodyNumbers: null,
  TwoBodyJoint: null,
};

/** How a public member is reached on an object: an accessor, a method or a plain data field. */
function memberKind(target: object, name: string): 'accessor' | 'method' | 'data' {
  for (let p: object | null = target; p; p = Object.getPrototypeOf(p) as object | null) {
    const d = Object.getOwnPropertyDescriptor(p, name);
    if (!d) continue;
    if (d.get || d.set) return 'accessor';
    return typeof d.value === 'function' ? 'method' : 'data';
  }
  return 'data';
}

/** Whether writing `name` on `target` reaches a setter (or a data field) rather than a lone getter. */
function hasSetter(target: object, name: string): boolean {
  for (let p: object | null = target; p; p = Object.getPrototypeOf(p) as object | null) {
    const d = Object.getOwnPropertyDescriptor(p, name);
    if (d) return d.set !== undefined || 'value' in d;
  }
  return true;
}

/** A property of a class's public API, written with every bad value. */
interface SetterEntry {
  readonly name: string;
  readonly target: (f: Fixture) => object;
  readonly property: string;
}

/** Every public property (accessor or data field) of every class, from the public API's list. */
const SETTERS: readonly SetterEntry[] = Object.entries(PUBLIC_MEMBERS).flatMap(([cls, names]) => {
  const target = TARGETS[cls];
  if (target === undefined) throw new Error(`no fixture object for ${cls}: add it to TARGETS`);
  if (target === null) return [];
  const sample = target(fixture());
  return names
    .split(' ')
    .filter((name) => name && name !== 'constructor' && memberKind(sample, name) !== 'method')
    .map((property) => ({ name: `${cls}.${property}`, target, property }));
});

/** Every public method, as `Class.method`, for the check that CALLS covers them all. */
const METHODS: readonly string[] = Object.entries(PUBLIC_MEMBERS).flatMap(([cls, names]) => {
  const target = TARGETS[cls];
  if (!target) return [];
  const sample = target(fixture());
  return names
    .split(' ')
    .filter((name) => name && name !== 'constructor' && memberKind(sample, name) === 'method')
    .map((name) => `${cls}.${name}`);
});

/** The kind of a value a getter returns, so an accepted write cannot change it. */
function kindOf(value: unknown): string {
  if (value === null) return 'null';
  if (typeof value === 'object' && 'x' in value && 'y' in value) return 'vector';
  return typeof value;
}

describe('every setter: a bad value is refused with the field named, or read back well-formed', () => {
  it.each(SETTERS.map((entry) => [entry.name, entry] as const))('%s', (_name, entry) => {
    const userData = entry.property === 'userData';
    for (const [label, value] of BAD_VALUES) {
      try {
        let kind = '';
        const outcome = audit(
          (f) => {
            const target = entry.target(f) as Record<string, unknown>;
            const before = target[entry.property];
            kind = kindOf(before);
            if (!hasSetter(target, entry.property)) {
              // Read-only (a getter alone, readonly in the typings): the language refuses the
              // write in strict code, every ES module, naming the property; nothing changes.
              expect(() => (target[entry.property] = value)).toThrow(
                new RegExp(`Cannot set property ${entry.property} of .* which has only a getter`),
              );
              const after = target[entry.property];
              expect(kindOf(after)).toBe(kind);
              if (typeof after !== 'object') expect(after).toBe(before);
              return;
            }
            target[entry.property] = value;
          },
          (f) => {
            // Accepted: the getter gives back a value of the same kind, finite if a number or
            // a vector (userData holds anything: it is the app's own).
            const read = (entry.target(f) as Record<string, unknown>)[entry.property];
            if (userData) return;
            expect(kindOf(read)).toBe(kind);
            if (typeof read === 'number') expect(Number.isNaN(read)).toBe(false);
            if (kind === 'vector')
              expect(finiteVector(read as { x: number; y: number })).toBe(true);
          },
        );
        if (userData) expect(outcome).toBe('accepted');
      } catch (error) {
        throw new Error(`${entry.name} = ${label}: ${(error as Error).message}`, { cause: error });
      }
    }
  });
});

/** A method (or function) and the good arguments it is called with; each is replaced in turn. */
interface CallEntry {
  readonly name: string;
  readonly args: (f: Fixture) => unknown[];
  readonly call: (f: Fixture, args: unknown[]) => unknown;
}

const circle = { type: 'circle', radius: 0.5 } as const;
const pose = { position: { x: 0, y: 0 } };

const CALLS: readonly CallEntry[] = [
  { name: 'new World', args: () => [{}], call: (_f, [o]) => new World(o as never) },
  {
    name: 'World.add',
    args: () => [particle({ radius: 1 })],
    call: (f, a) => f.world.add(a[0] as never),
  },
  { name: 'World.remove', args: (f) => [f.ball], call: (f, a) => f.world.remove(a[0] as never) },
  { name: 'World.has', args: (f) => [f.ball], call: (f, a) => f.world.has(a[0] as never) },
  {
    name: 'World.addJoint',
    args: (f) => [revoluteJoint({ bodyA: f.ground, bodyB: f.ball, anchor: { x: 2, y: 4 } })],
    call: (f, a) => f.world.addJoint(a[0] as never),
  },
  {
    name: 'World.removeJoint',
    args: (f) => [f.rope],
    call: (f, a) => f.world.removeJoint(a[0] as never),
  },
  { name: 'World.step', args: () => [1 / 60], call: (f, a) => f.world.step(a[0] as never) },
  {
    name: 'World.bodyAt',
    args: () => [{ x: 0, y: 0 }],
    call: (f, a) => f.world.bodyAt(a[0] as never),
  },
  {
    name: 'World.bodiesInAABB',
    args: () => [{ minX: -1, minY: -1, maxX: 1, maxY: 1 }],
    call: (f, a) => f.world.bodiesInAABB(a[0] as never),
  },
  {
    name: 'World.rayCast',
    args: () => [
      { x: 0, y: -5 },
      { x: 0, y: 10 },
    ],
    call: (f, a) => f.world.rayCast(a[0] as never, a[1] as never),
  },
  {
    name: 'World.rayCastAll',
    args: () => [
      { x: 0, y: -5 },
      { x: 0, y: 10 },
    ],
    call: (f, a) => f.world.rayCastAll(a[0] as never, a[1] as never),
  },
  {
    name: 'World.shapeCast',
    args: () => [circle, pose, { x: 0, y: 10 }],
    call: (f, a) => f.world.shapeCast(a[0] as never, a[1] as never, a[2] as never),
  },
  {
    name: 'World.overlapShape',
    args: () => [circle, pose],
    call: (f, a) => f.world.overlapShape(a[0] as never, a[1] as never),
  },
  {
    name: 'World.forEachContact',
    args: () => [() => undefined],
    call: (f, a) => f.world.forEachContact(a[0] as never),
  },
  {
    name: 'World.on',
    args: () => ['move', () => undefined],
    call: (f, a) => f.world.on(a[0] as never, a[1] as never),
  },
  {
    name: 'World.off',
    args: () => ['move', () => undefined],
    call: (f, a) => f.world.off(a[0] as never, a[1] as never),
  },
  { name: 'new Body', args: () => [{}], call: (_f, [o]) => new Body(o as never) },
  {
    // Its third argument, the name messages give the shape, is the factories' (a string).
    name: 'new Shape',
    args: (f) => [f.crate, { type: 'circle', radius: 0.25 }],
    call: (_f, a) => new Shape(a[0] as never, a[1] as never, 'shape'),
  },
  {
    name: 'new Force',
    args: () => [1, 0, 0, 'constant'],
    call: (_f, a) => new Force(a[0] as never, a[1] as never, a[2] as never, a[3] as never),
  },
  {
    name: 'Body.getWorldPoint',
    args: () => [
      { x: 1, y: 0 },
      { x: 0, y: 0 },
    ],
    call: (f, a) => f.crate.getWorldPoint(a[0] as never, a[1] as never),
  },
  {
    name: 'Body.getLocalPoint',
    args: () => [
      { x: 1, y: 0 },
      { x: 0, y: 0 },
    ],
    call: (f, a) => f.crate.getLocalPoint(a[0] as never, a[1] as never),
  },
  {
    name: 'Body.getVelocityAt',
    args: () => [
      { x: 1, y: 0 },
      { x: 0, y: 0 },
    ],
    call: (f, a) => f.crate.getVelocityAt(a[0] as never, a[1] as never),
  },
  {
    name: 'Body.addShape',
    args: () => [{ type: 'circle', radius: 0.25 }],
    call: (f, a) => f.crate.addShape(a[0] as never),
  },
  {
    name: 'Body.removeShape',
    args: (f) => [f.crate.shapes[0]],
    call: (f, a) => f.crate.removeShape(a[0] as never),
  },
  {
    name: 'Body.applyForce',
    args: () => [
      { x: 1, y: 0 },
      { duration: 1, point: { x: -2, y: 4 } },
    ],
    call: (f, a) => f.crate.applyForce(a[0] as never, a[1] as never),
  },
  {
    name: 'Body.applyTorque',
    args: () => [1, { duration: 'instant' }],
    call: (f, a) => f.crate.applyTorque(a[0] as never, a[1] as never),
  },
  {
    name: 'Body.removeForce',
    args: (f) => [f.push],
    call: (f, a) => f.crate.removeForce(a[0] as never),
  },
  {
    name: 'Body.applyImpulse',
    args: () => [
      { x: 1, y: 0 },
      { x: -2, y: 4 },
    ],
    call: (f, a) => f.crate.applyImpulse(a[0] as never, a[1] as never),
  },
  {
    name: 'Body.applyAngularImpulse',
    args: () => [1],
    call: (f, a) => f.crate.applyAngularImpulse(a[0] as never),
  },
  {
    name: 'Body.on',
    args: () => ['move', () => undefined],
    call: (f, a) => f.crate.on(a[0] as never, a[1] as never),
  },
  {
    name: 'Body.off',
    args: () => ['move', () => undefined],
    call: (f, a) => f.crate.off(a[0] as never, a[1] as never),
  },
  {
    name: 'Shape.collidesWith',
    args: (f) => [f.ball.shapes[0]],
    call: (f, a) => f.crate.shapes[0]!.collidesWith(a[0] as never),
  },
  {
    name: 'Shape.getBounds',
    args: () => [undefined],
    call: (f, a) => f.crate.shapes[0]!.getBounds(a[0] as never),
  },
  {
    name: 'Force.setVector',
    args: () => [{ x: 2, y: 0 }],
    call: (f, a) => f.push.setVector(a[0] as never),
  },
  { name: 'Force.setTorque', args: () => [2], call: (f, a) => f.twist.setTorque(a[0] as never) },
  {
    name: 'RevoluteJoint.setLimits',
    args: () => [-1, 1],
    call: (f, a) => f.hinge.setLimits(a[0] as never, a[1] as never),
  },
  {
    name: 'PrismaticJoint.setLimits',
    args: () => [-1, 1],
    call: (f, a) => f.slider.setLimits(a[0] as never, a[1] as never),
  },
  {
    name: 'DistanceJoint.setLengthRange',
    args: () => [0.5, 10],
    call: (f, a) => f.rope.setLengthRange(a[0] as never, a[1] as never),
  },
  {
    name: 'takeSnapshot',
    args: (f) => [f.world],
    call: (_f, a) => takeSnapshot(a[0] as never),
  },
  {
    name: 'restoreSnapshot',
    args: (f) => [takeSnapshot(f.world)],
    call: (_f, a) => restoreSnapshot(a[0] as never).step(),
  },
  {
    name: 'bodyAtPoint',
    args: (f) => [f.world.bodies, { x: 0, y: 5 }],
    call: (_f, a) => bodyAtPoint(a[0] as never, a[1] as never),
  },
  {
    name: 'checkWorldOptions',
    args: () => [{}],
    call: (_f, a) => checkWorldOptions(a[0] as never),
  },
  { name: 'checkTimeStep', args: () => [1 / 60], call: (_f, a) => checkTimeStep(a[0] as never) },
  {
    name: 'checkWorldSetting',
    args: () => ['subSteps', 4],
    call: (_f, a) => checkWorldSetting(a[0] as never, a[1]),
  },
  {
    name: 'checkRay',
    args: () => [
      { x: 0, y: 0 },
      { x: 1, y: 0 },
    ],
    call: (_f, a) => checkRay(a[0] as never, a[1] as never),
  },
  {
    name: 'checkQueryBox',
    args: () => [{ minX: -1, minY: -1, maxX: 1, maxY: 1 }],
    call: (_f, a) => checkQueryBox(a[0] as never),
  },
  {
    name: 'checkJointOptions',
    args: (f) => ['revolute', { bodyA: f.ground, bodyB: f.ball, anchor: { x: 0, y: 0 } }],
    call: (_f, a) => checkJointOptions(a[0] as never, a[1] as never),
  },
];

/** The public methods that take no argument: driven on stale handles and inside listeners below. */
const NO_ARGUMENTS = [
  'World.clear',
  'Body.resetMass',
  'Body.wake',
  'Body.sleep',
  'Body.clearForces',
  'Force.remove',
];

it('the tables drive every public method of every class', () => {
  const driven = new Set([...CALLS.map((entry) => entry.name), ...NO_ARGUMENTS]);
  expect(METHODS.filter((name) => !driven.has(name))).toEqual([]);
  expect(METHODS.length).toBeGreaterThanOrEqual(40);
  expect(SETTERS.length).toBeGreaterThan(90);
});

/** Bodies that are not this world's: another world's, a removed one, one never added. */
const STRANGERS: readonly [string, (f: Fixture) => unknown][] = [
  ['a body of another world', (f) => f.foreign()],
  ['a removed body', (f) => f.removed],
  ['a body never added', (f) => f.loose],
  ['a shape of another body', (f) => f.ball.shapes[0]],
  ['a force of another body', (f) => f.twist],
  [
    'a joint of another world',
    (f) => revoluteJoint({ bodyA: f.foreign(), bodyB: f.foreign(), anchor: { x: 0, y: 0 } }),
  ],
  ['the world itself', (f) => f.world],
];

describe('every method and function: each argument in turn gets every bad value', () => {
  const cases = CALLS.flatMap((entry) =>
    entry
      .args(fixture())
      .map((_, index) => [`${entry.name} argument ${index}`, entry, index] as const),
  );
  it.each(cases)('%s', (title, entry, index) => {
    for (const [label, bad] of [
      ...BAD_VALUES.map(([l, value]) => [l, () => value] as [string, () => unknown]),
      ...STRANGERS,
    ]) {
      try {
        audit((f) => {
          const args = entry.args(f);
          args[index] = bad(f);
          return entry.call(f, args);
        });
      } catch (error) {
        throw new Error(`${title} = ${label}: ${(error as Error).message}`, { cause: error });
      }
    }
  });
});

/** Factories and constructors taking one option object: each option gets every bad value. */
const OPTION_ENTRIES: readonly [
  string,
  (f: Fixture) => Record<string, unknown>,
  (o: never) => unknown,
][] = [
  [
    'new World',
    () => ({
      gravity: { x: 0, y: 10 },
      subSteps: 4,
      restitutionThreshold: 1,
      contactHertz: 30,
      contactDampingRatio: 10,
      maxContactPushSpeed: 3,
      maxLinearSpeed: 400,
      enableSleep: true,
      timeToSleep: 0.5,
      enableContinuous: true,
      kernel: 'auto',
    }),
    (o) => new World(o),
  ],
  [
    'particle',
    () => ({
      radius: 0.5,
      position: { x: 0, y: 0 },
      angle: 0,
      linearVelocity: { x: 0, y: 0 },
      angularVelocity: 0,
      type: 'dynamic',
      density: 1,
      friction: 0.5,
      restitution: 0,
      sensor: false,
      filter: { category: 1, mask: 0xffff, group: 0 },
      mass: 1,
      inertia: 1,
      gravityScale: 1,
      linearDamping: 0,
      angularDamping: 0,
      drag: 0,
      fixedRotation: false,
      bullet: false,
      allowSleep: true,
      asleep: false,
      onMove: () => undefined,
      onCollision: () => undefined,
    }),
    (o) => particle(o),
  ],
  [
    'box',
    () => ({ width: 1, height: 1, radius: 0, position: { x: 0, y: 0 }, angle: 0 }),
    (o) => box(o),
  ],
  ['capsule', () => ({ length: 1, radius: 0.25 }), (o) => capsule(o)],
  ['regularPolygon', () => ({ sides: 5, radius: 0.5 }), (o) => regularPolygon(o)],
  [
    'polygon',
    () => ({
      vertices: [
        { x: 0, y: 0 },
        { x: 1, y: 0 },
        { x: 0, y: 1 },
      ],
      radius: 0,
    }),
    (o) => polygon(o),
  ],
  [
    'wall',
    () => ({ from: { x: -1, y: 0 }, to: { x: 1, y: 0 }, oneSided: false, type: 'static' }),
    (o) => wall(o),
  ],
  [
    'new Body',
    () => ({
      shapes: [{ type: 'circle', radius: 0.5, offset: { x: 0, y: 0 }, density: 1 }],
      position: { x: 0, y: 0 },
    }),
    (o) => new Body(o),
  ],
  [
    'revoluteJoint',
    (f) => ({
      bodyA: f.ground,
      bodyB: f.ball,
      anchor: { x: 2, y: 4 },
      collideConnected: false,
      enableLimit: true,
      lowerAngle: -1,
      upperAngle: 1,
      enableMotor: true,
      motorSpeed: 1,
      maxMotorTorque: 10,
      enableSpring: true,
      hertz: 2,
      dampingRatio: 0.5,
    }),
    (o) => revoluteJoint(o),
  ],
  [
    'prismaticJoint',
    (f) => ({
      bodyA: f.ground,
      bodyB: f.ball,
      anchor: { x: 2, y: 4 },
      axis: { x: 1, y: 0 },
      enableLimit: true,
      lower: -1,
      upper: 1,
      enableMotor: true,
      motorSpeed: 1,
      maxMotorForce: 10,
      enableSpring: true,
      hertz: 2,
      dampingRatio: 0.5,
    }),
    (o) => prismaticJoint(o),
  ],
  [
    'distanceJoint',
    (f) => ({
      bodyA: f.crate,
      bodyB: f.ball,
      anchorA: { x: -2, y: 4 },
      anchorB: { x: 2, y: 4 },
      length: 4,
      minLength: 1,
      maxLength: 5,
      enableSpring: true,
      hertz: 2,
      dampingRatio: 0.5,
    }),
    (o) => distanceJoint(o),
  ],
  [
    'weldJoint',
    (f) => ({
      bodyA: f.ground,
      bodyB: f.ball,
      anchor: { x: 2, y: 4 },
      linearHertz: 0,
      angularHertz: 0,
      dampingRatio: 1,
    }),
    (o) => weldJoint(o),
  ],
  [
    'mouseJoint',
    (f) => ({ body: f.ball, target: { x: 2, y: 3 }, maxForce: 100, hertz: 5, dampingRatio: 0.7 }),
    (o) => mouseJoint(o),
  ],
];

describe('every option of every factory and constructor gets every bad value', () => {
  const cases = OPTION_ENTRIES.flatMap(([name, options, make]) =>
    [...Object.keys(options(fixture())), 'noSuchOption'].map(
      (key) => [`${name}({ ${key} })`, key, options, make] as const,
    ),
  );
  it.each(cases)('%s', (title, key, options, make) => {
    for (const [label, value] of [...BAD_VALUES, ...STRANGERS]) {
      try {
        audit((f) => {
          const bad = STRANGERS.some(([, v]) => v === value)
            ? (value as (f: Fixture) => unknown)(f)
            : value;
          const made = make({ ...options(f), [key]: bad } as never);
          // What is made goes into the fixture's world, where it must step like the rest.
          if (made instanceof Body) f.world.add(made);
          else if (made instanceof World) for (let i = 0; i < 60; i++) made.step();
          else f.world.addJoint(made as Joint);
        });
      } catch (error) {
        throw new Error(`${title} = ${label}: ${(error as Error).message}`, { cause: error });
      }
    }
  });
});

/** A world in which, within 120 steps, every event kind a step delivers fires. */
interface EventScene {
  readonly world: World;
  readonly ground: Body;
  readonly ball: Body;
  readonly zone: Body;
  readonly spare: Body;
  readonly hinge: Joint;
}

function eventScene(): EventScene {
  const world = new World({ gravity: { x: 0, y: 10 } });
  const ground = world.add(box({ type: 'static', position: { x: 0, y: 5 }, width: 20, height: 1 }));
  // A bouncing ball (contactBegin, collision, contactEnd) through a sensor (sensorBegin, sensorEnd).
  const ball = world.add(particle({ position: { x: 0, y: 0 }, radius: 0.25, restitution: 1 }));
  const zone = world.add(
    particle({ type: 'static', position: { x: 0, y: 2 }, radius: 0.5, sensor: true }),
  );
  // A sleeping crate that a dropped particle wakes (wake), and a pendulum (jointRemoved).
  const spare = world.add(box({ position: { x: 3, y: 4 }, width: 1, height: 1, asleep: true }));
  const bob = world.add(particle({ position: { x: -3, y: 2 }, radius: 0.2 }));
  const hinge = world.addJoint(
    revoluteJoint({ bodyA: ground, bodyB: bob, anchor: { x: -3, y: 1 } }),
  );
  return { world, ground, ball, zone, spare, hinge };
}

/** What a listener does, once, when its event first fires; `false` when it cannot apply. */
const LISTENER_ACTIONS: readonly [string, (s: EventScene) => unknown][] = [
  ['adds a body', (s) => s.world.add(particle({ position: { x: -5, y: 0 }, radius: 0.3 }))],
  ['removes the ball', (s) => s.world.remove(s.ball)],
  ['removes the ball twice', (s) => (s.world.remove(s.ball), s.world.remove(s.ball))],
  ['removes then adds the ball', (s) => (s.world.remove(s.ball), s.world.add(s.ball))],
  ['removes the ground', (s) => s.world.remove(s.ground)],
  ['clears the world', (s) => s.world.clear()],
  ['steps the world', (s) => s.world.step()],
  ['takes a snapshot', (s) => takeSnapshot(s.world)],
  ['restores a snapshot', () => restoreSnapshot(SAVED).step()],
  [
    'adds a joint',
    (s) =>
      s.world.addJoint(
        distanceJoint({
          bodyA: s.ground,
          bodyB: s.ball,
          anchorA: { x: 0, y: 4.5 },
          anchorB: s.ball.position,
        }),
      ),
  ],
  ['removes a joint', (s) => s.world.removeJoint(s.hinge)],
  [
    'adds a shape',
    (s) => s.ball.addShape({ type: 'circle', radius: 0.1, offset: { x: 0.2, y: 0 } }),
  ],
  ['removes a shape', (s) => s.spare.removeShape(s.spare.shapes[0]!)],
  ['moves the ball', (s) => (s.ball.position = { x: 1, y: 0 })],
  ['sets a NaN velocity', (s) => (s.ball.linearVelocity = { x: NaN, y: 0 })],
  ['applies a force', (s) => s.ball.applyForce({ x: 1, y: 0 }, { duration: 'instant' })],
  ['sleeps the ball', (s) => s.ball.sleep()],
  [
    'throws',
    () => {
      throw new Error('from a listener');
    },
  ],
];

/** A snapshot of another world, restored from inside listeners. */
const SAVED = takeSnapshot(eventScene().world);

const EVENT_KINDS = [
  'move',
  'collision',
  'contactBegin',
  'contactEnd',
  'sensorBegin',
  'sensorEnd',
  'wake',
  'bodyAdded',
  'bodyRemoved',
  'jointRemoved',
] as const;

describe('changes made inside every listener: a PhysicalError or the documented model, and the world steps on', () => {
  const cases = EVENT_KINDS.flatMap((kind) =>
    LISTENER_ACTIONS.map(
      ([label, action]) => [`${kind} listener ${label}`, kind, label, action] as const,
    ),
  );
  it.each(cases)('%s', (_title, kind, label, action) => {
    const s = eventScene();
    let fired = 0;
    let outcome: unknown = 'not yet';
    s.world.on(kind, () => {
      if (fired++ > 0) return;
      try {
        action(s);
        outcome = 'accepted';
      } catch (error) {
        outcome = error;
        throw error;
      }
    });
    const before = [...s.world.bodies];
    // The events the scene only delivers when asked: a body added, a body and a joint removed,
    // and the sleeping crate woken.
    const triggers = (step: number): void => {
      if (step === 1 && kind === 'bodyAdded')
        s.world.add(particle({ position: { x: 6, y: 0 }, radius: 0.2 }));
      if (step === 1 && kind === 'bodyRemoved') s.world.remove(s.world.bodies.at(-1)!);
      if (step === 1 && kind === 'jointRemoved') s.world.removeJoint(s.hinge);
      // A particle dropped on the sleeping crate wakes it.
      if (step === 1 && kind === 'wake') {
        s.world.add(particle({ position: { x: 3, y: 2.5 }, radius: 0.2 }));
      }
    };
    for (let step = 0; step < 120; step++) {
      try {
        triggers(step);
        s.world.step();
      } catch (error) {
        // What a listener throws reaches the caller of step() (or of the call whose events it
        // was): a PhysicalError naming a field, or the listener's own error.
        expect(error).toBe(outcome);
        if (label !== 'throws') {
          expect(error).toBeInstanceOf(PhysicalError);
          expect(
            (error as PhysicalError).message.startsWith(`${(error as PhysicalError).field}: `),
          ).toBe(true);
        }
      }
    }
    expect(fired).toBeGreaterThan(0);
    expect(outcome).not.toBe('not yet');
    if (label === 'throws') expect(outcome).toBeInstanceOf(Error);
    // Nothing was lost beyond what the action removed, and the world steps on, finite.
    // A listener that throws after queuing a change still has it applied (the README's model).
    const removedByAction =
      label.startsWith('removes the ball') && label !== 'removes then adds the ball'
        ? [s.ball]
        : label === 'removes the ground'
          ? [s.ground]
          : label === 'clears the world'
            ? before
            : [];
    for (const body of before) {
      const applied = outcome === 'accepted' || label === 'removes the ball twice';
      if (!applied || !removedByAction.includes(body)) {
        if (kind !== 'bodyRemoved' || body !== before.at(-1)) expect(s.world.has(body)).toBe(true);
      } else {
        expect(s.world.has(body)).toBe(false);
      }
    }
    for (const body of s.world.bodies) expect(body.world).toBe(s.world);
    expect(nonFinite(s.world)).toEqual([]);
    for (let i = 0; i < 60; i++) s.world.step();
    expect(nonFinite(s.world)).toEqual([]);
  });
});

/** Every place in a JSON value: the path and a setter of a copy at that place. */
function places(value: unknown, path: (string | number)[] = []): (string | number)[][] {
  if (value === null || typeof value !== 'object') return [path];
  const keys = Array.isArray(value) ? value.map((_, i) => i) : Object.keys(value);
  return [
    path,
    ...keys.flatMap((k) => places((value as Record<string, unknown>)[k], [...path, k])),
  ];
}

/** A deep copy of `snapshot` (JSON) with `change` made at `path`. */
function damaged(
  snapshot: unknown,
  path: (string | number)[],
  change: (old: unknown) => unknown,
): unknown {
  const copy = JSON.parse(JSON.stringify(snapshot)) as unknown;
  if (path.length === 0) return change(copy);
  let parent = copy as Record<string | number, unknown>;
  for (const key of path.slice(0, -1)) parent = parent[key] as Record<string | number, unknown>;
  const last = path.at(-1)!;
  const next = change(parent[last]);
  if (next === DELETE) {
    if (Array.isArray(parent)) parent.splice(last as number, 1);
    else Reflect.deleteProperty(parent, last);
  } else parent[last] = next;
  return copy;
}

const DELETE = Symbol('delete');

/** What each place is changed to: the value kinds, and arrays cut, emptied and doubled. */
const DAMAGE: readonly [string, (old: unknown) => unknown][] = [
  ['NaN', () => NaN],
  ['null', () => null],
  ['removed', () => DELETE],
  ["'a'", () => 'a'],
  ['-1', () => -1],
  ['1e300', () => 1e300],
  ['{}', () => ({})],
  ['a count off by one', (old) => (typeof old === 'number' ? old + 1 : old)],
  ['cut short', (old) => (Array.isArray(old) ? old.slice(0, -1) : old)],
  ['emptied', (old) => (Array.isArray(old) ? [] : old)],
  [
    'its first entry twice',
    (old) => (Array.isArray(old) && old.length > 0 ? [old[0], ...old] : old),
  ],
];

describe('restoreSnapshot: every place of a saved world damaged every way', () => {
  const f = fixture();
  const saved = JSON.parse(JSON.stringify(takeSnapshot(f.world))) as WorldSnapshot;
  const all = places(saved);
  // Each place gets one of the damages, in turn, so that every damage meets every kind of place;
  // one test per section of the snapshot, at most 150 places each (evenly spread: the broad
  // phase's trees alone have some 900).
  const sections = Object.keys(saved).map((key) => {
    const inside = all.map((path, i) => [path, i] as const).filter(([path]) => path[0] === key);
    const stride = Math.ceil(inside.length / 150);
    return [key, inside.filter((_, n) => n % stride === 0)] as const;
  });
  it.each(sections)('%s', (_section, paths) => {
    for (const [path, i] of paths) {
      const [label, change] = DAMAGE[i % DAMAGE.length]!;
      const input = damaged(saved, path, change);
      let world: World;
      try {
        world = restoreSnapshot(input as WorldSnapshot);
      } catch (error) {
        if (!(error instanceof PhysicalError)) {
          throw new Error(`${path.join('.')} ${label}: threw ${String(error)}`, { cause: error });
        }
        expect(error.message.startsWith(`${error.field}: `)).toBe(true);
        continue;
      }
      // Accepted: a world the API could have made, which steps on, finite.
      try {
        expect(nonFinite(world)).toEqual([]);
        for (let s = 0; s < 60; s++) world.step();
        expect(nonFinite(world)).toEqual([]);
      } catch (error) {
        throw new Error(`${path.join('.')} ${label}: accepted, then ${String(error)}`, {
          cause: error,
        });
      }
    }
  });
});
