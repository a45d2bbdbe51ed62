import { describe, it } from 'vitest';
import fc from 'fast-check';
import { World, box, capsule, particle, polygon, regularPolygon, wall } from '@physical/engine';
import type { Body } from '@physical/engine';

// Property tests: random valid scenes never produce NaN and never throw; random sequences of
// world operations (including removals from inside collision listeners) keep `world.bodies`
// consistent.

const size = fc.double({ min: 0.05, max: 3, noNaN: true });
const coordinate = fc.double({ min: -20, max: 20, noNaN: true });
const speed = fc.double({ min: -30, max: 30, noNaN: true });
const material = fc.record({
  density: fc.double({ min: 0.1, max: 10, noNaN: true }),
  friction: fc.double({ min: 0, max: 1.5, noNaN: true }),
  restitution: fc.double({ min: 0, max: 1, noNaN: true }),
});
const pose = fc.record({
  position: fc.record({ x: coordinate, y: coordinate }),
  angle: fc.double({ min: -Math.PI, max: Math.PI, noNaN: true }),
  linearVelocity: fc.record({ x: speed, y: speed }),
  angularVelocity: fc.double({ min: -20, max: 20, noNaN: true }),
});

type BodySpec =
  | { kind: 'particle'; radius: number }
  | { kind: 'box'; width: number; height: number }
  | { kind: 'regular'; sides: number; radius: number }
  | { kind: 'convex'; radius: number; angles: number[] }
  | { kind: 'wall'; length: number }
  | { kind: 'capsule'; length: number; radius: number }
  | { kind: 'star'; radius: number; reach: number[] };

const bodySpec: fc.Arbitrary<BodySpec> = fc.oneof(
  fc.record({ kind: fc.constant('particle' as const), radius: size }),
  fc.record({ kind: fc.constant('box' as const), width: size, height: size }),
  fc.record({
    kind: fc.constant('regular' as const),
    sides: fc.integer({ min: 3, max: 8 }),
    radius: size,
  }),
  fc.record({
    kind: fc.constant('convex' as const),
    radius: size,
    // Random points on a circle, sorted by angle and spread out: always convex.
    angles: fc.array(fc.double({ min: 0, max: 1, noNaN: true }), { minLength: 3, maxLength: 8 }),
  }),
  fc.record({
    kind: fc.constant('wall' as const),
    length: fc.double({ min: 0.5, max: 30, noNaN: true }),
  }),
  fc.record({ kind: fc.constant('capsule' as const), length: size, radius: size }),
  fc.record({
    kind: fc.constant('star' as const),
    radius: size,
    // Points at evenly spread angles and random distances: a simple, usually concave outline.
    reach: fc.array(fc.double({ min: 0.3, max: 1, noNaN: true }), { minLength: 3, maxLength: 24 }),
  }),
);

const scene = fc.record({
  gravity: fc.oneof(
    fc.constant({ x: 0, y: 0 }),
    fc.record({
      x: fc.double({ min: -20, max: 20, noNaN: true }),
      y: fc.double({ min: -20, max: 20, noNaN: true }),
    }),
  ),
  bodies: fc.array(fc.record({ spec: bodySpec, pose, material }), { minLength: 1, maxLength: 25 }),
});

interface Pose {
  position: { x: number; y: number };
  angle: number;
  linearVelocity: { x: number; y: number };
  angularVelocity: number;
}

function makeBody(
  spec: BodySpec,
  p: Pose,
  m: { density: number; friction: number; restitution: number },
): Body {
  const common = { ...p, ...m };
  switch (spec.kind) {
    case 'particle':
      return particle({ ...common, radius: spec.radius });
    case 'box':
      return box({ ...common, width: spec.width, height: spec.height });
    case 'regular':
      return regularPolygon({ ...common, sides: spec.sides, radius: spec.radius });
    case 'convex': {
      // Evenly spread base angles, jittered by less than half a slot: sorted and distinct.
      const n = spec.angles.length;
      const vertices = spec.angles.map((jitter, i) => {
        const angle = ((i + 0.1 + 0.8 * jitter) / n) * 2 * Math.PI;
        return { x: spec.radius * Math.cos(angle), y: spec.radius * Math.sin(angle) };
      });
      try {
        return polygon({ ...common, vertices });
      } catch {
        // Nearly collinear points can be rejected (validly): use the regular polygon instead.
        return regularPolygon({ ...common, sides: n, radius: spec.radius });
      }
    }
    case 'capsule':
      return capsule({ ...common, length: spec.length, radius: spec.radius });
    case 'star': {
      const n = spec.reach.length;
      const vertices = spec.reach.map((reach, i) => ({
        x: spec.radius * reach * Math.cos((2 * Math.PI * i) / n),
        y: spec.radius * reach * Math.sin((2 * Math.PI * i) / n),
      }));
      try {
        return polygon({ ...common, vertices });
      } catch {
        // Nearly straight or collinear runs can be rejected (validly): use a regular polygon.
        return regularPolygon({ ...common, sides: Math.min(n, 8), radius: spec.radius });
      }
    }
    case 'wall': {
      const c = Math.cos(p.angle);
      const s = Math.sin(p.angle);
      const half = spec.length / 2;
      return wall({
        from: { x: p.position.x - c * half, y: p.position.y - s * half },
        to: { x: p.position.x + c * half, y: p.position.y + s * half },
        friction: m.friction,
        restitution: m.restitution,
      });
    }
  }
}

