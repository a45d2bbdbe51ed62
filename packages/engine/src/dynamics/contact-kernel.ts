import { PhysicalError } from '../core/errors.ts';
import { CONTACT_KERNEL_HEX } from './contact-kernel-binary.ts';

// The contact passes (prepare, warm start, solve, relax, store) and the body passes (integration,
// finalize) have one source, wasm/contact-kernel.ts and wasm/body-passes.ts (AssemblyScript), built twice by scripts/contact-kernel-build.ts: to
// WebAssembly (contact-kernel-binary.ts) and, from the same optimised module, to JavaScript by
// Binaryen's wasm2js (contact-kernel-javascript.ts). Both run the same IEEE double operations in
// the same order, so they give bit-identical worlds (test/unit/dynamics/contact-kernel.test.ts)
// and a world may switch between them at any step. WebAssembly is preferred: V8 compiles it when
// it loads, so a world's first steps run compiled code instead of waiting for JavaScript to get
// hot, and the passes run without bounds checks or deoptimisation. The JavaScript build runs
// where WebAssembly cannot compile (a Content-Security-Policy without 'wasm-unsafe-eval') and in
// worlds created with `kernel: 'javascript'`. It is not imported here: the package's entry
// `@physical/engine/javascript-kernel` registers it (registerJavaScriptContactKernel), so apps
// that run WebAssembly do not ship it (issue #30, target 5).

/** The parts of the WebAssembly API used here (the engine's types assume only ES2022). */
export interface WasmMemory {
  readonly buffer: ArrayBuffer;
}
/** What an instance of the kernel imports: the memory its pointers point into. */
export interface KernelImports {
  env: { memory: WasmMemory };
}
interface WasmApi {
  Memory: new (descriptor: { initial: number }) => WasmMemory;
  Module: new (bytes: Uint8Array) => object;
  Instance: new (module: object, imports: object) => { readonly exports: object };
}

/** The kernel's exports; pointers are byte offsets into its memory. */
export interface ContactKernel extends BodyPasses, NarrowPhase {
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
  /**
   * prepare's second half, for the `count` classified constraints listed from `order`; the
   * softness, h and dt at `args` (KERNEL_ARGUMENTS, kernel-arguments.ts).
   */
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
    args: number,
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
  /**
   * A solve (useBias 1) or relax (0) pass; returns its bounces. `marks`: the impact marks; the
   * sub-step's numbers at `args` (kernel-arguments.ts).
   */
  solve(
    constraints: number,
    bodies: number,
    order: number,
    states: number,
    count: number,
    args: number,
    marks: number,
    useBias: number,
  ): number;
  /**
   * The `count` circle pairs listed at `pairs` (CIRCLE_PAIRS): normals and levers along their
   * centres as they are now (wasm/circle-pairs.ts).
   */
  refreshCirclePairs(
    constraints: number,
    bodies: number,
    pairs: number,
    count: number,
    states: number,
  ): void;
  /**
   * The heavy-on-light sweep's choice of contacts among the `count` constraints: listed at
   * `sweep` (SHOCK_SWEEP), made rigid and moved to the end of `order`; returns their number
   * (wasm/shock-propagation.ts).
   */
  prepareShockSweep(
    constraints: number,
    bodies: number,
    order: number,
    count: number,
    states: number,
    sweep: number,
    scratch: number,
    bodyCount: number,
    args: number,
  ): number;
  /**
   * The heavy-on-light sweep over the `count` entries at `sweep` (SHOCK_SWEEP), ground up, after
   * the solve (`useBias` 1) or relax (0) pass (wasm/shock-propagation.ts).
   */
  shockSweep(
    constraints: number,
    bodies: number,
    sweep: number,
    count: number,
    states: number,
    marks: number,
    args: number,
    useBias: number,
  ): void;
  /** One pass of the impact rounds in `mode` (IMPACT_ROUND, ...); returns the impacts started. */
  impacts(
    constraints: number,
    bodies: number,
    order: number,
    states: number,
    count: number,
    args: number,
    marks: number,
    mode: number,
  ): number;
}

/**
 * The body passes (wasm/body-passes.ts), built into the same module. `bodies` is the BODIES region,
 * `awake` the step's awake list (AWAKE_BODIES: world index of awake body i, whose state is slot
 * i + 1); with `useList` 1 the passes visit the awake indices of the int32 list at `list`
 * (BATCH_BODIES) from `from` to `to`, else the awake indices from `from` to `to`. `args` is the
 * KERNEL_ARGUMENTS region, where the caller stores the passes' fractional numbers
 * (kernel-arguments.ts: V8 can box each double passed to WebAssembly).
 */
