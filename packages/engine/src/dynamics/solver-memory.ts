import { BODY_STRIDE, BodyStore } from './body-memory.ts';
import { createContactKernel, type ContactKernel, type WasmMemory } from './contact-kernel.ts';
import { KERNEL_ARGUMENT_DOUBLES } from './kernel-arguments.ts';
import { NARROW_PHASE_SCRATCH_DOUBLES } from './narrow-phase-scratch.ts';
import type { Geometry } from './shape.ts';
import { GEOMETRY_STRIDE, writeGeometryRow } from './shape-geometry.ts';
import {
  FILTER_STRIDE,
  MATERIAL_STRIDE,
  SHAPE_STRIDE,
  ShapeTable,
  type ShapeMemory,
} from './shape-table.ts';
import { SWEEP_STRIDE } from './shock-sweep-layout.ts';
import { ESCAPE_STRIDE } from './shape-escapes.ts';
import type { JointPasses } from './joints/joint-kernel.ts';
import { JOINT_RECORD_STRIDE } from './joints/joint-record.ts';
import { JointStore } from './joints/joint-store.ts';

// The world's hot arrays in one block of memory: the bodies' own numbers (body-memory.ts, the one
// copy the Body handles read and write), the body states and the body table
// (body-state.ts), the contact data with each slot's bodies (contact-data.ts), and the contact
// constraints with their body offsets, visiting order, source slots and circle pairs
// (contact-solver.ts), and the step's awake list (world indices) and a batch's body list, which the
// kernel's body passes visit, and the bodies finalize found fast. The contact kernel (contact-kernel.ts) reads them at the regions' byte
// offsets, the rest of the solver through typed-array views. A world's memory is a WebAssembly
// memory from its start (the JavaScript build of the kernel is an optional entry, and small worlds
// lose nothing: see the engine README's WebAssembly section), or an ordinary ArrayBuffer run by
// the JavaScript build with `kernel: 'javascript'` and where WebAssembly cannot compile.
//
// Regions, in this order, each growing by doubling (contents kept), each 8-byte aligned.

