import { afterEach, describe, expect, it } from 'vitest';
import { hashWorld, runScene, sceneValues, scenes } from '@physical/scenes';
import { kernelSettings } from '../../engine/src/dynamics/solver-memory.ts';
// The JavaScript build of the kernel, compared here with the WebAssembly one.
import '@physical/engine/javascript-kernel';

// The kernel has one source (packages/engine/wasm/contact-kernel.ts: the contact passes, and
// wasm/body-passes.ts: integrating velocities and positions, the speed limits and finalizing the
// bodies) built twice: to WebAssembly and, by wasm2js, to JavaScript. Every sample must end in
// the same state whichever build runs it, from its first step to its last: the JavaScript build
// where WebAssembly cannot compile (or with `kernel: 'javascript'`) is then the same engine, not
// an approximation.

const DEFAULT_THRESHOLD = kernelSettings.minConstraints;
afterEach(() => {
  kernelSettings.minConstraints = DEFAULT_THRESHOLD;
});

describe('the two builds of the kernel (contact and body passes)', () => {
  for (const scene of scenes) {
    it(
      `${scene.id}: the same state hash with WebAssembly from the first step and with JavaScript only`,
      {
        timeout: 120_000,
      },
      () => {
        const values = sceneValues(scene);
        kernelSettings.minConstraints = 0;
        const wasm = runScene(scene, values);
        kernelSettings.minConstraints = Infinity;
        const js = runScene(scene, values);
        expect(hashWorld(js)).toBe(hashWorld(wasm));
      },
    );
  }
});
