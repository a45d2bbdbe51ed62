import { afterEach, describe, expect, it, vi } from 'vitest';
import { World, box, particle, regularPolygon, takeSnapshot, wall } from '@physical/engine';
import type { Body } from '@physical/engine';
import { readFileSync } from 'node:fs';
import { kernelSettings } from '../../../src/dynamics/solver-memory.ts';
// The JavaScript build of the contact passes, compared here with the WebAssembly one.
import '@physical/engine/javascript-kernel';
import { buildContactKernel } from '../../../scripts/contact-kernel-build.ts';
import { bodyStates, differingBits } from './body-states.ts';

// The contact kernel (wasm/contact-kernel.ts) is built to WebAssembly and, by wasm2js from the
// same module, to JavaScript: a world must come out bit for bit the same whichever runs, and
// whenever it switches. (Every sample: packages/scenes/test/kernel-builds.test.ts.)

const DEFAULT_THRESHOLD = kernelSettings.minConstraints;
afterEach(() => {
  kernelSettings.minConstraints = DEFAULT_THRESHOLD;
});

/** Bouncing particles (restitution, circle pairs), boxes landing flat (two-point impacts), polygons. */
function build(): { world: World; bodies: Body[] } {
  const world = new World();
  world.add(wall({ from: { x: -6, y: 0 }, to: { x: 6, y: 0 } }));
  world.add(wall({ from: { x: -6, y: 0 }, to: { x: -6, y: -30 } }));
  world.add(wall({ from: { x: 6, y: 0 }, to: { x: 6, y: -30 } }));
  const bodies: Body[] = [];
  for (let i = 0; i < 90; i++) {
    const common = {
      position: { x: -4.5 + (i % 10), y: -2 - 1.2 * Math.floor(i / 10) },
      angle: i % 5 === 0 ? 0 : 0.1 * i,
      linearVelocity: { x: ((i * 7) % 5) - 2, y: 0 },
      restitution: (i % 4) * 0.3,
      friction: 0.2 + 0.1 * (i % 6),
    };
    const kind = i % 3;
    bodies.push(
      world.add(
        kind === 0
          ? particle({ ...common, radius: 0.3 + 0.02 * (i % 5) })
          : kind === 1
            ? box({ ...common, width: 0.5 + 0.05 * (i % 4), height: 0.4, density: 1 + (i % 7) })
            : regularPolygon({ ...common, sides: 3 + (i % 6), radius: 0.4 }),
      ),
    );
  }
  return { world, bodies };
}

function run(minConstraints: number, steps: number): { states: Float64Array; usedKernel: boolean } {
  kernelSettings.minConstraints = minConstraints;
  const { world, bodies } = build();
  for (let i = 0; i < steps; i++) world.step(1 / 60);
  const states = bodyStates(bodies);
  return { states, usedKernel: usesWebAssembly(world) };
}

function usesWebAssembly(world: World): boolean {
  return (world as unknown as { solver: { memory: { usesWebAssembly: boolean } } }).solver.memory
    .usesWebAssembly;
}

function expectBitwiseEqual(a: Float64Array, b: Float64Array): void {
  expect(a.length).toBe(b.length);
  expect(differingBits(a, b)).toBe(0);
}