/** Solver body states: doubles. */
export const STATES = 0;
/** Constraint numbers: doubles. */
export const CONSTRAINT_DATA = 1;
/** Body state offsets of each constraint: 2 int32. */
export const CONSTRAINT_BODIES = 2;
/** Visiting order of the sub-step passes: int32. */
export const CONSTRAINT_ORDER = 3;
/** The contact slot each constraint came from: int32. */
export const CONSTRAINT_SLOTS = 4;
/** Constraints between two centred circles: int32. */
export const CIRCLE_PAIRS = 5;
/** Contact slots: doubles. */
export const CONTACT_DATA = 6;
/** World indices of each contact slot's bodies: 2 int32. */
export const CONTACT_BODIES = 7;
/** The body table: doubles. */
export const BODY_TABLE = 8;
/** Every body's numbers, by world index (body-memory.ts): doubles. */
export const BODIES = 9;
/** The step's awake bodies' world indices, by awake index (state slot minus one): int32. */
export const AWAKE_BODIES = 10;
/** A batch of islands' awake indices (solver-batches.ts), for the body passes: int32. */
export const BATCH_BODIES = 11;
/** The shapes' boxes, by shape id (shape-table.ts): doubles. */
export const SHAPE_BOXES = 12;
/** The shapes' filters (shape-table.ts): int32. */
export const SHAPE_FILTERS = 13;
/** The shapes' materials (shape-table.ts): doubles. */
export const SHAPE_MATERIALS = 14;
/** The shapes' geometry rows (shape-geometry.ts), which the kernel's narrow phase reads: doubles. */
export const SHAPE_GEOMETRY = 15;
/** The kernel's narrow phase's manifold and scratch (narrow-phase-scratch.ts): doubles, fixed. */
export const NARROW_PHASE_SCRATCH = 16;
/** Shape ids of each contact slot's shapes A and B: 2 int32. */
export const CONTACT_SHAPES = 17;
/** Each contact slot's pair kind (pair-kinds.ts): int32. */
export const CONTACT_KINDS = 18;
/** The awake indices of the bodies finalize found fast (continuous collision): int32. */
export const FAST_BODIES = 19;
/** The heavy-on-light sweep's list (shock-sweep-layout.ts), room for every constraint: doubles. */
export const SHOCK_SWEEP = 20;
/** The heavy-on-light sweep's scratch while it chooses (wasm/shock-propagation.ts): int32. */
export const SHOCK_SCRATCH = 21;
/** Every joint's record in the world (joints/joint-store.ts), JOINT_RECORD_STRIDE each: doubles. */
export const JOINT_RECORDS = 22;
/** The step's active joints, grouped by kind: record offset, state A, state B (3 int32 each). */
export const JOINT_ACTIVE = 23;
/** Each shape's next shape of the same body, id plus one, 0: none (body-memory.ts): int32. */
export const SHAPE_NEXT = 24;
/** The shapes whose box left its fat box in finalize (shape-escapes.ts): doubles, one row a shape. */
export const ESCAPED_SHAPES = 25;
/** The kernel's fractional arguments (kernel-arguments.ts), fixed size: doubles. */
export const KERNEL_ARGUMENTS = 26;
const REGIONS = 27;
/** Bytes per element of each region. */
const ELEMENT_BYTES = [
  8, 8, 4, 4, 4, 4, 8, 4, 8, 8, 4, 4, 8, 4, 8, 8, 8, 4, 4, 4, 8, 4, 8, 4, 4, 8, 8,
];
/** The shape regions of that many rows. */
const SHAPE_REGIONS: readonly (readonly [number, number])[] = [
  [SHAPE_BOXES, SHAPE_STRIDE],
  [SHAPE_FILTERS, FILTER_STRIDE],
  [SHAPE_MATERIALS, MATERIAL_STRIDE],
  [SHAPE_GEOMETRY, GEOMETRY_STRIDE],
  [SHAPE_NEXT, 1],
  [ESCAPED_SHAPES, ESCAPE_STRIDE],
];

/**
 * @internal When worlds move to the WebAssembly kernel: at this many contacts in a step (0, the
 * default: from their start; `Infinity`: never). Tests set it to compare both kernels.
 */
export const kernelSettings = { minConstraints: 0 };

