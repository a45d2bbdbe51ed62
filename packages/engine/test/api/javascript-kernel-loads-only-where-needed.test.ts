import { afterEach, describe, expect, it, vi } from 'vitest';
import { PhysicalError, World, box, revoluteJoint, wall } from '@physical/engine';
import type { Body } from '@physical/engine';
import { JOINT_KERNEL_HEX } from '../../src/dynamics/joints/joint-kernel-binary.ts';

// The contact passes' JavaScript build is an entry of its own, `@physical/engine/javascript-kernel`
// (issue #30, target 5): an app that runs WebAssembly does not ship it. A world that needs it and
// finds it missing says so when it is created, naming the option and the import.

/** The parts of the WebAssembly namespace replaced here (the engine's types assume ES2022 only). */
interface WasmNamespace {
  Module: new (bytes: Uint8Array) => object;
}
const api = (globalThis as unknown as { WebAssembly: WasmNamespace }).WebAssembly;
const originalModule = api.Module;
afterEach(() => {
  api.Module = originalModule;
});

function usesWebAssembly(world: World): boolean {
  return (world as unknown as { solver: { memory: { usesWebAssembly: boolean } } }).solver.memory
    .usesWebAssembly;
}

/** A crate dropped on a floor, stepped 90 times: its final pose and speed. */
function drop(world: World): number[] {
  world.add(wall({ from: { x: -5, y: 0 }, to: { x: 5, y: 0 } }));
  const crate: Body = world.add(
    box({ position: { x: 0, y: -2 }, angle: 0.3, width: 1, height: 1 }),
  );
  for (let i = 0; i < 90; i++) world.step(1 / 60);
  return [crate.position.x, crate.position.y, crate.angle, crate.linearVelocity.y];
}

describe('the JavaScript build of the contact passes', () => {
  it("is not loaded by the engine: kernel: 'javascript' without it is a PhysicalError naming the option and the import", () => {
    let error: unknown;
    try {
      new World({ kernel: 'javascript' });
    } catch (caught) {
      error = caught;
    }
    expect(error).toBeInstanceOf(PhysicalError);
    expect((error as PhysicalError).field).toBe('kernel');
    expect((error as Error).message).toContain("import '@physical/engine/javascript-kernel'");
  });

  it('is not needed by a small world, which runs WebAssembly from its first step', () => {
    const world = new World();
    expect(usesWebAssembly(world)).toBe(true);
    const [, y] = drop(world);
    // Resting on the floor (y down): its centre half a metre above it, to the solver's slop.
    expect(y).toBeCloseTo(-0.5, 2);
    expect(usesWebAssembly(world)).toBe(true);
  });

  it("runs kernel: 'javascript' once imported, and 'auto' where WebAssembly cannot compile, to the same bits", async () => {
    const reference = drop(new World());
    await import('@physical/engine/javascript-kernel');
    const javaScript = new World({ kernel: 'javascript' });
    expect(usesWebAssembly(javaScript)).toBe(false);
    expect(drop(javaScript)).toEqual(reference);

    // A fresh engine (its module not compiled yet) on a host that refuses to compile, as under
    // script-src 'self': without the entry, 'auto' says what to import; with it, it runs.
    vi.resetModules();
    api.Module = function refused(): object {
      throw new Error('Wasm code generation disallowed by embedder');
    } as unknown as WasmNamespace['Module'];
    const fresh = await import('../../src/index.ts');
    expect(() => new fresh.World()).toThrow(
      /kernel: is 'auto', but WebAssembly cannot run here .*import '@physical\/engine\/javascript-kernel'/,
    );
    await import('../../src/javascript-kernel.ts');
    const fallback = new fresh.World();
    expect(usesWebAssembly(fallback as unknown as World)).toBe(false);
    expect(drop(fallback as unknown as World)).toEqual(reference);
  });
});

/** The memory's joint passes: unset until the world first solves a joint. */
function jointPasses(world: World): object | undefined {
  return (world as unknown as { solver: { memory: { joints?: object } } }).solver.memory.joints;
}

