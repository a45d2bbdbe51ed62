import { afterEach, describe, expect, it } from 'vitest';
import { World, box, particle, wall } from '@physical/engine';
import type { Body } from '@physical/engine';
import { kernelSettings } from '../../../src/dynamics/solver-memory.ts';
import type { ContactKernel } from '../../../src/dynamics/contact-kernel.ts';
// The JavaScript build of the kernel, compared here with the WebAssembly one.
import '@physical/engine/javascript-kernel';
import { bodyStates, differingBits } from './body-states.ts';
import { Transform } from '../../../src/math/transform.ts';
import type { Solver } from '../../../src/dynamics/solver.ts';

// The body passes (integrate velocities, integrate positions, the speed limits, finalize) are
// written once, in packages/engine/wasm/body-passes.ts, and built into the kernel's WebAssembly
// module and, by wasm2js, its JavaScript build. Every sample runs in both builds to the same bits
// (packages/scenes/test/kernel-builds.test.ts); this world adds what the samples use little or
// not at all: forces with a duration and at a point, torques, damping, drag, gravity scale,
// kinematic bodies, bodies that fall asleep and bodies kept awake by a force.

const DEFAULT_THRESHOLD = kernelSettings.minConstraints;
afterEach(() => {
  kernelSettings.minConstraints = DEFAULT_THRESHOLD;
});

interface Run {
  states: Float64Array;
  sleepTimes: number[];
  awake: boolean[];
  bodies: Body[];
}

function run(minConstraints: number, steps: number): Run {
  kernelSettings.minConstraints = minConstraints;
  const world = new World();
  world.add(wall({ from: { x: -20, y: 0 }, to: { x: 20, y: 0 } }));
  const bodies: Body[] = [];
  const add = (body: Body): Body => {
    bodies.push(world.add(body));
    return body;
  };
  // Resting boxes that fall asleep.
  for (let i = 0; i < 6; i++) {
    add(box({ position: { x: -15 + 1.2 * i, y: -0.5 }, width: 1, height: 1 }));
  }
  // Damped, dragged and lightly weighed bodies in the air.
  add(box({ position: { x: -6, y: -10 }, width: 1, height: 0.5, linearDamping: 0.7 }));
  add(box({ position: { x: -4, y: -10 }, width: 0.5, height: 1, angularVelocity: 5 }));
  bodies[bodies.length - 1]!.angularDamping = 0.9;
  add(particle({ position: { x: -2, y: -30 }, radius: 0.3, drag: 0.4 }));
  add(particle({ position: { x: 0, y: -10 }, radius: 0.3, gravityScale: -0.25 }));
  // Kinematic bodies: moving and turning at the velocity given, whatever pushes them.
  add(
    box({
      type: 'kinematic',
      position: { x: 3, y: -3 },
      width: 2,
      height: 0.2,
      linearVelocity: { x: 0.5, y: 0 },
      angularVelocity: 0.3,
    }),
  );
  // Forces with a duration: constant, timed, at a point; a torque; an instant push.
  const pushed = add(box({ position: { x: 8, y: -0.5 }, width: 1, height: 1, friction: 0.3 }));
  pushed.applyForce({ x: 6, y: 0 }, { duration: 'constant' });
  const timed = add(box({ position: { x: 12, y: -0.5 }, width: 1, height: 1 }));
  timed.applyForce({ x: 0, y: -40 }, { duration: 1.5, point: { x: 12.4, y: -0.5 } });
  const spun = add(box({ position: { x: 16, y: -0.5 }, width: 1, height: 1 }));
  spun.applyTorque(6, { duration: 0.75 });
  // A fast particle, held to the world's speed limit.
  add(particle({ position: { x: 10, y: -20 }, radius: 0.2, linearVelocity: { x: 0, y: 1e6 } }));
  for (let i = 0; i < steps; i++) {
    if (i === 100) spun.applyTorque(-2, { duration: 'instant' });
    world.step(1 / 60);
  }
  return {
    states: bodyStates(bodies),
    sleepTimes: bodies.map((b) => b.sleepTime),
    awake: bodies.map((b) => b.awake),
    bodies,
  };
}