export class SolverMemory implements ShapeMemory {
  /** Views of the regions; a later reserve of any region replaces them all. */
  states: Float64Array = new Float64Array(0);
  constraintData: Float64Array = new Float64Array(0);
  constraintBodies: Int32Array = new Int32Array(0);
  constraintOrder: Int32Array = new Int32Array(0);
  constraintSlots: Int32Array = new Int32Array(0);
  circlePairs: Int32Array = new Int32Array(0);
  contactData: Float64Array = new Float64Array(0);
  contactBodies: Int32Array = new Int32Array(0);
  /** Each contact slot's shape ids (CONTACT_SHAPES) and pair kind (CONTACT_KINDS). */
  contactShapes: Int32Array = new Int32Array(0);
  contactKinds: Int32Array = new Int32Array(0);
  bodyTable: Float64Array = new Float64Array(0);
  /** The step's awake bodies' world indices (AWAKE_BODIES). */
  awakeBodies: Int32Array = new Int32Array(0);
  /** A batch's awake indices for the body passes (BATCH_BODIES). */
  batchBodies: Int32Array = new Int32Array(0);
  /** The kernel's narrow-phase manifold and scratch (NARROW_PHASE_SCRATCH). */
  narrowPhase: Float64Array = new Float64Array(0);
  /** The awake indices of the last finalize's fast bodies (FAST_BODIES). */
  fastBodies: Int32Array = new Int32Array(0);
  /** Each shape's next shape of its body (SHAPE_NEXT). */
  shapeNext: Int32Array = new Int32Array(0);
  /** The shapes finalize found out of their fat boxes (ESCAPED_SHAPES). */
  escapedShapes: Float64Array = new Float64Array(0);
  /**
   * The kernel's fractional arguments (KERNEL_ARGUMENTS, kernel-arguments.ts), stored here before
   * a call: V8 can box each double passed to WebAssembly.
   */
  kernelArguments: Float64Array = new Float64Array(0);
  /** The heavy-on-light sweep's list (SHOCK_SWEEP). */
  shockSweep: Float64Array = new Float64Array(0);
  /**
   * The bodies' numbers (body-memory.ts): the store every Body handle of the world reads through.
   * Its `data` is this memory's BODIES region, replaced (with every other view) when it moves.
   */
  readonly bodyStore: BodyStore = new BodyStore(new Float64Array(0));
  /**
   * The shapes' boxes, filters, materials and geometry (shape-table.ts), by shape id: the world's
   * shape table, whose arrays are this memory's shape regions, replaced (with every other view)
   * when it moves. It grows through {@link reserveShapes}.
   */
  readonly shapeTable: ShapeTable = new ShapeTable(0, this);
  /**
   * Every joint's record (joints/joint-store.ts), all kinds at one stride: the store every Joint
   * handle of the world reads through. Its `data` is the JOINT_RECORDS region, replaced with the
   * other views when the memory moves; it grows through this memory.
   */
  readonly jointStore: JointStore = new JointStore(JOINT_RECORD_STRIDE, 0, false, (doubles) =>
    this.reserve(JOINT_RECORDS, doubles),
  );
  /** The step's active joints (JOINT_ACTIVE): record offset, state A, state B per joint. */
  jointActive: Int32Array = new Int32Array(0);
  /** Byte offset of each region, for the kernel. */
  readonly offsets: number[] = new Array<number>(REGIONS).fill(0);
  /** The contact passes over this memory: WebAssembly once it has moved there, else JavaScript. */
  kernel!: ContactKernel;
  /**
   * The joints' passes over this memory (a module of their own, joints/joint-kernel.ts), in the
   * kernel's build; set by {@link loadJoints} before the first joint is solved.
   */
  joints!: JointPasses;
  /** What loads the joints' passes over a memory, once a joint was solved here (else null). */
  private jointLoader: ((memory: WasmMemory, webAssembly: boolean) => JointPasses) | null = null;
  private wasm: WasmMemory | null = null;
  /** Set when WebAssembly could not be had or is not wanted: stay on the ArrayBuffer, do not ask. */
  private wasmRefused = false;
  /** Elements each region holds. */
  private readonly capacities: number[] = new Array<number>(REGIONS).fill(0);
  private buffer: ArrayBuffer = new ArrayBuffer(0);

  /** Holds nothing until {@link start}, which the world calls once it knows its `kernel`. */
  constructor(
    private readonly constraintStride: number,
    private readonly contactStride: number,
    private readonly tableStride: number,
  ) {}

  /**
   * Lays out the first block: a WebAssembly memory (compiling the module once per process, so a
   * world's first big step does not wait for it), or with `javaScriptOnly` (World's
   * `kernel: 'javascript'`) an ArrayBuffer run by the JavaScript build, with no attempt to
   * compile WebAssembly from then on. Throws the PhysicalError of createContactKernel when the
   * JavaScript build is needed and not registered.
   */
  start(javaScriptOnly: boolean): void {
    this.wasmRefused = javaScriptOnly;
    this.layout(this.initialCapacities(), this.wantsKernel(0));
  }

