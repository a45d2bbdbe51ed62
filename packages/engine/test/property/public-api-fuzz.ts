import fc from 'fast-check';
import {
  PhysicalError,
  World,
  box,
  capsule,
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
} from '../../src/index.ts';
import type { Body, Force, Joint } from '../../src/index.ts';

// The fuzz suite over the whole public API (issue 15): random sequences of valid and invalid calls
// (bad numbers, absurd magnitudes, wrong types, null objects, typos, calls from inside listeners)
// on a small world. After every call:
// - the call succeeded, or threw a PhysicalError (never a TypeError or anything else);
// - a refused call left the world's snapshot bit-for-bit as it was (check, then change);
// - the world's state is finite;
// and at the end the world steps and its own snapshot restores. Shared by the CI test
// (public-api-fuzz.test.ts: fixed seed) and the long mode (`npm run fuzz -- --runs N`).

// ---------------------------------------------------------------- values

/** Numbers users get wrong: NaN, infinities, absurd magnitudes, signs, -0. */
const badNumber = fc.constantFrom(
  NaN,
  Infinity,
  -Infinity,
  Number.MAX_VALUE,
  -Number.MAX_VALUE,
  1e300,
  1e50,
  -1e20,
  1e-300,
  Number.MIN_VALUE,
  -1,
  -0,
  0,
  2 ** 53,
);
/** Values of the wrong type. */
const wrongType = fc.constantFrom<unknown>(
  null,
  undefined,
  'x',
  'constant',
  'colision',
  '',
  true,
  false,
  [],
  {},
  { x: 1 },
  () => 0,
  'y'.repeat(1000),
);
const goodNumber = fc.double({ min: -5, max: 5, noNaN: true });
const anyNumber = fc.oneof(
  { weight: 6, arbitrary: goodNumber },
  { weight: 2, arbitrary: badNumber },
  { weight: 1, arbitrary: wrongType },
);
const positiveNumber = fc.oneof(
  { weight: 6, arbitrary: fc.double({ min: 0.05, max: 3, noNaN: true }) },
  { weight: 2, arbitrary: badNumber },
  { weight: 1, arbitrary: wrongType },
);
const goodVector = fc.record({ x: goodNumber, y: goodNumber });
const anyVector = fc.oneof(
  { weight: 6, arbitrary: goodVector },
  { weight: 2, arbitrary: fc.record({ x: anyNumber, y: anyNumber }) },
  { weight: 1, arbitrary: wrongType },
);
const anyBoolean = fc.oneof(
  { weight: 6, arbitrary: fc.boolean() },
  { weight: 1, arbitrary: wrongType },
);
const eventName = fc.oneof(
  {
    weight: 6,
    arbitrary: fc.constantFrom(
      'move',
      'collision',
      'contactBegin',
      'contactEnd',
      'sensorBegin',
      'sensorEnd',
      'bodyAdded',
      'bodyRemoved',
      'jointRemoved',
      'wake',
    ),
  },
  { weight: 1, arbitrary: wrongType },
);
const duration = fc.oneof(
  fc.constantFrom<unknown>('instant', 'constant', 'forever'),
  positiveNumber,
);
const forceOptions = fc.oneof(
  {
    weight: 6,
    arbitrary: fc.record(
      { duration, point: fc.option(anyVector, { nil: undefined }) },
      { requiredKeys: [] },
    ),
  },
  { weight: 1, arbitrary: wrongType },
);
const material = fc.record(
  {
    density: positiveNumber,
    friction: anyNumber,
    restitution: anyNumber,
    sensor: anyBoolean,
    filter: fc.oneof(
      fc.record(
        { category: fc.integer({ min: 0, max: 3 }), mask: anyNumber, group: anyNumber },
        { requiredKeys: [] },
      ),
      wrongType,
    ),
  },
  { requiredKeys: [] },
);
/** A concave outline (an L), a convex one, and broken ones. */
const outline = fc.oneof(
  fc.constant([
    { x: -0.5, y: -0.5 },
    { x: 1, y: -0.5 },
    { x: 1, y: 0 },
    { x: 0, y: 0 },
    { x: 0, y: 1 },
    { x: -0.5, y: 1 },
  ]),
  fc.array(goodVector, { minLength: 3, maxLength: 12 }),
  fc.array(anyVector, { minLength: 0, maxLength: 5 }),
  wrongType,
);
const shapeOptions = fc
  .oneof(
    fc.record(
      { type: fc.constant('circle'), radius: positiveNumber, offset: anyVector },
      { requiredKeys: ['type'] },
    ),
    fc.record(
      {
        type: fc.constant('box'),
        width: positiveNumber,
        height: positiveNumber,
        angle: anyNumber,
        radius: anyNumber,
      },
      { requiredKeys: ['type'] },
    ),
    fc.record(
      { type: fc.constant('polygon'), vertices: outline, radius: anyNumber },
      { requiredKeys: ['type'] },
    ),
    fc.record({
      type: fc.constant('capsule'),
      center1: anyVector,
      center2: anyVector,
      radius: positiveNumber,
    }),
    fc.record({
      type: fc.constant('segment'),
      from: anyVector,
      to: anyVector,
      oneSided: anyBoolean,
    }),
    fc.record({ type: wrongType }),
    wrongType,
  )
  .chain((shape) =>
    typeof shape === 'object' && shape !== null && !Array.isArray(shape)
      ? material.map((m) => ({ ...m, ...shape }))
      : fc.constant(shape),
  );
