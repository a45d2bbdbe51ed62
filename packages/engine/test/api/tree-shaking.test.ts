import { build, type Metafile } from 'esbuild';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { CONTACT_KERNEL_HEX } from '../../src/dynamics/contact-kernel-binary.ts';
import { JOINT_KERNEL_HEX } from '../../src/dynamics/joints/joint-kernel-binary.ts';

// An app pays only for what it imports: bundled as an app bundler would (esbuild, minified,
// tree-shaken), an entry without joints or snapshots carries no snapshot code and no joint kind.
// Each check runs on the whole library too, where it must find what it looks for, so that a
// marker that no longer exists cannot make the app check pass.

const source = fileURLToPath(new URL('../../src/', import.meta.url));

/** Source files whose code must stay out of an app that imports neither joints nor snapshots. */
const SNAPSHOT_FILES = ['world/snapshot.ts', 'world/joint-snapshot.ts', 'world/snapshot-values.ts'];
const JOINT_FILES = [
  'dynamics/joints/revolute-joint.ts',
  'dynamics/joints/revolute-joint-solver.ts',
  'dynamics/joints/prismatic-joint.ts',
  'dynamics/joints/prismatic-joint-solver.ts',
  'dynamics/joints/distance-joint.ts',
  'dynamics/joints/weld-joint.ts',
  'dynamics/joints/mouse-joint.ts',
  'dynamics/joints/joint-factories.ts',
  // The joints' passes, a WebAssembly module of their own, and its loader.
  'dynamics/joints/joint-kernel-binary.ts',
  'dynamics/joints/joint-kernel-loader.ts',
];

/** Strings only those files hold, as they appear in minified output. */
const SNAPSHOT_MARKERS = [
  'physical-world', // the snapshot format name
  'cannot be taken while the world is stepping', // takeSnapshot's error
  'the versions this Physical reads', // restoreSnapshot's version check
  'must be a unit vector, got one of length', // a joint snapshot check
];
const JOINT_MARKERS = [
  'lowerAngle', // revolute
  'must not be the zero vector', // prismatic axis
  'must lie between minLength', // distance
  'angularHertz', // weld
  'must be a dynamic body, got a', // mouse
];

interface Bundle {
  readonly code: string;
  /** Source files (relative to src/) that put at least one byte into the output. */
  readonly files: string[];
}

async function bundle(entry: string, production = false): Promise<Bundle> {
  const result = await build({
    ...(production ? { define: { 'process.env.NODE_ENV': '"production"' } } : {}),
    stdin: { contents: entry, resolveDir: source, sourcefile: 'app.ts', loader: 'ts' },
    bundle: true,
    minify: true,
    treeShaking: true,
    format: 'esm',
    platform: 'neutral',
    target: 'es2022',
    write: false,
    metafile: true,
    logLevel: 'silent',
  });
  const metafile: Metafile = result.metafile;
  const output = Object.values(metafile.outputs)[0]!;
  const files = Object.entries(output.inputs)
    .filter(([, input]) => input.bytesInOutput > 0)
    .map(([path]) => path.replace(/\\/g, '/'))
    .filter((path) => path.includes('packages/engine/src/'))
    .map((path) =>
      path.slice(path.indexOf('packages/engine/src/') + 'packages/engine/src/'.length),
    );
  return { code: result.outputFiles[0]!.text, files };
}

/** An app: bodies, walls, forces; no joints, no snapshots. */
const APP = `
    import { Force, World, box, particle, polygon, wall } from './index.ts';
    const world = new World({ gravity: { x: 0, y: 9.81 } });
    world.add(wall({ from: { x: -10, y: 0 }, to: { x: 10, y: 0 } }));
    const crate = world.add(box({ position: { x: 0, y: -1 }, width: 1, height: 1 }));
    world.add(particle({ position: { x: 1, y: -3 }, radius: 0.25 }));
    world.add(polygon({ vertices: [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 1 }] }));
    crate.applyForce({ x: 5, y: 0 }, { duration: 0.5 });
    world.step();
    console.log(crate.position, Force);
`;

let library: Bundle;
let app: Bundle;
/** The app as a production build bundles it (process.env.NODE_ENV defined as "production"). */
let productionApp: Bundle;

beforeAll(async () => {
  // Every export kept, as a library bundle.
  library = await bundle(`export * from './index.ts';`);
  // An app: bodies, walls, forces; no joints, no snapshots.
  app = await bundle(APP);
  productionApp = await bundle(APP, true);
});

describe('tree-shaking: an app without joints or snapshots', () => {
  it('bundles the world, shapes and forces', () => {
    expect(app.files).toContain('world/world.ts');
    expect(app.files).toContain('dynamics/force.ts');
    expect(app.files).toContain('dynamics/body-factories.ts');
  });

  it('carries no snapshot code', () => {
    for (const file of SNAPSHOT_FILES) {
      expect(library.files, `the library bundles ${file}`).toContain(file);
      expect(app.files, `the app bundles ${file}`).not.toContain(file);
    }
    for (const marker of SNAPSHOT_MARKERS) {
      expect(library.code, `the library holds '${marker}'`).toContain(marker);
      expect(app.code, `the app holds '${marker}'`).not.toContain(marker);
    }
  });

  it('carries no joint kind', () => {
    for (const file of JOINT_FILES) {
      expect(library.files, `the library bundles ${file}`).toContain(file);
      expect(app.files, `the app bundles ${file}`).not.toContain(file);
    }
    for (const marker of JOINT_MARKERS) {
      expect(library.code, `the library holds '${marker}'`).toContain(marker);
      expect(app.code, `the app holds '${marker}'`).not.toContain(marker);
    }
  });

  it('carries the size warning in development builds only', () => {
    // Its message, as the development app (NODE_ENV not defined) holds it.
    const marker = 'in development builds only';
    expect(app.code).toContain(marker);
    expect(app.files).toContain('world/size-warning.ts');
    expect(productionApp.code).not.toContain(marker);
    expect(productionApp.files).not.toContain('world/size-warning.ts');
  });

  it("carries no joint passes: their WebAssembly module is the joints' own", () => {
    expect(library.code, 'the library holds the joints module').toContain(JOINT_KERNEL_HEX);
    expect(app.code, 'the app holds the joints module').not.toContain(JOINT_KERNEL_HEX);
    // Nor any part of it: its first bytes past the WebAssembly header (type section) are its own.
    expect(app.code).not.toContain(JOINT_KERNEL_HEX.slice(16, 80));
  });

  it('is smaller than the library, beside the kernel both ship', () => {
    // The WebAssembly contact kernel (hex in the bundle) holds every pass of the step but the
    // joints', and every world needs it: the JavaScript around it is what tree-shaking can drop.
    const kernel = CONTACT_KERNEL_HEX.length;
    expect(app.code).toContain(CONTACT_KERNEL_HEX);
    const rest = library.code.length - kernel - JOINT_KERNEL_HEX.length;
    expect(app.code.length - kernel).toBeLessThan(rest * 0.8);
  });
});
