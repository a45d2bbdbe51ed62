import { CONTACT_KERNEL_HEX } from './contact-kernel-binary.ts';

// The contact passes (prepare, warm start, solve, relax, store) compiled to WebAssembly from
// wasm/contact-kernel.ts, a line-for-line port of contact-solver.ts' prepareContacts,
// warmStartContacts, solveContacts and storeImpulses: the same operations in the same order on IEEE doubles, so both give bit-identical
// results (test/unit/dynamics/contact-kernel.test.ts) and a world may switch between them at any
// step. Why: V8 compiles WebAssembly when it loads, so a world's first steps run compiled code
// instead of waiting for JavaScript to get hot, and the passes run without bounds checks or
// deoptimisation.

/** The parts of the WebAssembly API used here (the engine's types assume only ES2022). */
export interface WasmMemory {
  readonly buffer: ArrayBuffer;
}
interface WasmApi {
  Memory: new (descriptor: { initial: number }) => WasmMemory;
  Module: new (bytes: Uint8Array) => object;
  Instance: new (module: object, imports: object) => { readonly exports: object };
}

/** The kernel's exports; pointers are byte offsets into its memory. */
export interface ContactKernel {
  /** prepareContacts; returns the number of constraints. */
  prepare(
    contactData: number,
    contactBodies: number,
    table: number,
    states: number,
    constraints: number,
    bodies: number,
    slots: number,
    circlePairs: number,
    contactCount: number,
    contactBiasRate: number,
    contactMassScale: number,
    contactImpulseScale: number,
    staticBiasRate: number,
    staticMassScale: number,
    staticImpulseScale: number,
    contactHertz: number,
    zeta: number,
    h: number,
    dt: number,
  ): number;
  /**
   * prepare's first half: which contacts become constraints (their slots, state offsets, the
   * circle-pair list and the counts below), without filling them. Returns their number.
   */
  classify(
    contactData: number,
    contactBodies: number,
    table: number,
    bodies: number,
    slots: number,
    circlePairs: number,
    contactCount: number,
  ): number;
  /** prepare's second half, for the `count` classified constraints listed from `order`. */
  prepareListed(
    contactData: number,
    contactBodies: number,
    table: number,
    states: number,
    constraints: number,
    bodies: number,
    slots: number,
    order: number,
    count: number,
    contactBiasRate: number,
    contactMassScale: number,
    contactImpulseScale: number,
    staticBiasRate: number,
    staticMassScale: number,
    staticImpulseScale: number,
    contactHertz: number,
    zeta: number,
    h: number,
    dt: number,
  ): void;
  /** The last prepare's or classify's counts. */
  readonly circlePairCount: { readonly value: number };
  readonly heavyOnLightCount: { readonly value: number };
  /** Stores the `count` constraints listed from `order` (a byte offset into the order). */
  storeImpulses(
    constraints: number,
    slots: number,
    contactData: number,
    order: number,
    count: number,
  ): void;
  warmStart(
    constraints: number,
    bodies: number,
    order: number,
    states: number,
    count: number,
  ): void;
  solve(
    constraints: number,
    bodies: number,
    order: number,
    states: number,
    count: number,
    inverseH: number,
    maxPushSpeed: number,
    restitutionThreshold: number,
    impactSpeed: number,
    loadSpeed: number,
    marks: number,
    useBias: number,
  ): number;
  impacts(
    constraints: number,
    bodies: number,
    order: number,
    states: number,
    count: number,
    impactSpeed: number,
    loadSpeed: number,
    marks: number,
    mode: number,
  ): number;
}

const wasm = (globalThis as { WebAssembly?: WasmApi }).WebAssembly;
/** The compiled module: undefined until first needed, null where WebAssembly is unavailable. */
let compiled: object | null | undefined;

function compile(): object | null {
  if (wasm === undefined) return null;
  try {
    const hex = CONTACT_KERNEL_HEX;
    const bytes = new Uint8Array(hex.length / 2);
    for (let i = 0; i < bytes.length; i++) bytes[i] = parseInt(hex.substr(2 * i, 2), 16);
    // Synchronous: the module is a few kilobytes, within every browser's main-thread limit.
    return new wasm.Module(bytes);
  } catch {
    // A Content-Security-Policy without 'wasm-unsafe-eval' refuses to compile: the JavaScript
    // passes run instead.
    return null;
  }
}

/**
 * A memory of `pages` 64 KiB pages with the kernel bound to it, or null where WebAssembly cannot
 * run (then the JavaScript passes do the same work).
 */
export function createContactKernel(
  pages: number,
): { memory: WasmMemory; kernel: ContactKernel } | null {
  if (compiled === undefined) compiled = compile();
  if (compiled === null || wasm === undefined) return null;
  try {
    const memory = new wasm.Memory({ initial: pages });
    const instance = new wasm.Instance(compiled, { env: { memory } });
    return { memory, kernel: instance.exports as ContactKernel };
  } catch {
    // Out of address space for another memory: this world keeps the JavaScript passes.
    return null;
  }
}
