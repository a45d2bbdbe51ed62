import { afterEach, describe, expect, it, vi } from 'vitest';
import { PhysicalError, World, box, wall } from '@physical/engine';
import type { Body } from '@physical/engine';

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