  private initialCapacities(): number[] {
    const initial = [64 * 8, 256 * this.constraintStride, 512, 256, 256, 256];
    const capacities = initial.concat([
      256 * this.contactStride,
      512,
      64 * this.tableStride,
      64 * BODY_STRIDE,
      64,
      64,
      // SHAPE_BOXES to SHAPE_GEOMETRY (the shape regions after them are at the end).
      ...SHAPE_REGIONS.slice(0, 4).map(([, stride]) => 64 * stride),
      NARROW_PHASE_SCRATCH_DOUBLES,
      512,
      256,
      64, // FAST_BODIES
      256 * SWEEP_STRIDE, // SHOCK_SWEEP
      0, // SHOCK_SCRATCH, sized below
      16 * JOINT_RECORD_STRIDE,
      48,
      64, // SHAPE_NEXT
      64 * ESCAPE_STRIDE, // ESCAPED_SHAPES
      KERNEL_ARGUMENT_DOUBLES,
    ]);
    this.sizeShockScratch(capacities);
    return capacities;
  }

  /** Writes shape `row`'s geometry row (SHAPE_GEOMETRY), when the shape joins the world. */
  writeGeometry(row: number, geometry: Geometry): void {
    writeGeometryRow(this.shapeTable.geometry, row, geometry);
  }

  /**
   * Makes room for `rows` shapes' rows (shape-table.ts), keeping them; replaces every view when
   * it grows (never inside a step: shapes join between steps).
   */
  reserveShapes(rows: number): void {
    if (rows * SHAPE_STRIDE <= this.capacities[SHAPE_BOXES]!) return;
    const wanted = this.capacities.slice();
    for (const [region, stride] of SHAPE_REGIONS)
      wanted[region] = grown(wanted[region]!, rows * stride);
    this.layout(wanted, this.wasm !== null);
  }

  /**
   * Shrinks back to the first sizes, keeping room for (and the numbers of) `bodies` bodies and
   * `contacts` contact slots: for a world that lost most of its bodies. A WebAssembly memory
   * cannot shrink: the numbers move into a new, smaller one.
   */
  shrink(bodies: number, contacts: number): void {
    const wanted = this.initialCapacities();
    this.sizeContacts(wanted, contacts);
    wanted[BODIES] = grown(wanted[BODIES]!, bodies * BODY_STRIDE);
    wanted[AWAKE_BODIES] = grown(wanted[AWAKE_BODIES]!, bodies);
    wanted[BATCH_BODIES] = grown(wanted[BATCH_BODIES]!, bodies);
    // The shapes keep their rows (the world keeps its shape ids).
    for (const [region] of SHAPE_REGIONS) wanted[region] = this.capacities[region]!;
    wanted[FAST_BODIES] = grown(wanted[FAST_BODIES]!, bodies);
    this.sizeShockScratch(wanted);
    wanted[JOINT_RECORDS] = grown(
      wanted[JOINT_RECORDS]!,
      this.jointStore.count * JOINT_RECORD_STRIDE,
    );
    const total = wanted.reduce((sum, c, r) => sum + c * ELEMENT_BYTES[r]!, 0);
    if (total >= this.buffer.byteLength / 2) return; // not worth a move
    this.wasm = null;
    this.layout(wanted, this.wantsKernel(contacts));
  }

  /**
   * Loads the joints' passes over this memory with `loader` (joints/joint-kernel-loader.ts, which
   * only the joints' batches import, so apps without joints do not ship the module), and over
   * every memory after it. Called when a world first solves a joint; nothing once loaded.
   */
  loadJoints(loader: (memory: WasmMemory, webAssembly: boolean) => JointPasses): void {
    if (this.jointLoader !== null) return;
    this.jointLoader = loader;
    this.joints = loader(this.wasm ?? { buffer: this.buffer }, this.wasm !== null);
  }

  /** Whether the passes run as WebAssembly now (else the kernel's JavaScript build). */
  get usesWebAssembly(): boolean {
    return this.wasm !== null;
  }

  /** Makes room for `doubles` state numbers; returns the states' view. */
  reserveStates(doubles: number): Float64Array {
    this.reserve(STATES, doubles);
    return this.states;
  }