const bodyOptions = fc.record(
  {
    type: fc.oneof(fc.constantFrom('dynamic', 'dynamic', 'static', 'kinematic'), wrongType),
    position: anyVector,
    angle: anyNumber,
    linearVelocity: anyVector,
    angularVelocity: anyNumber,
    mass: positiveNumber,
    gravityScale: anyNumber,
    linearDamping: anyNumber,
    drag: anyNumber,
    fixedRotation: anyBoolean,
    bullet: anyBoolean,
    allowSleep: anyBoolean,
    asleep: anyBoolean,
  },
  { requiredKeys: [] },
);

// ---------------------------------------------------------------- calls

/** What a call can reach: the world, and handles it made. */
interface Context {
  readonly world: World;
  readonly forces: Force[];
  /** Errors other than PhysicalError thrown inside listeners (reported after the step). */
  readonly listenerFaults: unknown[];
}

type Call = (ctx: Context) => void;

/** Picks an element of a list by a random index (or a junk value when the list is empty). */
function pick<T>(list: readonly T[], index: number): T {
  return list[index % Math.max(1, list.length)] as T;
}

const index = fc.nat(1000);

const setter = (
  target: (ctx: Context, i: number) => object | undefined,
  key: string,
  value: fc.Arbitrary<unknown>,
): fc.Arbitrary<Call> =>
  fc.tuple(index, value).map(([i, v]) =>
    // Counterexamples print as `set <key> = <value> on #<i>` rather than as function source.
    Object.assign(
      (ctx: Context) => {
        const object = target(ctx, i);
        if (object !== undefined) (object as Record<string, unknown>)[key] = v;
      },
      { [fc.toStringMethod]: () => `set ${key} = ${fc.stringify(v)} on #${i}` },
    ),
  );

const body = (ctx: Context, i: number): Body | undefined => pick(ctx.world.bodies, i);
const shape = (ctx: Context, i: number): object | undefined => {
  const b = body(ctx, i);
  return b === undefined ? undefined : pick(b.shapes, i >> 3);
};
const force = (ctx: Context, i: number): Force | undefined => pick(ctx.forces, i);
const joint = (ctx: Context, i: number): Joint | undefined => pick(ctx.world.joints, i);

const factory = fc.oneof(
  fc.tuple(bodyOptions, material, positiveNumber).map(
    ([o, m, r]) =>
      () =>
        particle({ ...o, ...m, radius: r } as never),
  ),
  fc.tuple(bodyOptions, material, positiveNumber, positiveNumber).map(
    ([o, m, w, h]) =>
      () =>
        box({ ...o, ...m, width: w, height: h } as never),
  ),
  fc.tuple(bodyOptions, outline).map(
    ([o, v]) =>
      () =>
        polygon({ ...o, vertices: v } as never),
  ),
  fc.tuple(bodyOptions, positiveNumber, anyNumber).map(
    ([o, r, l]) =>
      () =>
        capsule({ ...o, radius: r, length: l } as never),
  ),
  fc.tuple(bodyOptions, anyNumber, positiveNumber).map(
    ([o, s, r]) =>
      () =>
        regularPolygon({ ...o, sides: s, radius: r } as never),
  ),
  fc.tuple(anyVector, anyVector, anyBoolean).map(
    ([a, b, one]) =>
      () =>
        wall({ from: a, to: b, oneSided: one } as never),
  ),
  wrongType.map((junk) => () => particle(junk as never)),
);

