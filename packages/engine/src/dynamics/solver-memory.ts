import { createContactKernel, type ContactKernel, type WasmMemory } from './contact-kernel.ts';

// The solver's hot arrays in one block of memory: the body states (body-state.ts) and the contact
// constraints with their body and visiting-order indices (contact-solver.ts). The JavaScript
// passes read them through typed-array views; the WebAssembly kernel (contact-kernel.ts) reads
// the same bytes at the regions' offsets. A world starts on an ordinary ArrayBuffer and moves
// into a WebAssembly memory once it has `kernelSettings.minConstraints` contacts: a small world
// gains nothing from the kernel and would hold a memory's address-space reservation for nothing.
//
// Layout, each region growing by doubling (contents kept):
//   states: doubles | constraint data: count * stride doubles | bodies: 2 int32 | order: int32

const PAGE = 65536;

/**
 * @internal When worlds move to the WebAssembly kernel: at this many contacts in a step
 * (`Infinity`: never). Tests set it to compare both kernels.
 */
export const kernelSettings = { minConstraints: 64 };

export class SolverMemory {
  states: Float64Array = new Float64Array(0);
  constraintData: Float64Array = new Float64Array(0);
  constraintBodies: Int32Array = new Int32Array(0);
  constraintOrder: Int32Array = new Int32Array(0);
  /** Byte offsets of the regions, for the kernel. */
  statesOffset = 0;
  dataOffset = 0;
  bodiesOffset = 0;
  orderOffset = 0;
  /** The WebAssembly passes over this memory, once it has moved there; null before. */
  kernel: ContactKernel | null = null;
  private wasm: WasmMemory | null = null;
  /** Set when WebAssembly could not be had: stay on the ArrayBuffer, and do not ask again. */
  private wasmRefused = false;
  private stateCapacity = 0;
  private constraintCapacity = 0;

  constructor(private readonly constraintStride: number) {
    this.layout(64 * 8, 256, false);
  }

  /** Makes room for `doubles` state numbers; returns the states' view. */
  reserveStates(doubles: number): Float64Array {
    if (doubles > this.stateCapacity) {
      this.layout(grown(this.stateCapacity, doubles), this.constraintCapacity, this.wasm !== null);
    }
    return this.states;
  }

  /** Makes room for `count` constraints; moves to the WebAssembly kernel at the threshold. */
  reserveConstraints(count: number): void {
    const toWasm =
      this.wasm !== null || (!this.wasmRefused && count >= kernelSettings.minConstraints);
    if (count > this.constraintCapacity || toWasm !== (this.wasm !== null)) {
      this.layout(this.stateCapacity, grown(this.constraintCapacity, count), toWasm);
    }
  }

  private layout(stateDoubles: number, constraintCount: number, toWasm: boolean): void {
    // Where each region is now (offset, bytes) and where it goes.
    const from = [this.statesOffset, this.dataOffset, this.bodiesOffset, this.orderOffset];
    const sizes = [
      this.states.byteLength,
      this.constraintData.byteLength,
      this.constraintBodies.byteLength,
      this.constraintOrder.byteLength,
    ];
    const oldBuffer = this.states.buffer;
    const dataOffset = stateDoubles * 8;
    const bodiesOffset = dataOffset + constraintCount * this.constraintStride * 8;
    const orderOffset = bodiesOffset + constraintCount * 8;
    const total = orderOffset + constraintCount * 4;
    const to = [0, dataOffset, bodiesOffset, orderOffset];

    let buffer: ArrayBuffer | null = null;
    if (toWasm) {
      if (this.wasm !== null && this.wasm.buffer.byteLength >= total) {
        buffer = this.wasm.buffer;
      } else {
        // A new memory rather than memory.grow: growing detaches the old buffer, and the first
        // detached ArrayBuffer of a process makes V8 check for detachment at every typed-array
        // access of all optimised code from then on (measured: tumbler ~10 % slower).
        const created = createContactKernel(Math.ceil(total / PAGE));
        if (created !== null) {
          this.wasm = created.memory;
          this.kernel = created.kernel;
          buffer = created.memory.buffer;
        }
      }
    }
    if (buffer === null) {
      if (toWasm) this.wasmRefused = true;
      this.wasm = null;
      this.kernel = null;
      buffer = new ArrayBuffer(total);
    }
    const bytes = new Uint8Array(buffer);
    if (buffer === oldBuffer) {
      // The same memory, big enough: regions only move up, so move the last first, so none
      // overwrites one not yet moved.
      for (let r = 3; r >= 0; r--) bytes.copyWithin(to[r]!, from[r]!, from[r]! + sizes[r]!);
    } else {
      for (let r = 0; r < 4; r++) bytes.set(new Uint8Array(oldBuffer, from[r]!, sizes[r]!), to[r]!);
    }
    this.statesOffset = 0;
    this.dataOffset = dataOffset;
    this.bodiesOffset = bodiesOffset;
    this.orderOffset = orderOffset;
    this.states = new Float64Array(buffer, 0, stateDoubles);
    this.constraintData = new Float64Array(
      buffer,
      dataOffset,
      constraintCount * this.constraintStride,
    );
    this.constraintBodies = new Int32Array(buffer, bodiesOffset, 2 * constraintCount);
    this.constraintOrder = new Int32Array(buffer, orderOffset, constraintCount);
    this.stateCapacity = stateDoubles;
    this.constraintCapacity = constraintCount;
  }
}

function grown(capacity: number, needed: number): number {
  let size = Math.max(capacity, 1);
  while (size < needed) size *= 2;
  return size;
}