export interface BodyPasses {
  integrateVelocities(
    bodies: number,
    awake: number,
    list: number,
    useList: number,
    from: number,
    to: number,
    states: number,
    marks: number,
    args: number,
  ): void;
  integratePositions(
    bodies: number,
    awake: number,
    list: number,
    useList: number,
    from: number,
    to: number,
    states: number,
    args: number,
  ): void;
  limitSpeeds(
    bodies: number,
    awake: number,
    list: number,
    useList: number,
    from: number,
    to: number,
    states: number,
    args: number,
  ): void;
  /**
   * Velocities, centre, angle, transform and sleep clock of the `count` awake bodies into the body
   * memory; with `continuous` 1, lists the awake indices of the fast bodies (a sweep test due) at
   * `fast` (FAST_BODIES) and returns their number.
   */
  finalizeBodies(
    bodies: number,
    awake: number,
    count: number,
    states: number,
    args: number,
    fast: number,
    continuous: number,
  ): number;
  /**
   * The shapes' boxes of the `count` awake bodies at `awake` but the `fastCount` listed at `fast`
   * (wasm/shape-bounds.ts): each tight box into `boxes` (SHAPE_BOXES), each box grown for a next
   * step of `dt` that left its fat box listed at `escaped` (ESCAPED_SHAPES, shape-escapes.ts);
   * returns how many were listed.
   */
  shapeBounds(
    bodies: number,
    awake: number,
    count: number,
    fast: number,
    fastCount: number,
    boxes: number,
    geometry: number,
    next: number,
    args: number,
    escaped: number,
  ): number;
  /**
   * The same boxes for one body outside a step (wasm/shape-bounds.ts's bodyBounds): the body whose
   * numbers are at double `base` of `bodies` (BODIES), its whole shape chain or only shape `only`
   * (not -1); with `every` 1 each shape is listed at `escaped`, escaped or not. Returns how many
   * were listed.
   */
  bodyBounds(
    bodies: number,
    base: number,
    only: number,
    boxes: number,
    geometry: number,
    next: number,
    args: number,
    escaped: number,
    every: number,
  ): number;
  /**
   * The engine's cosSin (math/trigonometry.ts, compiled into the kernel) of `angle`: cos at byte
   * `out`, sin 8 bytes on. For the tests that compare the kernel's math with TypeScript's.
   */
  cosSin(angle: number, out: number): void;
  /** The engine's hypot (math/hypot.ts, compiled into the kernel). For the same tests. */
  hypot(x: number, y: number): number;
}

/**
 * The narrow phase (wasm/contact-gates.ts, wasm/update-manifold.ts and the wasm/collide-*.ts it
 * calls), built into the same module: the gates over the contact slots and the manifolds of the
 * contacts they leave, from the shapes' geometry rows (SHAPE_GEOMETRY, shape-geometry.ts) at the
 * bodies' poses (BODIES), through the narrow-phase scratch (NARROW_PHASE_SCRATCH,
 * narrow-phase-scratch.ts) into the contacts' slots (CONTACT_DATA).
 */
export interface NarrowPhase {
  /**
   * The narrow phase's gates over contact slots `from` to `count` - 1 (wasm/contact-gates.ts),
   * computing the manifolds they leave to compute; returns the first slot that needs the contact
   * manager (GATE_ACTION of the scratch says why: contact-gates.ts), or `count`. The arguments
   * are the regions CONTACT_DATA, CONTACT_BODIES, CONTACT_SHAPES, CONTACT_KINDS, BODIES,
   * SHAPE_BOXES, SHAPE_GEOMETRY and NARROW_PHASE_SCRATCH.
   */
  collideContacts(
    data: number,
    slotBodies: number,
    slotShapes: number,
    kinds: number,
    bodies: number,
    boxes: number,
    geometry: number,
    scratch: number,
    from: number,
    count: number,
    dt: number,
  ): number;
  /**
   * For tests: the collide function of pair kind `kind` on geometry rows at byte offsets `a` and
   * `b`, at the transforms in the scratch (S_TRANSFORM_A, S_TRANSFORM_B), into the scratch's
   * manifold.
   */
  collidePair(
    kind: number,
    a: number,
    b: number,
    scratch: number,
    speculativeDistance: number,
  ): void;
}

