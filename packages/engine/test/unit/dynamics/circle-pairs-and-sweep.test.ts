import { afterEach, describe, expect, it } from 'vitest';
import { World, box, particle, wall } from '@physical/engine';
import type { Body } from '@physical/engine';
import { kernelSettings } from '../../../src/dynamics/solver-memory.ts';
import type { ContactKernel } from '../../../src/dynamics/contact-kernel.ts';
// The JavaScript build of the kernel, compared here with the WebAssembly one.
import '@physical/engine/javascript-kernel';
import { bodyStates, differingBits } from './body-states.ts';

// The circle pairs' normals (wasm/circle-pairs.ts) and the heavy-on-light sweep
// (wasm/shock-propagation.ts) run between the kernel's contact passes, written once and built into
// both builds of the kernel. Few samples have heavy bodies on light ones; this world has both
// passes at work: stacks of 10:1 to 1000:1, heavy bouncy boxes landing on light ones, and a pile
// of particles (frictionless, bouncy, of unlike masses) under a heavy ball.

const DEFAULT_THRESHOLD = kernelSettings.minConstraints;
afterEach(() => {
  kernelSettings.minConstraints = DEFAULT_THRESHOLD;
});

function build(): { world: World; bodies: Body[] } {
  const world = new World();
  world.add(box({ type: 'static', position: { x: 0, y: 0.5 }, width: 60, height: 1 }));
  const bodies: Body[] = [];
  const add = (body: Body): Body => {
    bodies.push(world.add(body));
    return body;
  };
  for (const [k, ratio] of [10, 100, 1000].entries()) {
    const x = -20 + 8 * k;
    add(box({ position: { x, y: -0.5 }, width: 1, height: 1 }));
    add(box({ position: { x, y: -1.5 }, width: 1, height: 1, density: ratio, friction: 0.6 }));
    add(box({ position: { x: x + 2, y: -0.5 }, width: 1, height: 1 }));
    add(
      box({ position: { x: x + 2, y: -3 }, width: 1, height: 1, density: ratio, restitution: 0.5 }),
    );
  }
  // A frictionless pile of particles inside two walls, a heavy ball dropped on it.
  world.add(wall({ from: { x: 5, y: 0 }, to: { x: 5, y: -10 } }));
  world.add(wall({ from: { x: 10.5, y: 0 }, to: { x: 10.5, y: -10 } }));
  for (let r = 0; r < 6; r++) {
    for (let c = 0; c < 10; c++) {
      add(
        particle({
          position: { x: 5.3 + c * 0.52 + (r % 2) * 0.2, y: -0.3 - r * 0.5 },
          radius: 0.25,
          friction: 0,
          restitution: c % 3 === 0 ? 0.4 : 0,
          density: 1 + (c % 4),
        }),
      );
    }
  }
  add(particle({ position: { x: 7.7, y: -6 }, radius: 0.5, density: 50, friction: 0 }));
  return { world, bodies };
}

describe('the circle pairs and the heavy-on-light sweep, built into the kernel', () => {
  it('give bit-identical worlds in both builds', () => {
    const run = (minConstraints: number): Float64Array => {
      kernelSettings.minConstraints = minConstraints;
      const { world, bodies } = build();
      for (let i = 0; i < 300; i++) world.step(1 / 60);
      return bodyStates(bodies);
    };
    const js = run(Infinity);
    const wasm = run(0);
    expect(wasm.length).toBe(js.length);
    expect(differingBits(wasm, js)).toBe(0);
  }, 60_000);

  it('are what the step calls: each twice a sub-step', () => {
    const { world } = build();
    for (let i = 0; i < 60; i++) world.step(1 / 60);
    const memory = (world as unknown as { solver: { memory: { kernel: ContactKernel } } }).solver
      .memory;
    const calls = { refreshCirclePairs: 0, shockSweep: 0 };
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
    // Four sub-steps (the world's default): before the warm start and the relax pass, and after
    // the solve and the relax pass.
    expect(calls).toEqual({ refreshCirclePairs: 8, shockSweep: 8 });
  }, 60_000);
});