const jointFactory = fc
  .tuple(index, index, fc.nat(4), anyVector, anyNumber, anyBoolean)
  .map(([i, j, kind, point, value, flag]) => (ctx: Context): Joint => {
    const a = pick(ctx.world.bodies, i) as Body;
    const b = pick(ctx.world.bodies, j) as Body;
    switch (kind) {
      case 0:
        return revoluteJoint({
          bodyA: a,
          bodyB: b,
          anchor: point,
          enableMotor: flag,
          motorSpeed: value,
          maxMotorTorque: 10,
        } as never);
      case 1:
        return prismaticJoint({
          bodyA: a,
          bodyB: b,
          anchor: point,
          axis: { x: 1, y: value },
          enableLimit: flag,
        } as never);
      case 2:
        return distanceJoint({
          bodyA: a,
          bodyB: b,
          anchorA: point,
          anchorB: b?.position ?? point,
          hertz: value,
          enableSpring: flag,
        } as never);
      case 3:
        return weldJoint({ bodyA: a, bodyB: b, anchor: point, linearHertz: value } as never);
      default:
        return mouseJoint({ body: b, target: point, hertz: value } as never);
    }
  });

/** Every call the fuzz makes. Each may be valid or not. */
const call: fc.Arbitrary<Call> = fc.oneof(
  // World.
  factory.map((make) => (ctx: Context) => void ctx.world.add(make())),
  fc.tuple(index, wrongType).map(([i, junk]) => (ctx: Context) => {
    ctx.world.remove((i % 3 === 0 ? junk : body(ctx, i)) as Body);
  }),
  fc
    .oneof(
      positiveNumber.map((dt) => (typeof dt === 'number' ? dt / 30 : dt)),
      badNumber,
      wrongType,
    )
    .map((dt) => (ctx: Context) => ctx.world.step(dt as number)),
  setter((ctx) => ctx.world, 'gravity', anyVector),
  setter(
    (ctx) => ctx.world,
    'subSteps',
    fc.oneof(fc.integer({ min: 0, max: 70 }), badNumber, wrongType),
  ),
  setter((ctx) => ctx.world, 'restitutionThreshold', anyNumber),
  setter((ctx) => ctx.world, 'enableSleep', anyBoolean),
  fc.tuple(eventName, fc.nat(3)).map(([name, action]) => (ctx: Context) => {
    // A listener that makes calls itself, from inside the step.
    const stop = ctx.world.on(name as never, (() => listenerCall(ctx, action, stop)) as never);
  }),
  fc.tuple(eventName, wrongType).map(
    ([name, junk]) =>
      (ctx: Context) =>
        void ctx.world.on(name as never, junk as never),
  ),
  anyVector.map((p) => (ctx: Context) => void ctx.world.bodyAt(p as never)),
  fc
    .oneof(
      fc.record({ minX: anyNumber, minY: anyNumber, maxX: anyNumber, maxY: anyNumber }),
      wrongType,
    )
    .map((b) => (ctx: Context) => void ctx.world.bodiesInAABB(b as never)),
  fc.tuple(anyVector, anyVector).map(
    ([a, b]) =>
      (ctx: Context) =>
        void ctx.world.rayCast(a as never, b as never),
  ),
  fc.tuple(anyVector, anyVector).map(
    ([a, b]) =>
      (ctx: Context) =>
        void ctx.world.rayCastAll(a as never, b as never),
  ),
  fc.tuple(shapeOptions, anyVector, anyNumber, anyVector).map(([s, p, a, t]) => (ctx: Context) => {
    void ctx.world.shapeCast(s as never, { position: p, angle: a } as never, t as never);
  }),
  fc.tuple(shapeOptions, anyVector, wrongType).map(([s, p, junk]) => (ctx: Context) => {
    void ctx.world.overlapShape(s as never, (p === junk ? junk : { position: p }) as never);
  }),
  jointFactory.map((make) => (ctx: Context) => void ctx.world.addJoint(make(ctx))),
  fc.tuple(index, wrongType).map(([i, junk]) => (ctx: Context) => {
    ctx.world.removeJoint((i % 3 === 0 ? junk : joint(ctx, i)) as Joint);
  }),
  wrongType.map((junk) => () => void takeSnapshot(junk as never)),
  fc.tuple(fc.string({ maxLength: 12 }), anyNumber).map(([key, v]) => (ctx: Context) => {
    // A corrupted copy of the world's own snapshot: restore refuses it or builds a separate world.
    const copy = JSON.parse(JSON.stringify(takeSnapshot(ctx.world))) as Record<string, unknown>;
    const bodies = copy['bodies'] as Record<string, unknown>[];
    const target = bodies.length > 0 ? bodies[0]! : copy;
    target[key === '' ? 'angle' : key] = v;
    restoreSnapshot(copy as never);
  }),
  // Bodies.
  setter(body, 'position', anyVector),
  setter(body, 'angle', anyNumber),
  setter(body, 'linearVelocity', anyVector),
  setter(body, 'angularVelocity', anyNumber),
  setter(body, 'mass', positiveNumber),
  setter(body, 'inertia', positiveNumber),
  setter(body, 'gravityScale', anyNumber),
  setter(body, 'linearDamping', anyNumber),
  setter(body, 'angularDamping', anyNumber),
  setter(body, 'drag', anyNumber),
  setter(body, 'fixedRotation', anyBoolean),
  setter(body, 'bullet', anyBoolean),
  setter(body, 'allowSleep', anyBoolean),
  fc.tuple(index, anyVector, forceOptions).map(([i, f, o]) => (ctx: Context) => {
    const b = body(ctx, i);
    if (b !== undefined) ctx.forces.push(b.applyForce(f as never, o as never));
  }),
  fc.tuple(index, anyNumber, forceOptions).map(([i, t, o]) => (ctx: Context) => {
    const b = body(ctx, i);
    if (b !== undefined) ctx.forces.push(b.applyTorque(t as never, o as never));
  }),
  fc
    .tuple(index, anyVector, fc.option(anyVector, { nil: undefined }))
    .map(([i, j, p]) => (ctx: Context) => {
      body(ctx, i)?.applyImpulse(j as never, p as never);
    }),
  fc.tuple(index, anyNumber).map(
    ([i, j]) =>
      (ctx: Context) =>
        body(ctx, i)?.applyAngularImpulse(j as never),
  ),
  fc.tuple(index, shapeOptions).map(
    ([i, s]) =>
      (ctx: Context) =>
        void body(ctx, i)?.addShape(s as never),
  ),
  fc.tuple(index, wrongType).map(([i, junk]) => (ctx: Context) => {
    const b = body(ctx, i);
    b?.removeShape((i % 3 === 0 ? junk : pick(b.shapes, i >> 2)) as never);
  }),
  fc.tuple(index, fc.nat(3)).map(([i, which]) => (ctx: Context) => {
    const b = body(ctx, i);
    if (b === undefined) return;
    if (which === 0) b.resetMass();
    else if (which === 1) b.wake();
    else if (which === 2) b.sleep();
    else b.clearForces();
  }),
  fc.tuple(index, eventName).map(([i, name]) => (ctx: Context) => {
    const b = body(ctx, i);
    const stop = b?.on(name as never, (() => listenerCall(ctx, i, stop)) as never);
  }),
  fc.tuple(index, anyVector).map(([i, p]) => (ctx: Context) => {
    const b = body(ctx, i);
    b?.getWorldPoint(p as never);
    b?.getVelocityAt(p as never);
  }),
  // Shapes.
  setter(shape, 'friction', anyNumber),
  setter(shape, 'restitution', anyNumber),
  setter(
    shape,
    'filter',
    fc.oneof(
      fc.record({ category: anyNumber, mask: anyNumber, group: anyNumber }, { requiredKeys: [] }),
      wrongType,
    ),
  ),
  // Force handles.
  setter(force, 'x', anyNumber),
  setter(force, 'y', anyNumber),
  setter(force, 'torque', anyNumber),
  setter(force, 'remaining', anyNumber),
  fc.tuple(index, anyVector).map(
    ([i, v]) =>
      (ctx: Context) =>
        force(ctx, i)?.setVector(v as never),
  ),
  fc.tuple(index, anyNumber).map(
    ([i, v]) =>
      (ctx: Context) =>
        force(ctx, i)?.setTorque(v as never),
  ),
  index.map((i) => (ctx: Context) => force(ctx, i)?.remove()),
  // Joints: every setter a kind has (others are plain properties the joint ignores: skipped).
  fc
    .tuple(
      index,
      fc.constantFrom(
        'enableLimit',
        'enableMotor',
        'enableSpring',
        'motorSpeed',
        'maxMotorTorque',
        'maxMotorForce',
        'hertz',
        'dampingRatio',
        'length',
        'linearHertz',
        'angularHertz',
        'target',
        'maxForce',
        'lowerAngle',
        'upperAngle',
      ),
      fc.oneof(anyNumber, anyBoolean, anyVector),
    )
    .map(([i, key, v]) => (ctx: Context) => {
      const j = joint(ctx, i);
      if (j === undefined) return;
      let owner: object | null = j;
      while (owner !== null && Object.getOwnPropertyDescriptor(owner, key) === undefined) {
        owner = Object.getPrototypeOf(owner) as object | null;
      }
      if (owner === null || Object.getOwnPropertyDescriptor(owner, key)!.set === undefined) return;
      (j as unknown as Record<string, unknown>)[key] = v;
    }),
  fc.tuple(index, anyNumber, anyNumber).map(([i, a, b]) => (ctx: Context) => {
    const j = joint(ctx, i) as unknown as {
      setLimits?: (a: number, b: number) => void;
      setLengthRange?: (a: number, b: number) => void;
    };
    if (j?.setLimits !== undefined) j.setLimits(a as never, b as never);
    else j?.setLengthRange?.(a as never, b as never);
  }),
);