describe('the contact kernel, built to WebAssembly and to JavaScript', () => {
  it('gives bit-identical worlds in both builds over 400 steps of bouncing, sliding and stacking', () => {
    const js = run(Infinity, 400);
    const wasm = run(0, 400);
    expect(js.usedKernel).toBe(false);
    expect(wasm.usedKernel).toBe(true);
    // The scene moved: a kernel that did nothing would not pass the comparison by accident.
    expect(js.states.some((v, i) => i % 6 === 1 && v > -0.5)).toBe(true);
    expectBitwiseEqual(wasm.states, js.states);
  }, 30_000);

  it('leaves no trace when a world moves to it mid-run (at 40 contacts here)', () => {
    const js = run(Infinity, 300);
    const switched = run(40, 300);
    expect(switched.usedKernel).toBe(true);
    expectBitwiseEqual(switched.states, js.states);
  }, 30_000);

  it('prepares constraints and stores impulses bit for bit too: a bouncy pile with heavy bodies', () => {
    // Pressed bouncing contacts, circle pairs and heavy-on-light pairs all go through prepare;
    // the snapshot holds every contact's numbers (impulses, bouncing counts), not only the bodies.
    function pile(minConstraints: number): { saved: string; pressed: number } {
      kernelSettings.minConstraints = minConstraints;
      const world = new World();
      world.add(wall({ from: { x: -4, y: 0 }, to: { x: 4, y: 0 } }));
      world.add(wall({ from: { x: -4, y: 0 }, to: { x: -4, y: -30 } }));
      world.add(wall({ from: { x: 4, y: 0 }, to: { x: 4, y: -30 } }));
      for (let i = 0; i < 160; i++) {
        const position = { x: -3.5 + (i % 14) * 0.5, y: -1 - Math.floor(i / 14) * 0.6 };
        world.add(
          i % 3 === 0
            ? box({ position, width: 0.4, height: 0.35, density: 8 })
            : particle({ position, radius: 0.2, restitution: 0.4 }),
        );
      }
      let pressed = 0;
      for (let i = 0; i < 240; i++) {
        world.step(1 / 60);
        if (i % 20 === 0) {
          for (const contact of takeSnapshot(world).contacts) {
            if (((contact['data'] as number[])[22] ?? 0) >= 3) pressed++;
          }
        }
      }
      return { saved: JSON.stringify(takeSnapshot(world)), pressed };
    }
    const js = pile(Infinity);
    const wasm = pile(0);
    expect(js.pressed).toBeGreaterThan(0);
    expect(wasm.saved).toBe(js.saved);
  }, 30_000);

  it('never compiles WebAssembly in a world created with kernel: javascript', () => {
    kernelSettings.minConstraints = 0;
    const world = new World({ kernel: 'javascript' });
    world.add(wall({ from: { x: -6, y: 0 }, to: { x: 6, y: 0 } }));
    for (let i = 0; i < 100; i++) {
      world.add(
        box({
          position: { x: -4.5 + (i % 10), y: -0.5 - Math.floor(i / 10) },
          width: 1,
          height: 1,
        }),
      );
    }
    for (let i = 0; i < 30; i++) world.step(1 / 60);
    let contacts = 0;
    world.forEachContact(() => contacts++);
    expect(contacts).toBeGreaterThan(64);
    expect(usesWebAssembly(world)).toBe(false);
    // The default world of the same scene does move to WebAssembly (where Node can compile it).
    const auto = new World({ kernel: 'auto' });
    auto.add(wall({ from: { x: -6, y: 0 }, to: { x: 6, y: 0 } }));
    for (let i = 0; i < 100; i++) {
      auto.add(
        box({
          position: { x: -4.5 + (i % 10), y: -0.5 - Math.floor(i / 10) },
          width: 1,
          height: 1,
        }),
      );
    }
    auto.step(1 / 60);
    expect(usesWebAssembly(auto)).toBe(true);
  });

  it('compiles its WebAssembly module once per process, when the first world that may use it is created', async () => {
    // A fresh copy of the engine (its module not compiled yet), with WebAssembly.Module counted.
    vi.resetModules();
    const engine = await import('../../../src/index.ts');
    await import('../../../src/javascript-kernel.ts');
    // The engine's types assume only ES2022 (no WebAssembly namespace), as contact-kernel.ts does.
    const api = (
      globalThis as unknown as { WebAssembly: { Module: new (bytes: Uint8Array) => object } }
    ).WebAssembly;
    const original = api.Module;
    let compiles = 0;
    class Counted extends original {
      constructor(bytes: Uint8Array) {
        super(bytes);
        compiles++;
      }
    }
    api.Module = Counted;
    try {
      new engine.World({ kernel: 'javascript' });
      expect(compiles).toBe(0);
      const world = new engine.World();
      // At creation, not in the first step that needs it (a big world's first step).
      expect(compiles).toBe(1);
      new engine.World();
      world.add(engine.wall({ from: { x: -6, y: 0 }, to: { x: 6, y: 0 } }));
      for (let i = 0; i < 100; i++) {
        world.add(
          engine.box({
            position: { x: -4.5 + (i % 10), y: -0.5 - Math.floor(i / 10) },
            width: 1,
            height: 1,
          }),
        );
      }
      world.step(1 / 60);
      expect(usesWebAssembly(world as unknown as World)).toBe(true);
      expect(compiles).toBe(1);
    } finally {
      api.Module = original;
    }
  });

  it('refuses a kernel option other than auto or javascript, naming it', () => {
    expect(() => new World({ kernel: 'wasm' as 'auto' })).toThrow(
      "kernel: must be 'auto' or 'javascript', got 'wasm'.",
    );
  });

  it('is shipped as built from its source (npm run build:kernel -w @physical/engine)', async () => {
    // The layout mirror, the WebAssembly bytes and the JavaScript build, each as committed.
    for (const [path, text] of Object.entries(await buildContactKernel())) {
      expect(readFileSync(path, 'utf8'), path).toBe(text);
    }
  }, 120_000);
});
