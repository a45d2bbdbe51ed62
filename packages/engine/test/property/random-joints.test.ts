import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import {
  World,
  box,
  distanceJoint,
  mouseJoint,
  particle,
  prismaticJoint,
  revoluteJoint,
  weldJoint,
  type Body,
  type Joint,
} from '@physical/engine';

// Property test: random valid joints between random bodies (springs, limits, motors, ropes,
// mouse joints with moving targets), added and removed at random, never produce NaN or throw.
// The joints form a tree, with anchors within a metre of the bodies they join.

const unit = fc.double({ min: 0, max: 1, noNaN: true });
const jointSpec = fc.record({
  kind: fc.constantFrom('revolute', 'prismatic', 'distance', 'weld', 'mouse'),
  a: fc.nat(),
  b: fc.nat(),
  x: fc.double({ min: -3, max: 3, noNaN: true }),
  y: fc.double({ min: -3, max: 3, noNaN: true }),
  hertz: fc.double({ min: 0, max: 30, noNaN: true }),
  ratio: fc.double({ min: 0, max: 3, noNaN: true }),
  lower: fc.double({ min: -2, max: 0, noNaN: true }),
  upper: fc.double({ min: 0, max: 2, noNaN: true }),
  speed: fc.double({ min: -10, max: 10, noNaN: true }),
  strength: fc.double({ min: 0, max: 1000, noNaN: true }),
  flags: fc.array(fc.boolean(), { minLength: 4, maxLength: 4 }),
  removeAt: fc.integer({ min: -1, max: 120 }),
});

const scene = fc.record({
  bodies: fc.array(
    fc.record({
      x: unit,
      y: unit,
      size: fc.double({ min: 0.1, max: 1, noNaN: true }),
      round: fc.boolean(),
    }),
    { minLength: 2, maxLength: 8 },
  ),
  joints: fc.array(jointSpec, { minLength: 1, maxLength: 10 }),
});

describe('random joints', () => {
  it('never produce NaN and never throw in 120 steps (a tree of joints)', () => {
    fc.assert(
      fc.property(scene, ({ bodies: specs, joints: jointSpecs }) => {
        const world = new World();
        const ground = world.add(
          box({ type: 'static', position: { x: 0, y: 5 }, width: 20, height: 1 }),
        );
        const bodies: Body[] = [ground];
        for (const s of specs) {
          const position = { x: 6 * s.x - 3, y: 4 * s.y - 3 };
          bodies.push(
            world.add(
              s.round
                ? particle({ position, radius: s.size })
                : box({ position, width: s.size, height: 2 * s.size }),
            ),
          );
        }
        // A tree: joint k holds body k + 1 to an earlier body (or the ground). Random sets of
        // rigid joints between the same bodies would fight each other (over-constrained).
        const made = jointSpecs.slice(0, bodies.length - 1).flatMap((j, k): Joint[] => {
          const bodyB = bodies[k + 1]!;
          const bodyA = bodies[j.a % (k + 1)]!;
          // Anchors near the joined body, as joints are used: an anchor metres away from a light
          // body makes an ill-conditioned lever.
          const anchor = { x: bodyB.position.x + 0.3 * j.x, y: bodyB.position.y + 0.3 * j.y };
          const [limit, motor, spring, collide] = j.flags as [boolean, boolean, boolean, boolean];
          switch (j.kind) {
            case 'revolute':
              return [
                revoluteJoint({
                  bodyA,
                  bodyB,
                  anchor,
                  enableLimit: limit,
                  lowerAngle: j.lower,
                  upperAngle: j.upper,
                  enableMotor: motor,
                  motorSpeed: j.speed,
                  maxMotorTorque: j.strength,
                  enableSpring: spring,
                  hertz: j.hertz,
                  dampingRatio: j.ratio,
                  collideConnected: collide,
                }),
              ];
            case 'prismatic':
              return [
                prismaticJoint({
                  bodyA,
                  bodyB,
                  anchor,
                  axis: { x: j.upper + 0.1, y: j.lower },
                  enableLimit: limit,
                  lower: j.lower,
                  upper: j.upper,
                  enableMotor: motor,
                  motorSpeed: j.speed,
                  maxMotorForce: j.strength,
                  enableSpring: spring,
                  hertz: j.hertz,
                  dampingRatio: j.ratio,
                }),
              ];
            case 'distance':
              return [
                distanceJoint({
                  bodyA,
                  bodyB,
                  anchorA: anchor,
                  anchorB: bodyB.position,
                  enableSpring: spring,
                  hertz: j.hertz,
                  dampingRatio: j.ratio,
                  ...(limit ? { minLength: 0, maxLength: 10 } : {}),
                }),
              ];
            case 'weld':
              return [
                weldJoint({
                  bodyA,
                  bodyB,
                  anchor,
                  linearHertz: spring ? j.hertz : 0,
                  angularHertz: motor ? j.hertz : 0,
                  dampingRatio: j.ratio,
                }),
              ];
            case 'mouse': {
              const body = bodyB;
              return [
                mouseJoint({
                  body,
                  target: anchor,
                  maxForce: j.strength,
                  hertz: j.hertz + 0.1,
                  dampingRatio: j.ratio,
                }),
              ];
            }
          }
        });
        for (const joint of made) world.addJoint(joint);
        for (let step = 0; step < 120; step++) {
          world.step(1 / 60);
          made.forEach((joint, i) => {
            if (jointSpecs[i]?.removeAt === step && joint.world !== null) world.removeJoint(joint);
            if (joint.type === 'mouse' && 'target' in joint)
              joint.target = { x: Math.sin(step), y: -1 };
          });
          if (step === 60 && bodies.length > 2) world.remove(bodies[1]!);
        }
        for (const body of world.bodies) {
          expect(Number.isFinite(body.position.x) && Number.isFinite(body.position.y)).toBe(true);
          expect(Number.isFinite(body.angle)).toBe(true);
        }
        for (const joint of world.joints) {
          expect(
            Number.isFinite(joint.reactionForce.x) && Number.isFinite(joint.reactionTorque),
          ).toBe(true);
        }
      }),
      { numRuns: 12, seed: 7 },
    );
  }, 60_000);
});
