import fc from 'fast-check';
import {
  World,
  box,
  capsule,
  distanceJoint,
  mouseJoint,
  particle,
  polygon,
  prismaticJoint,
  regularPolygon,
  revoluteJoint,
  wall,
  weldJoint,
  type Body,
  type Joint,
} from '@physical/engine';

// Random worlds that use every feature a snapshot must carry: every joint kind with motors,
// limits and springs, a hinge chain with a heavy bob (the exact chain solve), a heavy box on a
// light one (the shock sweep), sensors, concave and rounded polygons, capsules, bullets,
// kinematic bodies, bodies that start asleep and islands that fall asleep, forces and torques
// with durations. Shared by the resume property (snapshot-resumes-exactly.test.ts) and the
// damaged-snapshot fuzz (damaged-snapshots.test.ts).

const coordinate = fc.double({ min: -6, max: 6, noNaN: true });
const speed = fc.double({ min: -15, max: 15, noNaN: true });
const size = fc.double({ min: 0.3, max: 1.2, noNaN: true });

const bodySpec = fc.record({
  kind: fc.constantFrom(
    'particle',
    'box',
    'rounded',
    'regular',
    'capsule',
    'concave',
    'kinematic',
    'static',
  ),
  x: coordinate,
  y: fc.double({ min: -8, max: -0.5, noNaN: true }),
  angle: fc.double({ min: -3, max: 3, noNaN: true }),
  vx: speed,
  vy: speed,
  spin: fc.double({ min: -5, max: 5, noNaN: true }),
  size,
  sensor: fc.boolean(),
  bullet: fc.boolean(),
  asleep: fc.boolean(),
  group: fc.integer({ min: -1, max: 1 }),
  force: fc.option(fc.double({ min: 0.02, max: 3, noNaN: true })),
  torque: fc.option(fc.constantFrom<'instant' | 'constant' | number>('instant', 'constant', 0.5)),
});

const jointSpec = fc.record({
  kind: fc.constantFrom('revolute', 'prismatic', 'distance', 'weld', 'mouse'),
  a: fc.nat(),
  b: fc.nat(),
  limit: fc.boolean(),
  motor: fc.boolean(),
  spring: fc.boolean(),
  collide: fc.boolean(),
});

/** A random world's recipe, and the step at which it is saved. */
export const worldSpec = fc.record({
  bodies: fc.array(bodySpec, { minLength: 2, maxLength: 14 }),
  joints: fc.array(jointSpec, { minLength: 1, maxLength: 6 }),
  bobRatio: fc.constantFrom(1, 30, 1000),
  stackRatio: fc.constantFrom(1, 20),
  subSteps: fc.constantFrom(4, 6),
  enableSleep: fc.boolean(),
  timeToSleep: fc.constantFrom(0.1, 0.5),
  pile: fc.boolean(),
  saveAt: fc.integer({ min: 0, max: 240 }),
});

export type WorldSpec = typeof worldSpec extends fc.Arbitrary<infer T> ? T : never;
type BodySpec = WorldSpec['bodies'][number];
type JointSpec = WorldSpec['joints'][number];

const CONCAVE = [
  { x: 0, y: 0 },
  { x: 2, y: 0 },
  { x: 2, y: -0.5 },
  { x: 0.5, y: -0.5 },
  { x: 0.5, y: -2 },
  { x: 0, y: -2 },
];

function makeBody(s: BodySpec, index: number): Body {
  const common = {
    position: { x: s.x, y: s.y },
    angle: s.angle,
    linearVelocity: { x: s.vx, y: s.vy },
    angularVelocity: s.spin,
    filter: { group: s.group },
    sensor: s.sensor && index % 3 === 0,
    bullet: s.bullet,
    asleep: s.asleep,
  };
  switch (s.kind) {
    case 'particle':
      return particle({ ...common, radius: s.size / 2, restitution: 0.6 });
    case 'box':
      return box({ ...common, width: s.size, height: s.size / 2, friction: 0.4 });
    case 'rounded':
      return box({ ...common, width: s.size, height: s.size / 3, radius: s.size / 8 });
    case 'regular':
      return regularPolygon({ ...common, sides: 3 + (index % 6), radius: s.size / 2 });
    case 'capsule':
      return capsule({ ...common, length: s.size, radius: s.size / 4 });
    case 'concave':
      return polygon({
        ...common,
        vertices: CONCAVE.map((p) => ({ x: p.x * s.size, y: p.y * s.size })),
      });
    case 'kinematic':
      return box({ ...common, type: 'kinematic', width: s.size * 2, height: 0.2 });
    default:
      return box({
        type: 'static',
        position: common.position,
        angle: s.angle / 6,
        width: s.size * 3,
        height: 0.3,
        sensor: common.sensor,
      });
  }
}

/**
 * A joint from one of the bodies to a new box 0.6 m beside it (a tree of joints with anchors
 * near both bodies, as apps build them), or null when the spec picks no valid pair.
 */
