// Builds the kernel, the contact passes (wasm/contact-kernel.ts) and the body passes
// (wasm/body-passes.ts, exported by contact-kernel.ts), from their one source (AssemblyScript),
// with the engine's own math compiled in as it is (src/math/trigonometry.ts and hypot.ts):
//
// 1. wasm/contact-layout.ts: the layout constants the kernel reads, generated from the engine's
//    own definitions (contact-constraint-layout.ts, contact-data.ts, body-state.ts,
//    body-memory.ts, shape-geometry.ts, shock-sweep-layout.ts, LINEAR_SLOP and SLEEP_SPEED), so
//    no number is copied by hand.
// 2. src/dynamics/contact-kernel-binary.ts: the optimised WebAssembly module, hex-encoded, so the
//    engine ships it with no dependency and no separate file to fetch.
// 3. src/dynamics/contact-kernel-javascript.ts: the same optimised module turned into JavaScript
//    by Binaryen's wasm2js, for hosts where WebAssembly cannot compile (a Content-Security-Policy
//    without 'wasm-unsafe-eval') and for worlds created with `kernel: 'javascript'`. wasm2js
//    keeps every f64 operation as the same IEEE double operation in the same order, so both
//    builds give bit-identical worlds (test/unit/dynamics/contact-kernel.test.ts checks every
//    sample).
// 4. src/dynamics/joints/joint-kernel-binary.ts and joint-kernel-javascript.ts: the joints' passes
//    (wasm/joint-passes.ts) as a second module of their own over the same imported memory and the
//    same layout, in both builds. Only the joints' code references them, so an app that imports
//    no joint class ships neither (issue #30, target 5); a world instantiates it when it first
//    solves a joint (joints/joint-kernel-loader.ts).
//
// `npm run build:kernel -w @physical/engine` writes all five; the test
// `contact-kernel-artefacts-are-current` builds them again and fails if a committed file differs.
import asc from 'assemblyscript/asc';
import binaryen from 'binaryen';
import { readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import * as prettier from 'prettier';
import * as bodyMemory from '../src/dynamics/body-memory.ts';
import * as bodyState from '../src/dynamics/body-state.ts';
import * as constraintLayout from '../src/dynamics/contact-constraint-layout.ts';
import * as contactData from '../src/dynamics/contact-data.ts';
import * as shapeGeometry from '../src/dynamics/shape-geometry.ts';
import * as narrowPhaseScratch from '../src/dynamics/narrow-phase-scratch.ts';
import * as kernelArguments from '../src/dynamics/kernel-arguments.ts';
import * as pairKinds from '../src/dynamics/pair-kinds.ts';
import * as contactGates from '../src/dynamics/contact-gates.ts';
import { SHAPE_STRIDE } from '../src/dynamics/shape-table.ts';
import * as shockSweep from '../src/dynamics/shock-sweep-layout.ts';
import * as shapeEscapes from '../src/dynamics/shape-escapes.ts';
import {
  AABB_MARGIN,
  LINEAR_SLOP,
  SLEEP_SPEED,
  SPECULATIVE_DISTANCE,
} from '../src/core/constants.ts';
import * as jointRecord from '../src/dynamics/joints/joint-record.ts';
import * as jointPassCodes from '../src/dynamics/joints/joint-pass-codes.ts';
import * as springMotorLimit from '../src/dynamics/joints/spring-motor-limit.ts';
import * as distanceLayout from '../src/dynamics/joints/distance-joint-layout.ts';
import * as mouseLayout from '../src/dynamics/joints/mouse-joint-layout.ts';
import * as prismaticLayout from '../src/dynamics/joints/prismatic-joint-solver.ts';
import * as revoluteLayout from '../src/dynamics/joints/revolute-joint-solver.ts';
import * as weldLayout from '../src/dynamics/joints/weld-joint-layout.ts';

const root = new URL('..', import.meta.url);
const file = (path: string): string => fileURLToPath(new URL(path, root));
export const KERNEL_SOURCE = file('wasm/contact-kernel.ts');
export const KERNEL_LAYOUT = file('wasm/contact-layout.ts');
export const KERNEL_BODY_PASSES = file('wasm/body-passes.ts');
export const KERNEL_LOAD_STORE = file('wasm/load-store.ts');
export const KERNEL_LANES = file('wasm/contact-lanes.ts');
/** The narrow phase's sources (wasm/update-manifold.ts, exported by contact-kernel.ts). */
export const KERNEL_NARROW_PHASE = [
  'contact-gates.ts',
  'update-manifold.ts',
  'manifold.ts',
  'one-point-manifold.ts',
  'closest-segment-fractions.ts',
  'collide-circles.ts',
  'collide-polygon-circle.ts',
  'collide-polygons.ts',
  'collide-segment-circle.ts',
  'collide-segment-polygon.ts',
  'collide-capsule-circle.ts',
  'collide-capsules.ts',
  'collide-polygon-capsule.ts',
  'collide-segment-capsule.ts',
];
export const KERNEL_DOUBLES_AT = file('wasm/doubles-at.ts');
export const KERNEL_MATH = file('wasm/kernel-math.ts');
export const KERNEL_CONSTRAINT_ACCESS = file('wasm/constraint-access.ts');
export const KERNEL_CIRCLE_PAIRS = file('wasm/circle-pairs.ts');
export const KERNEL_SHOCK_PROPAGATION = file('wasm/shock-propagation.ts');
/** The engine's own math, compiled into the kernel as it is (one source for both). */
export const ENGINE_TRIGONOMETRY = file('src/math/trigonometry.ts');
export const ENGINE_HYPOT = file('src/math/hypot.ts');
export const KERNEL_JOINT_PASSES = file('wasm/joint-passes.ts');
export const KERNEL_SHAPE_BOUNDS = file('wasm/shape-bounds.ts');
export const KERNEL_BINARY_MODULE = file('src/dynamics/contact-kernel-binary.ts');
export const KERNEL_JAVASCRIPT_MODULE = file('src/dynamics/contact-kernel-javascript.ts');
export const JOINT_KERNEL_BINARY_MODULE = file('src/dynamics/joints/joint-kernel-binary.ts');
export const JOINT_KERNEL_JAVASCRIPT_MODULE = file(
  'src/dynamics/joints/joint-kernel-javascript.ts',
);

/** Constants the kernel computes with as doubles; every other one is an i32 offset or count. */
const DOUBLES = new Set([
  'AABB_MARGIN',
  'LINEAR_SLOP',
  'SLEEP_SPEED',
  'SPECULATIVE_DISTANCE',
  'KEEP_GAP',
  'REUSE_TOLERANCE_SQUARED',
  'PRESSED_AFTER_BOUNCING_STEPS',
  'MAX_CONDITION_NUMBER',
  'SWEEP_SLIP',
  'J_DISTANCE_LENGTH_EPSILON',
]);

/** The numbers a module exports, by name (a module namespace lists its names sorted anyway). */
function numbers(module: Record<string, unknown>): [string, number][] {
  return Object.entries(module)
    .filter((e): e is [string, number] => typeof e[1] === 'number')
    .sort((a, b) => (a[0] < b[0] ? -1 : a[0] > b[0] ? 1 : 0));
}

/** A module's numbers with `prefix` before each name. */
function prefixed(prefix: string, module: Record<string, unknown>): [string, number][] {
  return numbers(module).map(([name, value]): [string, number] => [prefix + name, value]);
}

/** wasm/contact-layout.ts: every layout constant, named as the kernel reads it. */
export function kernelLayout(): string {
  const entries: [string, number][] = [
    ...numbers(constraintLayout),
    // Contact slots share names with constraints (NORMAL_X, ...): prefixed C_, points' P_ dropped.
    ...numbers(contactData).map(([name, value]): [string, number] => [
      name === 'CONTACT_STRIDE' ? name : `C_${name.replace(/^P_/, '')}`,
      value,
    ]),
    ...numbers(bodyState),
    ...numbers(bodyMemory),
    ...numbers(shapeGeometry),
    ...numbers(narrowPhaseScratch),
    ...numbers(kernelArguments),
    ...numbers(pairKinds),
    ...numbers(contactGates),
    ['SHAPE_STRIDE', SHAPE_STRIDE],
    ...numbers(shockSweep),
    ...numbers(shapeEscapes),
    ['AABB_MARGIN', AABB_MARGIN],
    ['LINEAR_SLOP', LINEAR_SLOP],
    ['SLEEP_SPEED', SLEEP_SPEED],
    ['SPECULATIVE_DISTANCE', SPECULATIVE_DISTANCE],
    // Joints' records (several kinds name a STRIDE, ...): the head and the spring, motor and
    // limit block prefixed J_, each kind's own numbers J_<KIND>_.
    ...prefixed('J_', jointRecord),
    ...prefixed('J_', springMotorLimit),
    ...prefixed('J_', jointPassCodes),
    ...prefixed('J_REVOLUTE_', revoluteLayout),
    ...prefixed('J_PRISMATIC_', prismaticLayout),
    ...prefixed('J_WELD_', weldLayout),
    ...prefixed('J_DISTANCE_', distanceLayout),
    ...prefixed('J_MOUSE_', mouseLayout),
  ];
  const lines = [
    '// Generated by `npm run build:kernel -w @physical/engine` from the engine definitions',
    '// (src/dynamics/contact-constraint-layout.ts, contact-data.ts with C_ names, body-state.ts,',
    '// body-memory.ts, shape-geometry.ts, narrow-phase-scratch.ts, kernel-arguments.ts,',
    '// pair-kinds.ts, contact-gates.ts, shock-sweep-layout.ts, shape-escapes.ts, core/constants.ts,',
    '// joints/ with J_ names). Do not edit; change those and run the script.',
  ];
  for (const [name, value] of entries) {
    const type = DOUBLES.has(name) ? 'f64' : 'i32';
    if (type === 'i32' && !Number.isInteger(value)) throw new Error(`${name} is not an integer`);
    lines.push(`export const ${name}: ${type} = ${value};`);
  }
  return lines.join('\n') + '\n';
}

/** AssemblyScript's optimiser settings (Binaryen's -O3: speed first). */
export const OPTIMIZE: readonly string[] = ['--optimizeLevel', '3', '--shrinkLevel', '0'];

/**
 * Compiles the kernel with the given layout; returns the optimised module's bytes. With `lanes`,
 * wasm/contact-lanes.ts is replaced by LANES true: pairs of independent constraints are solved in
 * f64x2 lanes (SIMD, WebAssembly only); without, the module has no SIMD, for wasm2js.
 */
export async function compile(
  layout: string,
  lanes: boolean,
  optimize: readonly string[] = OPTIMIZE,
): Promise<Uint8Array> {
  return optimised('contact-kernel.ts', kernelSources(layout, lanes), lanes, optimize);
}

/** The joints' module (wasm/joint-passes.ts): no SIMD, so one binary serves both builds. */
async function compileJoints(layout: string): Promise<Uint8Array> {
  const sources: Record<string, string> = {
    'joint-passes.ts': readFileSync(KERNEL_JOINT_PASSES, 'utf8'),
    'load-store.ts': readFileSync(KERNEL_LOAD_STORE, 'utf8'),
    'contact-layout.ts': layout,
  };
  return optimised('joint-passes.ts', sources, false);
}

/** The main module's sources, by the names its imports use. */
function kernelSources(layout: string, lanes: boolean): Record<string, string> {
  return {
    'contact-kernel.ts': readFileSync(KERNEL_SOURCE, 'utf8'),
    'body-passes.ts': readFileSync(KERNEL_BODY_PASSES, 'utf8'),
    'load-store.ts': readFileSync(KERNEL_LOAD_STORE, 'utf8'),
    ...Object.fromEntries(
      KERNEL_NARROW_PHASE.map((name) => [name, readFileSync(file(`wasm/${name}`), 'utf8')]),
    ),
    'doubles-at.ts': readFileSync(KERNEL_DOUBLES_AT, 'utf8'),
    'kernel-math.ts': readFileSync(KERNEL_MATH, 'utf8'),
    'constraint-access.ts': readFileSync(KERNEL_CONSTRAINT_ACCESS, 'utf8'),
    'circle-pairs.ts': readFileSync(KERNEL_CIRCLE_PAIRS, 'utf8'),
    'shock-propagation.ts': readFileSync(KERNEL_SHOCK_PROPAGATION, 'utf8'),
    'shape-bounds.ts': readFileSync(KERNEL_SHAPE_BOUNDS, 'utf8'),
    '../src/math/trigonometry.ts': readFileSync(ENGINE_TRIGONOMETRY, 'utf8'),
    '../src/math/hypot.ts': readFileSync(ENGINE_HYPOT, 'utf8'),
    'contact-layout.ts': layout,
    'contact-lanes.ts': lanes
      ? 'export const LANES: bool = true;\n'
      : readFileSync(KERNEL_LANES, 'utf8'),
  };
}

/**
 * Compiles `entry` among `sources` (AssemblyScript over the imported memory, no runtime);
 * returns the optimised module's bytes; `simd` enables the f64x2 lanes.
 */
async function optimised(
  entry: string,
  sources: Record<string, string>,
  simd: boolean,
  optimize: readonly string[] = OPTIMIZE,
): Promise<Uint8Array> {
  const outputs: Record<string, Uint8Array | string> = {};
  const result = await asc.main(
    [
      entry,
      '--outFile',
      'kernel.wasm',
      ...optimize,
      '--runtime',
      'stub',
      '--importMemory',
      '--noExportMemory',
      '--noAssert',
      ...(simd ? ['--enable', 'simd'] : []),
    ],
    {
      readFile: (name: string) => sources[name] ?? null,
      writeFile: (name: string, contents: Uint8Array | string) => {
        outputs[name] = contents;
      },
      listFiles: () => [],
    },
  );
  const binary = outputs['kernel.wasm'];
  if (result.error || !(binary instanceof Uint8Array)) {
    throw new Error(`${entry} does not compile:\n${result.stderr.toString()}`);
  }
  return binary;
}

/** The same module as JavaScript (Binaryen's wasm2js): a factory over an imported memory. */
function toJavaScript(binary: Uint8Array): string {
  const module = binaryen.readBinary(binary);
  try {
    const f = binaryen.Features;
    module.setFeatures(f.MVP | f.NontrappingFPToInt | f.MutableGlobals | f.SignExt);
    const js = module.emitAsmjs();
    // wasm2js ends with an instance over an empty buffer and its exports: keep the factory only.
    const start = js.indexOf('function asmFunc(imports) {');
    const end = js.indexOf('var memasmFunc');
    if (start < 0 || end < 0) throw new Error('unexpected wasm2js output');
    return js.slice(start, end).trim();
  } finally {
    module.dispose();
  }
}

/** The generated module's text for the given hex bytes. */
export function kernelBinaryModule(hex: string): string {
  return [
    '// Generated by `npm run build:kernel -w @physical/engine` from wasm/contact-kernel.ts',
    '// (AssemblyScript): the contact kernel as WebAssembly, hex-encoded (hex compresses better',
    '// than base64 under gzip). Do not edit; change the source and run the script.',
    // As Prettier writes it, so the generated file passes the format check unchanged.
    'export const CONTACT_KERNEL_HEX =',
    `  '${hex}';`,
    '',
  ].join('\n');
}

/** The generated JavaScript module, formatted as the repository's Prettier writes it. */
async function kernelJavaScriptModule(factory: string): Promise<string> {
  const text = [
    '// Generated by `npm run build:kernel -w @physical/engine` from wasm/contact-kernel.ts: the',
    "// WebAssembly module turned into JavaScript by Binaryen's wasm2js, for hosts where",
    '// WebAssembly cannot compile and worlds created with `kernel: "javascript"`. Do not edit;',
    '// change the source and run the script.',
    '/* eslint-disable */',
    '// @ts-nocheck',
    "import type { ContactKernel, KernelImports } from './contact-kernel.ts';",
    '',
    factory,
    '',
    '/** The contact kernel over `imports.env.memory.buffer`, as JavaScript. */',
    'export const createJavaScriptContactKernel: (imports: KernelImports) => ContactKernel =',
    '  asmFunc;',
    '',
  ].join('\n');
  const options = await prettier.resolveConfig(KERNEL_JAVASCRIPT_MODULE);
  return prettier.format(text, { ...options, filepath: KERNEL_JAVASCRIPT_MODULE });
}

/** The joints' module as hex, as kernelBinaryModule writes the main one. */
export function jointKernelBinaryModule(hex: string): string {
  return [
    '// Generated by `npm run build:kernel -w @physical/engine` from wasm/joint-passes.ts',
    "// (AssemblyScript): the joints' passes as a WebAssembly module of their own over the",
    "// contact kernel's memory, hex-encoded; only the joints' code imports it. Do not edit;",
    '// change the source and run the script.',
    'export const JOINT_KERNEL_HEX =',
    `  '${hex}';`,
    '',
  ].join('\n');
}

/** The joints' module as JavaScript (wasm2js), formatted as the repository's Prettier writes it. */
async function jointKernelJavaScriptModule(factory: string): Promise<string> {
  const text = [
    '// Generated by `npm run build:kernel -w @physical/engine` from wasm/joint-passes.ts: the',
    "// joints' WebAssembly module turned into JavaScript by Binaryen's wasm2js, for hosts where",
    '// WebAssembly cannot compile and worlds created with `kernel: "javascript"`. Do not edit;',
    '// change the source and run the script.',
    '/* eslint-disable */',
    '// @ts-nocheck',
    "import type { KernelImports } from '../contact-kernel.ts';",
    "import type { JointPasses } from './joint-kernel.ts';",
    '',
    factory,
    '',
    "/** The joints' passes over `imports.env.memory.buffer`, as JavaScript. */",
    'export const createJavaScriptJointKernel: (imports: KernelImports) => JointPasses = asmFunc;',
    '',
  ].join('\n');
  const options = await prettier.resolveConfig(JOINT_KERNEL_JAVASCRIPT_MODULE);
  return prettier.format(text, { ...options, filepath: JOINT_KERNEL_JAVASCRIPT_MODULE });
}

/** Every generated file, path to text, built afresh from the sources. */
export async function buildContactKernel(): Promise<Record<string, string>> {
  const layout = kernelLayout();
  const binary = await compile(layout, true);
  const scalar = await compile(layout, false);
  const joints = await compileJoints(layout);
  return {
    [KERNEL_LAYOUT]: layout,
    [KERNEL_BINARY_MODULE]: kernelBinaryModule(Buffer.from(binary).toString('hex')),
    [KERNEL_JAVASCRIPT_MODULE]: await kernelJavaScriptModule(toJavaScript(scalar)),
    [JOINT_KERNEL_BINARY_MODULE]: jointKernelBinaryModule(Buffer.from(joints).toString('hex')),
    [JOINT_KERNEL_JAVASCRIPT_MODULE]: await jointKernelJavaScriptModule(toJavaScript(joints)),
  };
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  for (const [path, text] of Object.entries(await buildContactKernel())) {
    writeFileSync(path, text);
    process.stdout.write(`wrote ${path}: ${text.length} characters\n`);
  }
}