/** Creates the JavaScript build of the kernel over `imports.env.memory` (wasm2js's factory). */
export type JavaScriptKernelFactory = (imports: KernelImports) => ContactKernel;

/** The JavaScript build, once `@physical/engine/javascript-kernel` registered it. */
let javaScriptKernel: JavaScriptKernelFactory | null = null;

/** Makes the JavaScript build available to every world (the javascript-kernel entry calls it). */
export function registerJavaScriptContactKernel(factory: JavaScriptKernelFactory): void {
  javaScriptKernel = factory;
}

/** The fix every missing-build message names. */
export const IMPORT_IT =
  "import '@physical/engine/javascript-kernel' once, before creating the world (the JavaScript build of the contact passes)";

const wasm = (globalThis as { WebAssembly?: WasmApi }).WebAssembly;
/** The compiled module: undefined until first needed, null where WebAssembly is unavailable. */
let compiled: object | null | undefined;

/** The value of a lower-case hex digit's character code. */
function nibble(code: number): number {
  return code < 58 ? code - 48 : code - 87;
}

/**
 * A WebAssembly module compiled from `hex` (its bytes, lower-case hex), or null where WebAssembly
 * cannot compile it (no WebAssembly, a Content-Security-Policy without 'wasm-unsafe-eval', or no
 * SIMD for the contact kernel's lanes). The joints' module (joints/joint-kernel-loader.ts)
 * compiles with it too.
 */
export function compileHex(hex: string): object | null {
  if (wasm === undefined) return null;
  try {
    const bytes = new Uint8Array(hex.length / 2);
    // Character codes, not parseInt(substr): this loop runs once, cold, and parseInt over 17,000
    // two-letter strings took 17-26 ms of a 5,000-box pyramid's first step (CPU time, shared
    // machine); this took 3-9 ms on the same machine.
    for (let i = 0; i < bytes.length; i++) {
      bytes[i] = (nibble(hex.charCodeAt(2 * i)) << 4) | nibble(hex.charCodeAt(2 * i + 1));
    }
    // Synchronous: the module is a few kilobytes, within every browser's main-thread limit.
    return new wasm.Module(bytes);
  } catch {
    // A Content-Security-Policy without 'wasm-unsafe-eval' refuses to compile, and so does a
    // WebAssembly without SIMD (the module solves contacts in f64x2 lanes): the JavaScript build
    // runs instead.
    return null;
  }
}

/** An instance of a compiled module over `memory` (a WebAssembly memory): its exports. */
export function instantiate(module: object, memory: WasmMemory): object {
  // Only called with a module compileHex made, so the API is there.
  return new (wasm as WasmApi).Instance(module, { env: { memory } }).exports;
}

const PAGE = 65536;

/**
 * A memory of at least `bytes` bytes with the kernel bound to it: WebAssembly when `webAssembly`
 * is true and it can run (a WebAssembly memory of whole 64 KiB pages), else the registered
 * JavaScript build over an ordinary ArrayBuffer. `webAssembly` in the result says which. Throws a
 * PhysicalError naming the `kernel` option and the import that fixes it when the JavaScript build
 * is needed and was not registered.
 */
export function createContactKernel(
  bytes: number,
  webAssembly: boolean,
): { memory: WasmMemory; kernel: ContactKernel; webAssembly: boolean } {
  if (webAssembly) {
    if (compiled === undefined) compiled = compileHex(CONTACT_KERNEL_HEX);
    if (compiled !== null && wasm !== undefined) {
      try {
        const memory = new wasm.Memory({ initial: Math.ceil(bytes / PAGE) });
        return {
          memory,
          kernel: instantiate(compiled, memory) as ContactKernel,
          webAssembly: true,
        };
      } catch {
        // Out of address space for another memory: the JavaScript build, if registered.
      }
    }
  }
  if (javaScriptKernel === null) {
    throw new PhysicalError(
      'kernel',
      webAssembly
        ? `is 'auto', but WebAssembly cannot run here (no WebAssembly or no WebAssembly SIMD, a Content-Security-Policy without 'wasm-unsafe-eval', or no address space for another memory): ${IMPORT_IT}.`
        : `is 'javascript', but the JavaScript build is not loaded: ${IMPORT_IT}.`,
    );
  }
  const memory = { buffer: new ArrayBuffer(bytes) };
  return { memory, kernel: javaScriptKernel({ env: { memory } }), webAssembly: false };
}