  /** Makes room for `count` contact slots, keeping their contents. */
  reserveContacts(count: number): void {
    if (count * this.contactStride <= this.capacities[CONTACT_DATA]!) return;
    const wanted = this.capacities.slice();
    this.sizeContacts(wanted, count);
    this.layout(wanted, this.wasm !== null);
  }

  /**
   * Makes room for `count` bodies' numbers (body-memory.ts), keeping them; replaces every view
   * when it grows (never inside a step: bodies join between steps).
   */
  reserveBodies(count: number): void {
    this.reserve(BODIES, count * BODY_STRIDE);
  }

  /**
   * Makes room for `records` joints' records (kept) and `active` active joints; replaces every
   * view when it grows (at a step's start, before the joints are prepared).
   */
  reserveJoints(records: number, active: number): void {
    const have = this.capacities;
    if (records * JOINT_RECORD_STRIDE <= have[JOINT_RECORDS]! && 3 * active <= have[JOINT_ACTIVE]!)
      return;
    const wanted = have.slice();
    wanted[JOINT_RECORDS] = grown(have[JOINT_RECORDS]!, records * JOINT_RECORD_STRIDE);
    wanted[JOINT_ACTIVE] = grown(have[JOINT_ACTIVE]!, 3 * active);
    this.layout(wanted, this.wasm !== null);
  }

  /**
   * Makes room for `count` bodies in the body table and the awake lists (reserveStep made it
   * already, unless bodies joined since).
   */
  reserveBodyTable(count: number): Float64Array {
    const have = this.capacities;
    if (
      count * this.tableStride > have[BODY_TABLE]! ||
      count > have[AWAKE_BODIES]! ||
      count > have[BATCH_BODIES]! ||
      count > have[FAST_BODIES]!
    ) {
      const wanted = have.slice();
      this.sizeBodies(wanted, count);
      this.layout(wanted, this.wasm !== null);
    }
    return this.bodyTable;
  }

  /** Makes room for `count` int32 of the heavy-on-light sweep's scratch (SHOCK_SCRATCH). */
  reserveShockScratch(count: number): void {
    this.reserve(SHOCK_SCRATCH, count);
  }

  /** Makes room for `count` constraints; moves to the WebAssembly kernel at the tests' threshold. */
  reserveConstraints(count: number): void {
    const toWasm = this.wantsKernel(count);
    if (count <= this.capacities[CONSTRAINT_ORDER]! && toWasm === (this.wasm !== null)) return;
    const wanted = this.capacities.slice();
    this.sizeConstraints(wanted, count);
    this.layout(wanted, toWasm);
  }

  /**
   * Makes room at once for a step of `bodies` bodies (`stateDoubles` state numbers) and
   * `contacts` contacts, constraints included, moving to the WebAssembly kernel if the step will
   * (as reserveConstraints would). Reserving region by region moved the whole block once per
   * region on a big world's first step (four moves of up to 15 MB for a 5,000-box pyramid).
   *
   * Called at the step's start, before anything of the step is written: a move carries only the
   * `bodies` bodies' numbers and the first `liveContacts` contact slots. The per-step regions
   * (states, body table, constraints) are rebuilt by the step before they are read, so they are
   * not copied, and nor are the rooms past the live bodies and slots: every byte copied lands on
   * a fresh page of the new block, and a fresh page costs a fault (~18 us each on the project's
   * machines; large_pyramid's first step copied 8,192 bodies' room for 5,050 bodies). A world
   * whose bodies and shapes joined through {@link reserveForeseen} does not move here in its
   * first step unless it makes more contacts than foreseen.
   */
  reserveStep(stateDoubles: number, bodies: number, contacts: number, liveContacts: number): void {
    const have = this.capacities;
    const toWasm = this.wantsKernel(contacts);
    // Nothing to do in a step like the last one: checked before anything is allocated.
    if (this.holdsStep(stateDoubles, bodies, contacts) && toWasm === (this.wasm !== null)) return;
    const wanted = have.slice();
    this.sizeStep(wanted, stateDoubles, bodies, contacts);
    const keep = new Array<number>(REGIONS).fill(0);
    keep[CONTACT_DATA] = liveContacts * this.contactStride;
    keep[CONTACT_BODIES] = 2 * liveContacts;
    keep[CONTACT_SHAPES] = 2 * liveContacts;
    keep[CONTACT_KINDS] = liveContacts;
    keep[BODIES] = bodies * BODY_STRIDE;
    for (const [region] of SHAPE_REGIONS) keep[region] = have[region]!;
    keep[JOINT_RECORDS] = this.jointStore.count * JOINT_RECORD_STRIDE;
    this.layout(wanted, toWasm, keep);
  }

