import { describe, it } from 'vitest';
import fc from 'fast-check';
import {
  World,
  box,
  capsule,
  distanceJoint,
  mouseJoint,
  particle,
  prismaticJoint,
  regularPolygon,
  restoreSnapshot,
  revoluteJoint,
  takeSnapshot,
  wall,
  weldJoint,
} from '@physical/engine';
import type { Body, Joint, WorldSnapshot } from '@physical/engine';

// Property: for random scenes (every shape kind, sensors, filters, bullets, kinematic bodies,
// forces with durations, joints of every kind) saved at a random step, the copy made through JSON
// steps bit-for-bit like the original, and ends with the same snapshot.

const coordinate = fc.double({ min: -8, max: 8, noNaN: true });
const speed = fc.double({ min: -40, max: 40, noNaN: true });
const bodySpec = fc.record({
  kind: fc.constantFrom('particle', 'box', 'regular', 'capsule', 'wall', 'kinematic'),
  x: coordinate,
  y: coordinate,
  angle: fc.double({ min: -3, max: 3, noNaN: true }),
  vx: speed,
  vy: speed,
  size: fc.double({ min: 0.1, max: 1.5, noNaN: true }),
  sensor: fc.boolean(),
  bullet: fc.boolean(),
  group: fc.integer({ min: -1, max: 1 }),
  force: fc.option(fc.double({ min: 0.05, max: 2, noNaN: true })),
});

type BodySpec = typeof bodySpec extends fc.Arbitrary<infer T> ? T : never;

const jointSpec = fc.record({
  kind: fc.constantFrom('revolute', 'prismatic', 'distance', 'weld', 'mouse'),
  a: fc.nat(),
  b: fc.nat(),
  limit: fc.boolean(),
  motor: fc.boolean(),
  spring: fc.boolean(),
  collide: fc.boolean(),
});

type JointSpec = typeof jointSpec extends fc.Arbitrary<infer T> ? T : never;

/** A joint between two of the bodies, or null when the spec picks no valid pair. */
function makeJoint(s: JointSpec, bodies: readonly Body[]): Joint | null {
  const a = bodies[s.a % bodies.length]!;
  const b = bodies[s.b % bodies.length]!;
  if (s.kind === 'mouse') {
    if (b.type !== 'dynamic') return null;
    return mouseJoint({ body: b, target: { x: b.position.x + 0.5, y: b.position.y - 1 } });
  }
  if (a === b || (a.type !== 'dynamic' && b.type !== 'dynamic')) return null;
  const anchor = { x: (a.position.x + b.position.x) / 2, y: (a.position.y + b.position.y) / 2 };
  const common = { bodyA: a, bodyB: b, collideConnected: s.collide };
  const drive = { enableMotor: s.motor, motorSpeed: 1, enableSpring: s.spring, hertz: 2 };
  switch (s.kind) {
    case 'revolute':
      return revoluteJoint({
        ...common,
        ...drive,
        anchor,
        enableLimit: s.limit,
        lowerAngle: -0.5,
        upperAngle: 0.5,
        maxMotorTorque: 20,
      });
    case 'prismatic':
      return prismaticJoint({
        ...common,
        ...drive,
        anchor,
        axis: { x: 1, y: 0.3 },
        enableLimit: s.limit,
        lower: -1,
        upper: 1,
        maxMotorForce: 20,
      });
    case 'distance': {
      const length = Math.hypot(a.position.x - b.position.x, a.position.y - b.position.y);
      return distanceJoint({
        ...common,
        anchorA: a.position,
        anchorB: b.position,
        enableSpring: s.spring,
        hertz: s.motor ? 0 : 3,
        dampingRatio: 0.5,
        ...(s.limit ? { minLength: 0.5 * length, maxLength: 1.5 * length } : {}),
      });
    }
    default:
      return weldJoint({ ...common, anchor, linearHertz: s.spring ? 5 : 0, angularHertz: 2 });
  }
}

function makeBody(s: BodySpec, index: number): Body {
  const common = {
    position: { x: s.x, y: s.y },
    angle: s.angle,
    linearVelocity: { x: s.vx, y: s.vy },
    filter: { group: s.group },
    sensor: s.sensor && index % 3 === 0,
    bullet: s.bullet,
  };
  switch (s.kind) {
    case 'particle':
      return particle({ ...common, radius: s.size / 2 });
    case 'box':
      return box({ ...common, width: s.size, height: s.size / 2, restitution: 0.5 });
    case 'regular':
      return regularPolygon({ ...common, sides: 3 + (index % 6), radius: s.size / 2 });
    case 'capsule':
      return capsule({ ...common, length: s.size, radius: s.size / 4 });
    case 'kinematic':
      return box({ ...common, type: 'kinematic', width: s.size, height: 0.2 });
    default:
      return wall({ from: { x: s.x - 5, y: s.y }, to: { x: s.x + 5, y: s.y + s.size } });
  }
}

function bits(world: World): string {
  const joints = world.joints.map((j) =>
    [j.reactionForce.x, j.reactionForce.y, j.reactionTorque].map(String).join(','),
  );
  return world.bodies
    .map((b) =>
      [
        b.position.x,
        b.position.y,
        b.angle,
        b.linearVelocity.x,
        b.linearVelocity.y,
        b.angularVelocity,
      ]
        .map((v) => (Object.is(v, -0) ? '-0' : String(v)))
        .join(','),
    )
    .concat(joints)
    .join(';');
}

describe('snapshot round trip', () => {
  it('a copy restored at any step evolves bit-for-bit like the original', () => {
    fc.assert(
      fc.property(
        fc.array(bodySpec, { minLength: 1, maxLength: 20 }),
        fc.array(jointSpec, { maxLength: 4 }),
        fc.integer({ min: 0, max: 60 }),
        (specs, jointSpecs, saveAt) => {
          const world = new World();
          specs.forEach((s, i) => {
            const body = world.add(makeBody(s, i));
            if (s.force !== null && body.type === 'dynamic') {
              body.applyForce({ x: 5, y: -20 }, { duration: s.force });
            }
          });
          for (const s of jointSpecs) {
            const joint = makeJoint(s, world.bodies);
            if (joint !== null) world.addJoint(joint);
          }
          for (let i = 0; i < saveAt; i++) world.step(1 / 60);
          const copy = restoreSnapshot(
            JSON.parse(JSON.stringify(takeSnapshot(world))) as WorldSnapshot,
          );
          // Every step: a lost warm start can heal within a few steps.
          for (let i = 0; i < 120; i++) {
            world.step(1 / 60);
            copy.step(1 / 60);
            if (bits(copy) !== bits(world)) return false;
          }
          return JSON.stringify(takeSnapshot(copy)) === JSON.stringify(takeSnapshot(world));
        },
      ),
      { numRuns: 30, seed: 20261122 },
    );
  }, 60_000);
});
