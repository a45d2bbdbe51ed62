import { describe, expect, it } from 'vitest';
import { SPECULATIVE_DISTANCE } from '../../../src/core/constants.ts';
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
import type { Geometry } from '../../../src/dynamics/shape.ts';
import { makeCapsule } from '../../../src/geometry/capsule.ts';
import { makeCircle } from '../../../src/geometry/circle.ts';
import { makeBox, makePolygon } from '../../../src/geometry/polygon.ts';
import { makeSegment } from '../../../src/geometry/segment.ts';
import { Transform } from '../../../src/math/transform.ts';
import { collideIn, Manifold } from './kernel-collide.ts';

// The narrow phase is one source (wasm/collide-*.ts) built twice, to WebAssembly and by wasm2js
// to JavaScript (scripts/contact-kernel-build.ts). Worlds must not drift apart when a page runs
// one build and another page the other, so every pair kind must give the same manifold bits in
// both: here on shapes of every kind, touching, deep, speculative, apart, and turned.

const circle = makeCircle(0.1, -0.05, 0.35, 'circle');
const capsule = makeCapsule(-0.4, 0.1, 0.5, -0.2, 0.15, 'capsule');
const box = makeBox(0.3, 0.2, 0, 0, 0, 0, 'box');
const roundedBox = makeBox(0.25, 0.15, 0.05, -0.02, 0.3, 0.05, 'rounded');
const hexagon = makePolygon(
  Array.from({ length: 6 }, (_, i) => ({
    x: 0.4 * Math.cos((i * Math.PI) / 3),
    y: 0.4 * Math.sin((i * Math.PI) / 3),
  })),
  0,
  'hexagon',
);
const wall = makeSegment(-1.5, 0.2, 1.5, -0.1, false, 'wall');
const oneSidedWall = makeSegment(-1.5, 0.2, 1.5, -0.1, true, 'oneSided');
const polygons = [box, roundedBox, hexagon];
const walls = [wall, oneSidedWall];

const pairs: [string, number, Geometry[], Geometry[]][] = [
  ['circles', PAIR_CIRCLES, [circle], [circle]],
  ['polygon and circle', PAIR_POLYGON_CIRCLE, polygons, [circle]],
  ['polygons', PAIR_POLYGONS, polygons, polygons],
  ['segment and circle', PAIR_SEGMENT_CIRCLE, walls, [circle]],
  ['segment and polygon', PAIR_SEGMENT_POLYGON, walls, polygons],
  ['capsule and circle', PAIR_CAPSULE_CIRCLE, [capsule], [circle]],
  ['capsules', PAIR_CAPSULES, [capsule], [capsule]],
  ['polygon and capsule', PAIR_POLYGON_CAPSULE, polygons, [capsule]],
  ['segment and capsule', PAIR_SEGMENT_CAPSULE, walls, [capsule]],
];

/** Every number of a manifold, as the bits of its doubles. */
function bits(m: Manifold): string {
  const numbers = [m.normalX, m.normalY, m.pointCount];
  for (let i = 0; i < m.pointCount; i++) {
    const p = m.points[i === 0 ? 0 : 1];
    numbers.push(p.x, p.y, p.separation, p.id);
  }
  const view = new DataView(new ArrayBuffer(8));
  return numbers
    .map((n) => {
      view.setFloat64(0, n);
      return view.getBigUint64(0).toString(16);
    })
    .join(' ');
}

/** Deterministic numbers in [0, 1) (a linear congruential generator). */
function random(seed: number): () => number {
  let state = seed;
  return () => {
    state = (state * 1664525 + 1013904223) >>> 0;
    return state / 2 ** 32;
  };
}

describe('the narrow phase in both builds', () => {
  for (const [name, kind, shapesA, shapesB] of pairs) {
    it(`${name}: the same manifold bits in WebAssembly and JavaScript, touching, deep, speculative and turned`, () => {
      const next = random(kind + 1);
      const counts = [0, 0, 0];
      const wasm = new Manifold();
      const js = new Manifold();
      for (const a of shapesA) {
        for (const b of shapesB) {
          for (let n = 0; n < 150; n++) {
            // A far from the origin and turned; B around it at distances from deep overlap
            // (0.1 m between origins) to just past the speculative margin.
            const angleA = n % 5 === 0 ? 0 : 6.3 * next();
            const xfA = new Transform().set(100 + 3 * next(), -40 + next(), angleA);
            const angle = 6.3 * next();
            const reach = 0.1 + 1.3 * next();
            const xfB = new Transform().set(
              xfA.x + reach * Math.cos(angle),
              xfA.y + reach * Math.sin(angle),
              n % 4 === 0 ? angleA : 6.3 * next(),
            );
            // Speculative distances as the gates pass them: the bare margin, or one widened by
            // how fast the bodies close.
            const margin = SPECULATIVE_DISTANCE + (n % 3 === 0 ? 0.5 * next() : 0);
            wasm.speculativeDistance = margin;
            js.speculativeDistance = margin;
            collideIn('webassembly', kind, a, xfA, b, xfB, wasm);
            collideIn('javascript', kind, a, xfA, b, xfB, js);
            expect(bits(js)).toBe(bits(wasm));
            counts[wasm.pointCount]!++;
          }
        }
      }
      // The cases reach every outcome the pair kind can have: no point, one, and (for the kinds
      // with faces) two.
      expect(counts[0]).toBeGreaterThan(0);
      expect(counts[1]).toBeGreaterThan(0);
      const twoPoints =
        kind !== PAIR_CIRCLES &&
        kind !== PAIR_POLYGON_CIRCLE &&
        kind !== PAIR_SEGMENT_CIRCLE &&
        kind !== PAIR_CAPSULE_CIRCLE;
      if (twoPoints) expect(counts[2]).toBeGreaterThan(0);
    });
  }
});
