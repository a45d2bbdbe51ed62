// The narrow-phase functions as the tests call them: the kernel's (wasm/collide-*.ts, issue #30),
// run through its collidePair export on two geometry rows (shape-geometry.ts) written into a
// small memory of their own, in either build. The manifold comes back as an object.
import { SPECULATIVE_DISTANCE } from '../../../src/core/constants.ts';
import { createContactKernel, type ContactKernel } from '../../../src/dynamics/contact-kernel.ts';
import {
  M_COUNT,
  M_NORMAL_X,
  M_NORMAL_Y,
  M_POINT_STRIDE,
  M_POINTS,
  MP_ID,
  MP_SEPARATION,
  MP_X,
  MP_Y,
  NARROW_PHASE_SCRATCH_DOUBLES,
  S_TRANSFORM_A,
  S_TRANSFORM_B,
} from '../../../src/dynamics/narrow-phase-scratch.ts';
import {
  PAIR_CAPSULE_CIRCLE,
  PAIR_CAPSULES,
  PAIR_CIRCLES,
  PAIR_POLYGON_CAPSULE,
  PAIR_POLYGON_CIRCLE,
  PAIR_POLYGONS,
  PAIR_SEGMENT_CAPSULE,
  PAIR_SEGMENT_CIRCLE,
  PAIR_SEGMENT_POLYGON,
} from '../../../src/dynamics/pair-kinds.ts';
import { GEOMETRY_STRIDE, writeGeometryRow } from '../../../src/dynamics/shape-geometry.ts';
import type { Geometry } from '../../../src/dynamics/shape.ts';
import type { Capsule } from '../../../src/geometry/capsule.ts';
import type { Circle } from '../../../src/geometry/circle.ts';
import type { Polygon } from '../../../src/geometry/polygon.ts';
import type { Segment } from '../../../src/geometry/segment.ts';
import type { Transform } from '../../../src/math/transform.ts';
import '../../../src/javascript-kernel.ts';

/** One manifold point: world position (m), separation (m), feature id. */
export interface ManifoldPoint {
  x: number;
  y: number;
  separation: number;
  id: number;
}

/** What a collide function found: up to two points sharing a normal (world frame, A to B). */
export class Manifold {
  normalX = 0;
  normalY = 0;
  pointCount = 0;
  /** Input: keep points closer than this (m). */
  speculativeDistance: number = SPECULATIVE_DISTANCE;
  readonly points: [ManifoldPoint, ManifoldPoint] = [
    { x: 0, y: 0, separation: 0, id: 0 },
    { x: 0, y: 0, separation: 0, id: 0 },
  ];
}

/** Which build runs the kernel. */
export type Build = 'webassembly' | 'javascript';

const ROWS = 0;
const SCRATCH = 2 * GEOMETRY_STRIDE * 8;
const BYTES = SCRATCH + NARROW_PHASE_SCRATCH_DOUBLES * 8;

interface Instance {
  kernel: ContactKernel;
  doubles: Float64Array;
}
const instances = new Map<Build, Instance>();

function instance(build: Build): Instance {
  let found = instances.get(build);
  if (found === undefined) {
    const created = createContactKernel(BYTES, build === 'webassembly');
    if (created.webAssembly !== (build === 'webassembly')) throw new Error(`no ${build} build`);
    found = { kernel: created.kernel, doubles: new Float64Array(created.memory.buffer) };
    instances.set(build, found);
  }
  return found;
}

/** Feature key for a pair of features, as the kernel makes it (wasm/manifold.ts). */
export function makeFeatureId(a: number, b: number): number {
  return ((a & 0xff) << 8) | (b & 0xff);
}

/** Runs pair kind `kind` on geometries `a`, `b` at `xfA`, `xfB` in `build`, into `out`. */
export function collideIn(
  build: Build,
  kind: number,
  a: Geometry,
  xfA: Transform,
  b: Geometry,
  xfB: Transform,
  out: Manifold,
): void {
  const { kernel, doubles } = instance(build);
  const rows = doubles.subarray(ROWS / 8, SCRATCH / 8);
  writeGeometryRow(rows, 0, a);
  writeGeometryRow(rows, 1, b);
  const m = SCRATCH / 8;
  doubles.set([xfA.x, xfA.y, xfA.c, xfA.s], m + S_TRANSFORM_A);
  doubles.set([xfB.x, xfB.y, xfB.c, xfB.s], m + S_TRANSFORM_B);
  kernel.collidePair(kind, ROWS, ROWS + GEOMETRY_STRIDE * 8, SCRATCH, out.speculativeDistance);
  out.normalX = doubles[m + M_NORMAL_X]!;
  out.normalY = doubles[m + M_NORMAL_Y]!;
  out.pointCount = doubles[m + M_COUNT]!;
  for (let i = 0; i < out.pointCount; i++) {
    const p = m + M_POINTS + i * M_POINT_STRIDE;
    const point = out.points[i === 0 ? 0 : 1];
    point.x = doubles[p + MP_X]!;
    point.y = doubles[p + MP_Y]!;
    point.separation = doubles[p + MP_SEPARATION]!;
    point.id = doubles[p + MP_ID]!;
  }
}

type Collide<A, B> = (a: A, xfA: Transform, b: B, xfB: Transform, out: Manifold) => void;
const pair =
  <A extends Geometry, B extends Geometry>(kind: number): Collide<A, B> =>
  (a, xfA, b, xfB, out) =>
    collideIn('webassembly', kind, a, xfA, b, xfB, out);

// The kernel's functions by their names (wasm/collide-*.ts), in the WebAssembly build; the
// builds' agreement is narrow-phase-builds.test.ts's.
export const collideCircles = pair<Circle, Circle>(PAIR_CIRCLES);
export const collidePolygonAndCircle = pair<Polygon, Circle>(PAIR_POLYGON_CIRCLE);
export const collidePolygons = pair<Polygon, Polygon>(PAIR_POLYGONS);
export const collideSegmentAndCircle = pair<Segment, Circle>(PAIR_SEGMENT_CIRCLE);
export const collideSegmentAndPolygon = pair<Segment, Polygon>(PAIR_SEGMENT_POLYGON);
export const collideCapsuleAndCircle = pair<Capsule, Circle>(PAIR_CAPSULE_CIRCLE);
export const collideCapsules = pair<Capsule, Capsule>(PAIR_CAPSULES);
export const collidePolygonAndCapsule = pair<Polygon, Capsule>(PAIR_POLYGON_CAPSULE);
export const collideSegmentAndCapsule = pair<Segment, Capsule>(PAIR_SEGMENT_CAPSULE);