/** Calls made by listeners, inside a step: some are refused there (step, shape changes, snapshots). */
function listenerCall(ctx: Context, action: number, stop: (() => void) | undefined): void {
  const { world } = ctx;
  try {
    switch (action % 4) {
      case 0:
        stop?.();
        break;
      case 1:
        world.step();
        break;
      case 2:
        if (world.bodies.length > 0) world.remove(world.bodies[action % world.bodies.length]!);
        break;
      default:
        world.bodies[0]?.addShape({ type: 'circle', radius: 0.2 });
    }
  } catch (error) {
    if (!(error instanceof PhysicalError)) ctx.listenerFaults.push(error);
  }
}

// ---------------------------------------------------------------- the property

function startWorld(): Context {
  const world = new World();
  world.add(wall({ from: { x: -6, y: 3 }, to: { x: 6, y: 3 } }));
  world.add(box({ position: { x: 0, y: 1 }, width: 1, height: 1 }));
  world.add(particle({ position: { x: 1.5, y: 0 }, radius: 0.3, restitution: 0.5 }));
  world.add(
    polygon({
      position: { x: -2, y: 0 },
      vertices: [
        { x: -0.5, y: -0.5 },
        { x: 1, y: -0.5 },
        { x: 1, y: 0 },
        { x: 0, y: 0 },
        { x: 0, y: 1 },
        { x: -0.5, y: 1 },
      ],
    }),
  );
  world.add(capsule({ position: { x: 3, y: 0 }, radius: 0.2, length: 0.6 }));
  const ctx: Context = { world, forces: [], listenerFaults: [] };
  ctx.forces.push(world.bodies[1]!.applyForce({ x: 1, y: 0 }, { duration: 'constant' }));
  world.addJoint(
    revoluteJoint({ bodyA: world.bodies[0]!, bodyB: world.bodies[1]!, anchor: { x: 0, y: 1.5 } }),
  );
  world.step();
  return ctx;
}