  /**
   * Makes room, while bodies and shapes join a world, for the step the world can foresee: `bodies`
   * bodies (`stateDoubles` state numbers), `shapes` shapes' rows, and `contacts` contacts and as
   * many constraints (the contact manager's rule, `foreseenContacts`: a few per shape), in one
   * move of the block, and touches every page of the new block that such a step writes. Then the
   * first step neither moves the block (reserveStep finds the room made) nor takes a page fault
   * on each fresh page it writes (large_pyramid's first step took ~6,300 faults: ~2,000 moving
   * the block, ~1,900 making its 15,000 contact slots, ~1,900 preparing their constraints).
   * The world calls it each time its shapes outgrow the last room, grown by half
   * (WorldMembership.foresee), so the block moves O(log n) times while a world is built and
   * every region grows in the same move.
   */
  reserveForeseen(stateDoubles: number, bodies: number, shapes: number, contacts: number): void {
    const have = this.capacities;
    if (
      this.holdsStep(stateDoubles, bodies, contacts) &&
      bodies * BODY_STRIDE <= have[BODIES]! &&
      shapes * SHAPE_STRIDE <= have[SHAPE_BOXES]!
    ) {
      return;
    }
    // Exactly the room asked for (the caller doubles it as the world grows), not rounded up to
    // a power of two on top: every byte of it is touched.
    const wanted = have.slice();
    this.sizeStep(wanted, stateDoubles, bodies, contacts, atLeast);
    wanted[BODIES] = atLeast(wanted[BODIES]!, bodies * BODY_STRIDE);
    for (const [region, stride] of SHAPE_REGIONS)
      wanted[region] = atLeast(wanted[region]!, shapes * stride);
    this.layout(wanted, this.wasm !== null, undefined, true);
  }

  /** Whether the block holds a step of `bodies` bodies and `contacts` contacts as it is. */
  private holdsStep(stateDoubles: number, bodies: number, contacts: number): boolean {
    const have = this.capacities;
    return (
      stateDoubles <= have[STATES]! &&
      bodies * this.tableStride <= have[BODY_TABLE]! &&
      bodies <= have[AWAKE_BODIES]! &&
      bodies <= have[BATCH_BODIES]! &&
      bodies <= have[FAST_BODIES]! &&
      contacts * this.contactStride <= have[CONTACT_DATA]! &&
      contacts <= have[CONSTRAINT_ORDER]!
    );
  }

  /** Grows `wanted`'s regions for a step of `bodies` bodies and `contacts` contacts. */
  private sizeStep(
    wanted: number[],
    stateDoubles: number,
    bodies: number,
    contacts: number,
    size: Sizing = grown,
  ): void {
    wanted[STATES] = size(wanted[STATES]!, stateDoubles);
    this.sizeBodies(wanted, bodies, size);
    this.sizeContacts(wanted, contacts, size);
    this.sizeConstraints(wanted, contacts, size);
  }

  /** Whether a step of `count` contacts runs on the WebAssembly kernel (once moved, it stays). */
  private wantsKernel(count: number): boolean {
    return this.wasm !== null || (!this.wasmRefused && count >= kernelSettings.minConstraints);
  }