function makeJoint(s: JointSpec, world: World, first: number): Joint | null {
  const bodies = world.bodies;
  const a = bodies[first + (s.a % (bodies.length - first))]!;
  if (s.kind === 'mouse') {
    if (a.type !== 'dynamic') return null;
    return mouseJoint({
      body: a,
      target: { x: a.position.x + 0.5, y: a.position.y - 1 },
      maxForce: 200,
      hertz: 4,
    });
  }
  const b = world.add(
    box({
      position: { x: a.position.x + 0.6, y: a.position.y },
      width: 0.3 + 0.1 * (s.b % 4),
      height: 0.2,
      angularVelocity: (s.b % 5) - 2,
    }),
  );
  const anchor = { x: a.position.x + 0.3, y: a.position.y };
  const common = { bodyA: a, bodyB: b, collideConnected: s.collide };
  const drive = { enableMotor: s.motor, motorSpeed: 1.5, enableSpring: s.spring, hertz: 2 };
  switch (s.kind) {
    case 'revolute':
      return revoluteJoint({
        ...common,
        ...drive,
        anchor,
        enableLimit: s.limit,
        lowerAngle: -0.4,
        upperAngle: 0.3,
        maxMotorTorque: 20,
        dampingRatio: 0.3,
      });
    case 'prismatic':
      return prismaticJoint({
        ...common,
        ...drive,
        anchor,
        axis: { x: 1, y: 0.3 },
        enableLimit: s.limit,
        lower: -0.5,
        upper: 0.8,
        maxMotorForce: 20,
      });
    case 'distance':
      return distanceJoint({
        ...common,
        anchorA: a.position,
        anchorB: b.position,
        enableSpring: s.spring,
        hertz: s.motor ? 0 : 3,
        dampingRatio: 0.5,
        ...(s.limit ? { minLength: 0.3, maxLength: 0.9 } : {}),
      });
    default:
      return weldJoint({ ...common, anchor, linearHertz: s.spring ? 5 : 0, angularHertz: 2 });
  }
}

/** Three light links on hinges from a static pivot, and a bob `ratio` times heavier. */
function addChain(world: World, ratio: number): void {
  const pivot = world.add(
    box({ type: 'static', position: { x: 9, y: -9 }, width: 0.2, height: 0.2 }),
  );
  let previous = pivot;
  for (let k = 0; k < 3; k++) {
    const link = world.add(
      box({ position: { x: 9.25 + 0.5 * k, y: -9 }, width: 0.5, height: 0.05, density: 20 }),
    );
    world.addJoint(
      revoluteJoint({ bodyA: previous, bodyB: link, anchor: { x: 9 + 0.5 * k, y: -9 } }),
    );
    previous = link;
  }
  const bob = world.add(
    particle({ position: { x: 10.5, y: -9 }, radius: 0.1, density: 32 * ratio }),
  );
  world.addJoint(revoluteJoint({ bodyA: previous, bodyB: bob, anchor: { x: 10.5, y: -9 } }));
}

/** Builds the world a spec describes (not yet stepped). */
export function buildWorld(spec: WorldSpec): World {
  const world = new World({
    subSteps: spec.subSteps,
    enableSleep: spec.enableSleep,
    timeToSleep: spec.timeToSleep,
  });
  world.add(wall({ from: { x: -20, y: 0 }, to: { x: 20, y: 0.5 } }));
  // A hinge chain of light links with a bob `bobRatio` times heavier.
  addChain(world, spec.bobRatio);
  // A heavy box on a light one, on the ground.
  world.add(box({ position: { x: -9, y: -0.25 }, width: 0.5, height: 0.5 }));
  world.add(box({ position: { x: -9, y: -1 }, width: 1, height: 1, density: spec.stackRatio / 4 }));

  // A pile of 45 boxes: over 64 contacts, enough for the contact kernel to matter (worlds, restored
  // ones too, run its WebAssembly build from their first step).
  if (spec.pile) {
    for (let row = 0; row < 9; row++) {
      for (let i = 0; i < 9 - row; i++) {
        world.add(
          box({
            position: { x: -16 + i * 0.52 + row * 0.26, y: -0.25 - 0.5 * row },
            width: 0.5,
            height: 0.5,
          }),
        );
      }
    }
  }
  // Random joints may join any body but the ground: the chain's links and bob, the stacked
  // boxes, the pile and the random bodies.
  spec.bodies.forEach((s, i) => {
    const body = world.add(makeBody(s, i));
    if (body.type !== 'dynamic') return;
    if (s.force !== null) body.applyForce({ x: 4, y: -15 }, { duration: s.force });
    if (s.torque !== null) body.applyTorque(2, { duration: s.torque });
  });
  for (const s of spec.joints) {
    const joint = makeJoint(s, world, 1);
    if (joint !== null) world.addJoint(joint);
  }
  // Kinematic bodies keep moving.
  for (const body of world.bodies) {
    if (body.type === 'kinematic') body.angularVelocity = 0.5;
  }
  return world;
}

const scratch = new Float64Array(1);
const scratchBytes = new Uint8Array(scratch.buffer);

function mix(hash: number, x: number): number {
  scratch[0] = x;
  let h = hash;
  for (let i = 0; i < 8; i++) {
    h ^= scratchBytes[i]!;
    h = Math.imul(h, 0x01000193) >>> 0;
  }
  return h;
}

/**
 * 32-bit FNV-1a over the exact bits of every body's pose, velocity and sleep state and every
 * joint's reaction: any difference in the last bit of any of them shows.
 */
export function stateHash(world: World): number {
  let h = 0x811c9dc5;
  for (const b of world.bodies) {
    h = mix(h, b.position.x);
    h = mix(h, b.position.y);
    h = mix(h, b.angle);
    h = mix(h, b.linearVelocity.x);
    h = mix(h, b.linearVelocity.y);
    h = mix(h, b.angularVelocity);
    h = mix(h, b.isAwake ? 1 : 0);
  }
  for (const j of world.joints) {
    h = mix(h, j.reactionForce.x);
    h = mix(h, j.reactionForce.y);
    h = mix(h, j.reactionTorque);
  }
  return h;
}
