import type { KernelImports } from '../contact-kernel.ts';

// The joints' passes are a second module beside the contact kernel (issue #30, target 5): an app
// that imports no joint class ships neither of its builds. This file is what both builds and the
// `@physical/engine/javascript-kernel` entry share: the passes' signatures and the slot the
// entry registers the JavaScript build in. The WebAssembly build is loaded by
// joint-kernel-loader.ts, which only the joints' batches import.

/**
 * The joints' passes (wasm/joint-passes.ts), a module of their own over the contact kernel's
 * memory (joint-kernel-binary.ts, and joint-kernel-javascript.ts by wasm2js): one entry for every
 * kind and pass.
 */
export interface JointPasses {
  /**
   * Pass `pass` (joint-pass-codes.ts: the warm start, a solve or a relax pass) of the joints of
   * kind `kind` (KIND_...): active joints `from` to `to` of the JOINT_ACTIVE list at `active`
   * (record offset, state A, state B), their records in JOINT_RECORDS at `records`, the states at
   * `states`. The step's numbers (a warm start reads none): the sub-step and its inverse, the
   * joint softness (bias rate, mass and impulse scale) and the largest bias speed, stored at
   * `args` (KERNEL_ARGUMENTS: A_JOINT_..., kernel-arguments.ts; V8 boxes each double passed to
   * WebAssembly).
   */
  jointPass(
    kind: number,
    pass: number,
    records: number,
    active: number,
    states: number,
    from: number,
    to: number,
    args: number,
  ): void;
}

/** Creates the JavaScript build of the joints' passes over `imports.env.memory` (wasm2js). */
export type JavaScriptJointKernelFactory = (imports: KernelImports) => JointPasses;

/** The JavaScript build, once `@physical/engine/javascript-kernel` registered it. */
let javaScriptJointKernel: JavaScriptJointKernelFactory | null = null;

/** Makes the joints' JavaScript build available to every world (the javascript-kernel entry). */
export function registerJavaScriptJointKernel(factory: JavaScriptJointKernelFactory): void {
  javaScriptJointKernel = factory;
}

/** The registered JavaScript build, or null. */
export function registeredJavaScriptJointKernel(): JavaScriptJointKernelFactory | null {
  return javaScriptJointKernel;
}