describe('the body passes, built into the kernel', () => {
  it('give bit-identical worlds in both builds with forces, torques, damping, drag, gravity scale, kinematic and sleeping bodies', () => {
    const js = run(Infinity, 400);
    const wasm = run(0, 400);
    expect(wasm.states.length).toBe(js.states.length);
    expect(differingBits(wasm.states, js.states)).toBe(0);
    expect(wasm.sleepTimes).toEqual(js.sleepTimes);
    expect(wasm.awake).toEqual(js.awake);
    // The passes ran: resting boxes fell asleep, the constantly pushed box is kept awake and slides.
    expect(js.awake.slice(0, 6)).toEqual([false, false, false, false, false, false]);
    const pushed = js.bodies[11]!;
    expect(pushed.awake).toBe(true);
    expect(pushed.sleepTime).toBe(0);
    expect(pushed.position.x).toBeGreaterThan(8.5);
  }, 60_000);

  it('integrate a free body by semi-implicit Euler: v = g t, y = g h^2 n (n + 1) / 2 over n sub-steps', () => {
    for (const minConstraints of [0, Infinity]) {
      kernelSettings.minConstraints = minConstraints;
      const world = new World({ gravity: { x: 0, y: 9.81 }, subSteps: 4 });
      const body = world.add(particle({ position: { x: 0, y: 0 }, radius: 0.5 }));
      const steps = 30;
      for (let i = 0; i < steps; i++) world.step(1 / 60);
      const n = steps * 4;
      const h = 1 / 240;
      // Tolerance: rounding of 120 sums of about 1e-3 each.
      expect(body.linearVelocity.y).toBeCloseTo(9.81 * n * h, 10);
      expect(body.position.y).toBeCloseTo((9.81 * h * h * n * (n + 1)) / 2, 10);
      expect(body.linearVelocity.x).toBe(0);
    }
  });

  it('are what the step calls: each sub-step integrates velocities and positions once, and each step finalizes once', () => {
    const world = new World({ subSteps: 4 });
    world.add(box({ position: { x: 0, y: 0 }, width: 1, height: 1 }));
    world.step(1 / 60);
    const memory = (world as unknown as { solver: { memory: { kernel: ContactKernel } } }).solver
      .memory;
    const calls = { integrateVelocities: 0, integratePositions: 0, finalizeBodies: 0 };
    // The kernel's exports are read-only: a copy that inherits them, with the three counted.
    const kernel = memory.kernel;
    const counted = Object.create(kernel) as ContactKernel;
    for (const name of Object.keys(calls) as (keyof typeof calls)[]) {
      const pass = kernel[name] as (...args: number[]) => void;
      Object.defineProperty(counted, name, {
        value: (...args: number[]) => {
          calls[name]++;
          pass(...args);
        },
      });
    }
    memory.kernel = counted;
    world.step(1 / 60);
    expect(calls).toEqual({ integrateVelocities: 4, integratePositions: 4, finalizeBodies: 1 });
  });

  it("finalize sets each awake body's transform from its new angle and lists the fast bodies, the same in both builds", () => {
    interface Record {
      /** Awake bodies whose transform differs from TypeScript's setFromCenter, bit for bit. */
      wrongTransforms: number;
      /** Per step: the ids of the fast bodies and of the fast bullets, as the solver listed them. */
      fast: string[];
      /** The same, from the rule itself (centre's travel plus turn times max extent > half the min extent). */
      expected: string[];
    }
    const record = (minConstraints: number): Record => {
      kernelSettings.minConstraints = minConstraints;
      const world = new World();
      world.add(wall({ from: { x: -30, y: 0 }, to: { x: 30, y: 0 } }));
      // A thin plate that fast bodies would pass through without their sweep.
      world.add(box({ type: 'static', position: { x: 10, y: -5 }, width: 0.05, height: 8 }));
      // Fast particles and a fast bullet fired at it, a fast spinning bar, falling boxes, and a
      // kinematic body moving fast (not dynamic: never listed).
      for (let i = 0; i < 4; i++) {
        world.add(
          particle({
            position: { x: -5, y: -2 - i },
            radius: 0.1,
            linearVelocity: { x: 90 + 10 * i, y: 0 },
          }),
        );
      }
      world.add(
        particle({
          position: { x: -8, y: -7 },
          radius: 0.05,
          bullet: true,
          linearVelocity: { x: 200, y: 0 },
        }),
      );
      world.add(box({ position: { x: -15, y: -10 }, width: 3, height: 0.1, angularVelocity: 40 }));
      for (let i = 0; i < 5; i++) {
        world.add(box({ position: { x: -20 + 1.5 * i, y: -1 - 3 * i }, width: 1, height: 1 }));
      }
      world.add(
        box({
          type: 'kinematic',
          position: { x: -25, y: -15 },
          width: 1,
          height: 1,
          linearVelocity: { x: 100, y: 0 },
        }),
      );
      const solver = (world as unknown as { solver: Solver }).solver;
      const finalize = solver.finalizeBodies.bind(solver);
      const result: Record = { wrongTransforms: 0, fast: [], expected: [] };
      const transform = new Transform();
      solver.finalizeBodies = (dt, bounds, continuous) => {
        finalize(dt, bounds, continuous);
        const fast: number[] = [];
        const bullets: number[] = [];
        for (let i = 0; i < solver.awakeCount; i++) {
          const body = solver.awake[i]!;
          transform.setFromCenter(
            body.centerX,
            body.centerY,
            body.angleValue,
            body.localCenterX,
            body.localCenterY,
          );
          const t = body.transform;
          if (
            !Object.is(t.x, transform.x) ||
            !Object.is(t.y, transform.y) ||
            !Object.is(t.c, transform.c) ||
            !Object.is(t.s, transform.s)
          ) {
            result.wrongTransforms++;
          }
          const dx = body.centerX - body.center0X;
          const dy = body.centerY - body.center0Y;
          const motion =
            Math.sqrt(dx * dx + dy * dy) + Math.abs(body.angleValue - body.angle0) * body.maxExtent;
          if (body.type === 'dynamic' && motion > 0.5 * body.minExtent) {
            (body.bullet ? bullets : fast).push(body.id);
          }
        }
        const listed = (list: readonly Body[], count: number): string =>
          list
            .slice(0, count)
            .map((b) => b.id)
            .join(',');
        result.fast.push(
          `${listed(solver.fastBodies, solver.fastCount)} | ${listed(solver.fastBullets, solver.fastBulletCount)}`,
        );
        result.expected.push(`${fast.join(',')} | ${bullets.join(',')}`);
      };
      for (let i = 0; i < 120; i++) world.step(1 / 60);
      return result;
    };
    const js = record(Infinity);
    const wasm = record(0);
    for (const r of [js, wasm]) {
      expect(r.wrongTransforms).toBe(0);
      expect(r.fast).toEqual(r.expected);
    }
    expect(wasm.fast).toEqual(js.fast);
    // The lists held something: fast bodies and the bullet in the first steps, none at the end.
    expect(js.fast[0]).toMatch(/^\d+(,\d+)+ \| \d+$/);
    expect(js.fast.filter((f) => f !== ' | ').length).toBeGreaterThan(3);
  }, 60_000);
});
