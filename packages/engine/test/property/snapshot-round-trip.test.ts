import { describe, it } from 'vitest';
import fc from 'fast-check';
import { World, box, particle, regularPolygon, wall } from '@physical/engine';
import type { Body, WorldSnapshot } from '@physical/engine';

// Property: for random scenes (every shape kind, sensors, filters, bullets, kinematic bodies,
// forces with durations) saved at a random step, the copy made through JSON steps bit-for-bit
// like the original.

const coordinate = fc.double({ min: -8, max: 8, noNaN: true });
const speed = fc.double({ min: -40, max: 40, noNaN: true });
const bodySpec = fc.record({
  kind: fc.constantFrom('particle', 'box', 'regular', 'wall', 'kinematic'),
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
    case 'kinematic':
      return box({ ...common, type: 'kinematic', width: s.size, height: 0.2 });
    default:
      return wall({ from: { x: s.x - 5, y: s.y }, to: { x: s.x + 5, y: s.y + s.size } });
  }
}

function bits(world: World): string {
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
    .join(';');
}

describe('snapshot round trip', () => {
  it('a copy restored at any step evolves bit-for-bit like the original', () => {
    fc.assert(
      fc.property(
        fc.array(bodySpec, { minLength: 1, maxLength: 20 }),
        fc.integer({ min: 0, max: 60 }),
        (specs, saveAt) => {
          const world = new World();
          specs.forEach((s, i) => {
            const body = world.add(makeBody(s, i));
            if (s.force !== null && body.type === 'dynamic') {
              body.applyForce({ x: 5, y: -20 }, { duration: s.force });
            }
          });
          for (let i = 0; i < saveAt; i++) world.step(1 / 60);
          const copy = World.fromSnapshot(
            JSON.parse(JSON.stringify(world.snapshot())) as WorldSnapshot,
          );
          for (let i = 0; i < 120; i++) {
            world.step(1 / 60);
            copy.step(1 / 60);
          }
          return bits(copy) === bits(world);
        },
      ),
      { numRuns: 30, seed: 20261122 },
    );
  }, 60_000);
});
