import { describe, expect, it } from 'vitest';
import { cosSin } from '../../../src/math/trigonometry.ts';
import { hypot } from '../../../src/math/hypot.ts';
import { createContactKernel } from '../../../src/dynamics/contact-kernel.ts';
// The JavaScript build of the kernel, compared here with the WebAssembly one and TypeScript.
import '@physical/engine/javascript-kernel';

// src/math/trigonometry.ts and hypot.ts are compiled into the kernel as they are (one source,
// scripts/contact-kernel-build.ts). Both builds of the kernel (WebAssembly and wasm2js's
// JavaScript) must give the very bits TypeScript gives, for every argument the step could pass
// and the odd ones it should not: huge, tiny and subnormal, negative, both zeros, the infinities
// and NaN (NaN compared as NaN: JavaScript does not keep a NaN's payload bits).

/** A fixed pseudo-random sequence in [0, 1) (a linear congruential generator), so runs repeat. */
function sequence(seed: number): () => number {
  let state = seed >>> 0;
  return () => {
    state = (Math.imul(state, 1664525) + 1013904223) >>> 0;
    return state / 4294967296;
  };
}

/** Arguments: random over every scale from 1e-320 to 1e308 of both signs, and the edge cases. */
function arguments_(): number[] {
  const random = sequence(30);
  const list = [
    0,
    -0,
    Infinity,
    -Infinity,
    NaN,
    Number.MIN_VALUE,
    -Number.MIN_VALUE,
    Number.MAX_VALUE,
    -Number.MAX_VALUE,
    2.2250738585072014e-308, // the smallest normal double
    Number.EPSILON,
    Math.PI / 4,
    Math.PI / 2,
    Math.PI,
    1647099.3291652855, // 2^20 pi/2: the switch to the exact remainder
    1e22,
  ];
  // Near multiples of pi/2, where the reduction cancels (fdlibm's second and third rounds).
  for (let k = -400; k <= 400; k++) {
    const a = (k * Math.PI) / 2;
    list.push(a, a * (1 + Number.EPSILON), a * (1 - Number.EPSILON), a + 1e-12);
  }
  for (let i = 0; i < 20_000; i++) {
    const magnitude = 10 ** (-320 + 628 * random());
    list.push(random() < 0.5 ? -magnitude : magnitude);
  }
  for (let i = 0; i < 20_000; i++) list.push(-20 + 40 * random());
  return list;
}

const builds = [
  { name: 'WebAssembly', webAssembly: true },
  { name: 'JavaScript (wasm2js)', webAssembly: false },
];

describe("the kernel's cosSin and hypot are the engine's, bit for bit", () => {
  const list = arguments_();

  for (const build of builds) {
    it(`cosSin: ${build.name} gives TypeScript's cos and sin for ${list.length} angles`, () => {
      const { memory, kernel, webAssembly } = createContactKernel(65536, build.webAssembly);
      expect(webAssembly).toBe(build.webAssembly);
      const view = new Float64Array(memory.buffer, 0, 2);
      const expected = new Float64Array(2);
      let differing = 0;
      for (const angle of list) {
        cosSin(angle, expected);
        kernel.cosSin(angle, 0);
        if (!Object.is(view[0], expected[0]) || !Object.is(view[1], expected[1])) differing++;
      }
      expect(differing).toBe(0);
      // The comparison compared something: the sign of zero kept, NaN for the infinities.
      kernel.cosSin(-0, 0);
      expect(Object.is(view[1], -0)).toBe(true);
      kernel.cosSin(Infinity, 0);
      expect(view[0]).toBeNaN();
    });

    it(`hypot: ${build.name} gives TypeScript's length for ${list.length} pairs`, () => {
      const { kernel } = createContactKernel(65536, build.webAssembly);
      let differing = 0;
      for (let i = 0; i < list.length; i++) {
        const x = list[i]!;
        const y = list[(i * 7919 + 13) % list.length]!;
        if (!Object.is(kernel.hypot(x, y), hypot(x, y))) differing++;
        if (!Object.is(kernel.hypot(y, x), hypot(y, x))) differing++;
      }
      expect(differing).toBe(0);
      // Scaled out of underflow and overflow, as hypot.ts promises.
      expect(kernel.hypot(3e-320, 4e-320)).toBeGreaterThan(0);
      expect(kernel.hypot(3e200, 4e200)).toBe(hypot(3e200, 4e200));
      expect(kernel.hypot(-Infinity, NaN)).toBe(Infinity);
    });
  }
});