function allFinite(bodies: readonly Body[]): boolean {
  for (const b of bodies) {
    const values = [
      b.position.x,
      b.position.y,
      b.angle,
      b.linearVelocity.x,
      b.linearVelocity.y,
      b.angularVelocity,
    ];
    if (!values.every(Number.isFinite)) return false;
  }
  return true;
}

describe('random scenes', () => {
  it('never produce NaN and never throw in 200 steps', () => {
    fc.assert(
      fc.property(scene, ({ gravity, bodies }) => {
        const world = new World({ gravity });
        for (const { spec, pose: p, material: m } of bodies) world.add(makeBody(spec, p, m));
        for (let i = 0; i < 200; i++) {
          world.step(1 / 60);
          if (!allFinite(world.bodies)) return false;
        }
        return world.bodies.length === bodies.length;
      }),
      { numRuns: 40, seed: 20240601 },
    );
  });

  type Operation =
    | { op: 'add'; spec: BodySpec; pose: Pose }
    | { op: 'remove'; index: number }
    | {
        op: 'force';
        index: number;
        x: number;
        y: number;
        duration: 'instant' | 'constant' | number;
      }
    | { op: 'step'; count: number }
    | { op: 'removeOnCollision'; index: number };

  const operation: fc.Arbitrary<Operation> = fc.oneof(
    fc.record({ op: fc.constant('add' as const), spec: bodySpec, pose }),
    fc.record({ op: fc.constant('remove' as const), index: fc.nat() }),
    fc.record({
      op: fc.constant('force' as const),
      index: fc.nat(),
      x: speed,
      y: speed,
      duration: fc.oneof(
        fc.constant('instant' as const),
        fc.constant('constant' as const),
        fc.double({ min: 0.01, max: 2, noNaN: true }),
      ),
    }),
    fc.record({ op: fc.constant('step' as const), count: fc.integer({ min: 1, max: 20 }) }),
    fc.record({ op: fc.constant('removeOnCollision' as const), index: fc.nat() }),
  );

  it('random add/remove/applyForce/step sequences keep world.bodies consistent', () => {
    fc.assert(
      fc.property(fc.array(operation, { minLength: 1, maxLength: 40 }), (operations) => {
        const world = new World();
        // A floor and walls so that things collide.
        world.add(wall({ from: { x: -20, y: 10 }, to: { x: 20, y: 10 } }));
        const expected = new Set<Body>(world.bodies);
        const removed = new Set<Body>();
        for (const operation of operations) {
          const list = world.bodies;
          switch (operation.op) {
            case 'add': {
              const body = world.add(
                makeBody(operation.spec, operation.pose, {
                  density: 1,
                  friction: 0.5,
                  restitution: 0.3,
                }),
              );
              expected.add(body);
              break;
            }
            case 'remove': {
              if (list.length === 0) break;
              const body = list[operation.index % list.length]!;
              world.remove(body);
              expected.delete(body);
              removed.add(body);
              break;
            }
            case 'force': {
              const dynamic = list.filter((b) => b.type === 'dynamic');
              if (dynamic.length === 0) break;
              dynamic[operation.index % dynamic.length]!.applyForce(
                { x: operation.x, y: operation.y },
                { duration: operation.duration },
              );
              break;
            }
            case 'removeOnCollision': {
              if (list.length === 0) break;
              const body = list[operation.index % list.length]!;
              // Remove the body from inside its first collision listener (once).
              const off = body.on('collision', () => {
                off();
                if (world.has(body)) {
                  world.remove(body);
                  expected.delete(body);
                  removed.add(body);
                }
              });
              break;
            }
            case 'step':
              for (let i = 0; i < operation.count; i++) world.step(1 / 60);
              break;
          }
          // world.bodies matches what we added and removed, without duplicates.
          const now = world.bodies;
          if (now.length !== expected.size || new Set(now).size !== now.length) return false;
          for (const body of now) if (!expected.has(body) || body.world !== world) return false;
          for (const body of removed) if (body.world !== null || world.has(body)) return false;
          if (!allFinite(now)) return false;
        }
        return true;
      }),
      { numRuns: 50, seed: 7 },
    );
  });
});