  /** Grows `wanted`'s body table and awake lists to hold `count` bodies (no smaller than they are). */
  private sizeBodies(wanted: number[], count: number, size: Sizing = grown): void {
    wanted[BODY_TABLE] = size(wanted[BODY_TABLE]!, count * this.tableStride);
    wanted[AWAKE_BODIES] = size(wanted[AWAKE_BODIES]!, count);
    wanted[BATCH_BODIES] = size(wanted[BATCH_BODIES]!, count);
    wanted[FAST_BODIES] = size(wanted[FAST_BODIES]!, count);
    this.sizeShockScratch(wanted);
  }

  /** Grows `wanted`'s contact regions to hold `count` slots (no smaller than they are). */
  private sizeContacts(wanted: number[], count: number, size: Sizing = grown): void {
    const slots = size(wanted[CONTACT_DATA]! / this.contactStride, count);
    wanted[CONTACT_DATA] = slots * this.contactStride;
    wanted[CONTACT_BODIES] = 2 * slots;
    wanted[CONTACT_SHAPES] = 2 * slots;
    wanted[CONTACT_KINDS] = slots;
  }

  /** Grows `wanted`'s constraint regions to hold `count` constraints (no smaller than they are). */
  private sizeConstraints(wanted: number[], count: number, size: Sizing = grown): void {
    const n = size(wanted[CONSTRAINT_ORDER]!, count);
    wanted[CONSTRAINT_DATA] = n * this.constraintStride;
    wanted[CONSTRAINT_BODIES] = 2 * n;
    wanted[CONSTRAINT_ORDER] = n;
    wanted[CONSTRAINT_SLOTS] = n;
    wanted[CIRCLE_PAIRS] = n;
    wanted[SHOCK_SWEEP] = n * SWEEP_STRIDE;
    this.sizeShockScratch(wanted);
  }

  /**
   * Grows `wanted`'s SHOCK_SCRATCH with the constraints and bodies it is sized for (5 int32 per
   * constraint, 2 per solver slot), so it never moves the memory on its own.
   */
  private sizeShockScratch(wanted: number[]): void {
    const needed = 5 * wanted[CONSTRAINT_ORDER]! + 2 * (wanted[AWAKE_BODIES]! + 1);
    wanted[SHOCK_SCRATCH] = grown(wanted[SHOCK_SCRATCH]!, needed);
  }

  private reserve(region: number, elements: number): void {
    if (elements <= this.capacities[region]!) return;
    const wanted = this.capacities.slice();
    wanted[region] = grown(wanted[region]!, elements);
    this.layout(wanted, this.wasm !== null);
  }