/** A two-link pendulum swinging from a static box, stepped 120 times: its links' poses. */
function swing(world: World, joint: typeof revoluteJoint = revoluteJoint): number[] {
  const pivot = world.add(
    box({ type: 'static', position: { x: 0, y: 0 }, width: 0.2, height: 0.2 }),
  );
  const a = world.add(box({ position: { x: 1, y: 0 }, width: 2, height: 0.2 }));
  const b = world.add(box({ position: { x: 3, y: 0 }, width: 2, height: 0.2, density: 3 }));
  world.step(1 / 60);
  expect(jointPasses(world), 'no joint passes loaded before a joint').toBeUndefined();
  world.addJoint(joint({ bodyA: pivot, bodyB: a, anchor: { x: 0, y: 0 } }));
  world.addJoint(joint({ bodyA: a, bodyB: b, anchor: { x: 2, y: 0 } }));
  for (let i = 0; i < 120; i++) world.step(1 / 60);
  expect(jointPasses(world), 'the joint passes loaded with the first joint').toBeDefined();
  return [a.position.x, a.position.y, a.angle, b.position.x, b.position.y, b.angle];
}

describe("the joints' passes, a module of their own", () => {
  it('swing a pendulum (the links hang below the pivot, the hinges hold) with WebAssembly', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    const [ax, ay, aAngle, bx, by, bAngle] = swing(world) as [
      number,
      number,
      number,
      number,
      number,
      number,
    ];
    expect(usesWebAssembly(world)).toBe(true);
    // The hinges hold, to 3 cm (soft joints stretch a little under the swing's load; unsolved, the
    // links would have fallen ~4 m in the 2 s): the first link's centre stays 1 m from the pivot,
    // and its far end (1 m along it) meets the second link's near end (1 m back along that).
    expect(Math.abs(Math.hypot(ax, ay) - 1)).toBeLessThan(0.03);
    const endX = ax + Math.cos(aAngle);
    const endY = ay + Math.sin(aAngle);
    const startX = bx - Math.cos(bAngle);
    const startY = by - Math.sin(bAngle);
    expect(Math.hypot(endX - startX, endY - startY)).toBeLessThan(0.03);
    // Gravity (y down) has swung the first link below the pivot's level.
    expect(ay).toBeGreaterThan(0);
  });

  it("run as JavaScript (the entry's build) over a WebAssembly memory where only their module cannot compile, to the same bits", async () => {
    const reference = swing(new World({ gravity: { x: 0, y: 10 } }));
    vi.resetModules();
    // Refuses only the joints' module (by its length): the contact kernel still compiles.
    const jointBytes = JOINT_KERNEL_HEX.length / 2;
    api.Module = function refuseJoints(bytes: Uint8Array): object {
      if (bytes.length === jointBytes) throw new Error('Wasm code generation disallowed');
      return new originalModule(bytes);
    } as unknown as WasmNamespace['Module'];
    const fresh = await import('../../src/index.ts');
    const missing = new fresh.World({ gravity: { x: 0, y: 10 } });
    let error: unknown;
    try {
      swing(missing as unknown as World, fresh.revoluteJoint as typeof revoluteJoint);
    } catch (caught) {
      error = caught;
    }
    expect(error).toBeInstanceOf(fresh.PhysicalError);
    expect((error as Error).message).toMatch(
      /^kernel: .*import '@physical\/engine\/javascript-kernel'/,
    );
    await import('../../src/javascript-kernel.ts');
    const mixed = new fresh.World({ gravity: { x: 0, y: 10 } });
    const swung = swing(mixed as unknown as World, fresh.revoluteJoint as typeof revoluteJoint);
    expect(usesWebAssembly(mixed as unknown as World)).toBe(true);
    expect(swung).toEqual(reference);
  });

  it('run as JavaScript where no WebAssembly compiles, to the same bits', async () => {
    const reference = swing(new World({ gravity: { x: 0, y: 10 } }));
    vi.resetModules();
    api.Module = function refused(): object {
      throw new Error('Wasm code generation disallowed by embedder');
    } as unknown as WasmNamespace['Module'];
    const fresh = await import('../../src/index.ts');
    await import('../../src/javascript-kernel.ts');
    const fallback = new fresh.World({ gravity: { x: 0, y: 10 } });
    const swung = swing(fallback as unknown as World, fresh.revoluteJoint as typeof revoluteJoint);
    expect(usesWebAssembly(fallback as unknown as World)).toBe(false);
    expect(swung).toEqual(reference);
  });
});
