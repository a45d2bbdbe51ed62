import { PhysicalError } from '../../core/errors.ts';
import { IMPORT_IT, compileHex, instantiate, type WasmMemory } from '../contact-kernel.ts';
import { JOINT_KERNEL_HEX } from './joint-kernel-binary.ts';
import { registeredJavaScriptJointKernel, type JointPasses } from './joint-kernel.ts';

// Loads the joints' passes over a world's solver memory. Only the joints' batches import this
// file (joint-batch.ts), so the module's hex is bundled only by apps that use a joint class; a
// world loads it when it first solves a joint, and again over each new memory
// (SolverMemory.loadJoints).

/** The compiled module: undefined until first needed, null where WebAssembly cannot compile it. */
let compiled: object | null | undefined;

/**
 * The joints' passes over `memory`, the contact kernel's: the WebAssembly build when the kernel
 * runs WebAssembly (`webAssembly`) and the module compiles, else the registered JavaScript build
 * over the same bytes (both builds give the same bits: test/unit/dynamics/joint-kernel.test.ts).
 * Throws a PhysicalError naming the `kernel` option and the import that fixes it when the
 * JavaScript build is needed and was not registered.
 */
export function createJointKernel(memory: WasmMemory, webAssembly: boolean): JointPasses {
  if (webAssembly) {
    if (compiled === undefined) compiled = compileHex(JOINT_KERNEL_HEX);
    if (compiled !== null) return instantiate(compiled, memory) as JointPasses;
  }
  const factory = registeredJavaScriptJointKernel();
  if (factory === null) {
    throw new PhysicalError(
      'kernel',
      `cannot run the joints' passes as WebAssembly here: ${IMPORT_IT}.`,
    );
  }
  // A plain object over the same bytes: wasm2js's factory sets a `grow` on the memory it gets.
  return factory({ env: { memory: { buffer: memory.buffer } } });
}