function expectFinite(world: World): void {
  for (const b of world.bodies) {
    const values = [
      b.position.x,
      b.position.y,
      b.angle,
      b.linearVelocity.x,
      b.linearVelocity.y,
      b.angularVelocity,
    ];
    if (!values.every(Number.isFinite)) {
      throw new Error(
        `body ${world.bodies.indexOf(b)} has a non-finite state: ${values.join(', ')}`,
      );
    }
  }
}

/** The property: a random sequence of calls on a fresh world. */
export const publicApiProperty = fc.property(
  fc.array(call, { minLength: 1, maxLength: 12 }),
  (calls) => {
    const ctx = startWorld();
    const { world } = ctx;
    for (const c of calls) {
      // Saved as data before the call, stringified only when compared.
      const before = takeSnapshot(world);
      let refused = false;
      try {
        c(ctx);
      } catch (error) {
        if (!(error instanceof PhysicalError)) throw error;
        refused = true;
      }
      if (ctx.listenerFaults.length > 0) throw ctx.listenerFaults[0];
      // Listeners catch what they are refused (listenerCall), so a step is never cut short.
      if (refused) {
        if (JSON.stringify(takeSnapshot(world)) !== JSON.stringify(before)) {
          throw new Error('a refused call changed the world');
        }
      }
      expectFinite(world);
    }
    for (let i = 0; i < 3; i++) {
      try {
        world.step();
      } catch (error) {
        if (!(error instanceof PhysicalError)) throw error;
      }
    }
    expectFinite(world);
    const copy = restoreSnapshot(JSON.parse(JSON.stringify(takeSnapshot(world))) as never);
    copy.step();
    expectFinite(copy);
  },
);