  /**
   * Lays the regions out at `capacities` (elements each), carrying the first `keep[r]` elements of
   * each region over (default: all that fits).
   */
  private layout(
    capacities: number[],
    toWasm: boolean,
    keep?: readonly number[],
    touch = false,
  ): void {
    const to: number[] = [];
    let total = 0;
    for (let r = 0; r < REGIONS; r++) {
      to.push(total);
      total += Math.ceil((capacities[r]! * ELEMENT_BYTES[r]!) / 8) * 8;
    }
    const oldBuffer = this.buffer;
    let buffer: ArrayBuffer;
    if (this.wasm !== null && toWasm && this.wasm.buffer.byteLength >= total) {
      buffer = this.wasm.buffer;
    } else {
      // A new memory rather than memory.grow: growing detaches the old buffer, and the first
      // detached ArrayBuffer of a process makes V8 check for detachment at every typed-array
      // access of all optimised code from then on (measured: tumbler ~10 % slower).
      const created = createContactKernel(total, toWasm);
      if (toWasm && !created.webAssembly) this.wasmRefused = true;
      this.wasm = created.webAssembly ? created.memory : null;
      this.kernel = created.kernel;
      if (this.jointLoader !== null) {
        this.joints = this.jointLoader(created.memory, created.webAssembly);
      }
      buffer = created.memory.buffer;
    }
    const bytes = new Uint8Array(buffer);
    const from = this.offsets;
    // A region keeps what fits (all of it when growing; the live part when shrinking), or what
    // the caller says is live.
    const sizes = this.capacities.map(
      (c, r) => Math.min(c, capacities[r]!, keep === undefined ? c : keep[r]!) * ELEMENT_BYTES[r]!,
    );
    if (buffer === oldBuffer) {
      // The same memory, big enough: regions only move up, so move the last first, so none
      // overwrites one not yet moved.
      for (let r = REGIONS - 1; r >= 0; r--)
        bytes.copyWithin(to[r]!, from[r]!, from[r]! + sizes[r]!);
    } else {
      for (let r = 0; r < REGIONS; r++) {
        bytes.set(new Uint8Array(oldBuffer, from[r]!, sizes[r]!), to[r]!);
      }
      // A fresh block is zeros that the system maps page by page at the first write: a zero
      // written on each page past what was copied maps them now, the contents unchanged. The
      // heavy-on-light sweep's regions are left to the steps that use them.
      if (touch) {
        for (let r = 0; r < REGIONS; r++) {
          if (r === SHOCK_SWEEP || r === SHOCK_SCRATCH) continue;
          const end = to[r]! + capacities[r]! * ELEMENT_BYTES[r]!;
          for (let p = to[r]! + sizes[r]!; p < end; p = (p | (PAGE_BYTES - 1)) + 1) bytes[p] = 0;
        }
      }
    }
    for (let r = 0; r < REGIONS; r++) {
      this.offsets[r] = to[r]!;
      this.capacities[r] = capacities[r]!;
    }
    this.buffer = buffer;
    const f64 = (r: number): Float64Array => new Float64Array(buffer, to[r]!, capacities[r]!);
    const i32 = (r: number): Int32Array => new Int32Array(buffer, to[r]!, capacities[r]!);
    this.states = f64(STATES);
    this.constraintData = f64(CONSTRAINT_DATA);
    this.constraintBodies = i32(CONSTRAINT_BODIES);
    this.constraintOrder = i32(CONSTRAINT_ORDER);
    this.constraintSlots = i32(CONSTRAINT_SLOTS);
    this.circlePairs = i32(CIRCLE_PAIRS);
    this.contactData = f64(CONTACT_DATA);
    this.contactBodies = i32(CONTACT_BODIES);
    this.bodyTable = f64(BODY_TABLE);
    this.bodyStore.data = f64(BODIES);
    this.awakeBodies = i32(AWAKE_BODIES);
    this.batchBodies = i32(BATCH_BODIES);
    this.narrowPhase = f64(NARROW_PHASE_SCRATCH);
    this.contactShapes = i32(CONTACT_SHAPES);
    this.contactKinds = i32(CONTACT_KINDS);
    const shapes = this.shapeTable;
    shapes.data = f64(SHAPE_BOXES);
    shapes.filters = i32(SHAPE_FILTERS);
    shapes.materials = f64(SHAPE_MATERIALS);
    shapes.geometry = f64(SHAPE_GEOMETRY);
    this.fastBodies = i32(FAST_BODIES);
    this.shockSweep = f64(SHOCK_SWEEP);
    this.jointStore.data = f64(JOINT_RECORDS);
    this.jointActive = i32(JOINT_ACTIVE);
    this.shapeNext = i32(SHAPE_NEXT);
    this.escapedShapes = f64(ESCAPED_SHAPES);
    this.kernelArguments = f64(KERNEL_ARGUMENTS);
  }
}

/** The pages the system maps memory by (4 KiB on the platforms the engine runs on). */
const PAGE_BYTES = 4096;

/** A region's new capacity from its capacity and the elements needed. */
type Sizing = (capacity: number, needed: number) => number;

/** No smaller than `capacity`, nor than `needed`. */
function atLeast(capacity: number, needed: number): number {
  return Math.max(capacity, needed);
}

function grown(capacity: number, needed: number): number {
  let size = Math.max(capacity, 1);
  while (size < needed) size *= 2;
  return size;
}
