import { afterEach, describe, expect, it } from 'vitest';
import { World, box, regularPolygon, wall } from '@physical/engine';
import type { Body } from '@physical/engine';
import { STATE_STRIDE } from '../../../src/dynamics/body-state.ts';
import { batchSettings, SolverBatches } from '../../../src/dynamics/solver-batches.ts';
import { kernelSettings } from '../../../src/dynamics/solver-memory.ts';
// The JavaScript build of the contact passes, compared here with the WebAssembly one.
import '@physical/engine/javascript-kernel';
import { bodyStates, differingBits } from './body-states.ts';

// Batches of islands (solver-batches.ts) must change when a constraint is solved, never what
// comes out: a world solved batch by batch is bit for bit the world solved whole.

const DEFAULTS = { ...batchSettings };
const DEFAULT_KERNEL = kernelSettings.minConstraints;
afterEach(() => {
  Object.assign(batchSettings, DEFAULTS);
  kernelSettings.minConstraints = DEFAULT_KERNEL;
});

/**
 * Eight separate piles of boxes and polygons (some bouncy, some spinning) on one ground, and a
 * kinematic paddle sweeping through two of them, which joins them into one island while it
 * touches both.
 */
function build(): { world: World; bodies: Body[] } {
  const world = new World();
  world.add(wall({ from: { x: -40, y: 0 }, to: { x: 40, y: 0 } }));
  const bodies: Body[] = [];
  for (let pile = 0; pile < 8; pile++) {
    for (let i = 0; i < 12; i++) {
      const common = {
        position: { x: -35 + 9 * pile + 0.3 * (i % 3), y: -0.5 - 1.1 * i },
        angle: i % 4 === 0 ? 0 : 0.05 * i,
        angularVelocity: (i % 5) - 2,
        restitution: (i % 3) * 0.3,
        friction: 0.3 + 0.1 * (i % 4),
      };
      bodies.push(
        world.add(
          i % 2 === 0
            ? box({ ...common, width: 1, height: 0.8, density: 1 + (i % 3) })
            : regularPolygon({ ...common, sides: 3 + (i % 5), radius: 0.5 }),
        ),
      );
    }
  }
  const paddle = world.add(
    box({ type: 'kinematic', position: { x: -31, y: -2 }, width: 1, height: 6 }),
  );
  paddle.linearVelocity = { x: 1.5, y: 0 };
  bodies.push(paddle);
  return { world, bodies };
}

interface Run {
  states: Float64Array;
  /** The most batches any step was split into. */
  mostBatches: number;
}

function run(steps: number): Run {
  const { world, bodies } = build();
  const solver = (world as unknown as { solver: { batches: SolverBatches } }).solver;
  let mostBatches = 0;
  for (let i = 0; i < steps; i++) {
    world.step(1 / 60);
    mostBatches = Math.max(mostBatches, solver.batches.count);
  }
  const states = bodyStates(bodies);
  return { states, mostBatches };
}

describe('solving a step in batches of islands', () => {
  for (const kernel of ['WebAssembly', 'JavaScript'] as const) {
    it(`gives the bit-identical world over 300 steps (${kernel} passes)`, () => {
      kernelSettings.minConstraints = kernel === 'WebAssembly' ? 0 : Infinity;
      batchSettings.minConstraints = Infinity;
      const whole = run(300);
      batchSettings.minConstraints = 0;
      batchSettings.constraintsPerBatch = 8;
      const batched = run(300);
      expect(whole.mostBatches).toBe(0);
      // Eight piles, the paddle joining two of them for a while: several batches.
      expect(batched.mostBatches).toBeGreaterThanOrEqual(4);
      expect(differingBits(whole.states, batched.states)).toBe(0);
    });
  }
});

/** Constraint bodies as the solver stores them: state offsets, 0 for a static body. */
function offsets(pairs: [number, number][]): Int32Array {
  const out = new Int32Array(2 * pairs.length);
  pairs.forEach(([a, b], i) => {
    out[2 * i] = a < 0 ? 0 : (a + 1) * STATE_STRIDE;
    out[2 * i + 1] = b < 0 ? 0 : (b + 1) * STATE_STRIDE;
  });
  return out;
}

describe('SolverBatches.build', () => {
  it('keeps islands whole and every island its constraints in their order', () => {
    batchSettings.minConstraints = 0;
    batchSettings.constraintsPerBatch = 3;
    // Bodies 0-1-2 form one island (through 1), 3-4 another, 5 rests on the ground alone,
    // 6 touches nothing; -1 is the static ground.
    const pairs: [number, number][] = [
      [0, 1],
      [3, 4],
      [-1, 5],
      [1, 2],
      [-1, 0],
      [4, 3],
      [2, -1],
      [3, -1],
      [5, -1],
    ];
    const original = [6, 2, 0, 5, 8, 1, 3, 7, 4];
    const order = Int32Array.from(original);
    const batches = new SolverBatches();
    expect(batches.build(order, pairs.length, offsets(pairs), 7)).toBe(true);
    // Islands join batches as their first constraint comes: {0, 1, 2} (4 constraints), then
    // {5} (2), then {3, 4} (3), each over the 3 a batch holds.
    expect(batches.count).toBe(3);
    const island = (c: number): number =>
      c === 1 || c === 5 || c === 7 ? 1 : c === 2 || c === 8 ? 2 : 0;
    const seen = new Map<number, number>();
    const lastPosition = new Map<number, number>();
    for (let k = 0; k < batches.count; k++) {
      for (let n = batches.orderStart[k]!; n < batches.orderStart[k + 1]!; n++) {
        const c = order[n]!;
        // Every constraint of an island lands in one batch...
        expect(seen.get(island(c)) ?? k).toBe(k);
        seen.set(island(c), k);
        // ...after the constraints of its island that came before it.
        const position = original.indexOf(c);
        expect(position).toBeGreaterThan(lastPosition.get(island(c)) ?? -1);
        lastPosition.set(island(c), position);
      }
    }
    expect(batches.orderStart[batches.count]).toBe(pairs.length);
    expect([...order].sort()).toEqual([0, 1, 2, 3, 4, 5, 6, 7, 8]);
    // Each body once, in the batch of its island's constraints; body 6 with the first batch.
    const bodyBatch = new Map<number, number>();
    for (let k = 0; k < batches.count; k++) {
      for (let n = batches.bodyStart[k]!; n < batches.bodyStart[k + 1]!; n++) {
        bodyBatch.set(batches.bodies[n]!, k);
      }
    }
    expect(bodyBatch.size).toBe(7);
    expect(bodyBatch.get(0)).toBe(seen.get(0));
    expect(bodyBatch.get(2)).toBe(seen.get(0));
    expect(bodyBatch.get(3)).toBe(seen.get(1));
    expect(bodyBatch.get(5)).toBe(seen.get(2));
    expect(bodyBatch.get(6)).toBe(0);
  });

  it('leaves the order alone when one island holds most constraints, or there are few', () => {
    batchSettings.minConstraints = 0;
    batchSettings.constraintsPerBatch = 1;
    const pairs: [number, number][] = [
      [0, 1],
      [1, 2],
      [2, 3],
      [-1, 4],
    ];
    const order = Int32Array.from([3, 1, 0, 2]);
    const batches = new SolverBatches();
    expect(batches.build(order, pairs.length, offsets(pairs), 5)).toBe(false);
    expect(batches.count).toBe(0);
    expect([...order]).toEqual([3, 1, 0, 2]);
    batchSettings.minConstraints = 5;
    expect(new SolverBatches().build(order, 4, offsets(pairs), 5)).toBe(false);
  });
});
