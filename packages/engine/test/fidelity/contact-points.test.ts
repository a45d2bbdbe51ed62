import { describe, expect, it } from 'vitest';
import { SPECULATIVE_DISTANCE } from '../../src/core/constants.ts';
import { collidePolygons, Manifold } from '../unit/collision/kernel-collide.ts';
import { makeBox } from '../../src/geometry/polygon.ts';
import { Transform } from '../../src/math/transform.ts';

// Fidelity law 13: contact points of two boxes at known angles match the analytic contact points
// (midway between the touching corner and the face it presses into) within 1 mm, and their
// separations match the analytic penetration within 1e-6 m.

const POSITION_TOLERANCE = 1e-3;
const SEPARATION_TOLERANCE = 1e-6;
const DEGREE = Math.PI / 180;

interface Expected {
  x: number;
  y: number;
  separation: number;
}

interface Scene {
  name: string;
  /** Lower body A: centre, angle, half extents. */
  a: { x: number; y: number; angle: number; halfWidth: number; halfHeight: number };
  /** Upper body B: centre and angle, half extents 0.5 x 0.5. */
  b: { x: number; y: number; angle: number };
  normalX: number;
  normalY: number;
  points: Expected[];
}

/** World corners of a 1 m box centred at (x, y) turned by `angle`. */
function corners(x: number, y: number, angle: number): [number, number][] {
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  const list: [number, number][] = [];
  for (const [lx, ly] of [
    [-0.5, -0.5],
    [0.5, -0.5],
    [0.5, 0.5],
    [-0.5, 0.5],
  ] as const) {
    list.push([x + c * lx - s * ly, y + s * lx + c * ly]);
  }
  return list;
}

/**
 * B (a 1 m box) rests on the flat top face y = 0.5 of a wide ground box A, with its lowest corner
 * at (cornerX, 0.5 - depth). Analytic contacts: every corner of B below the face or within the
 * speculative distance above it, each midway between the corner and the face.
 */
function onGround(name: string, angle: number, cornerX: number, depth: number): Scene {
  const offsets = corners(0, 0, angle);
  let lowest = offsets[0]!;
  for (const corner of offsets) {
    if (corner[1] < lowest[1]) lowest = corner;
  }
  const x = cornerX - lowest[0];
  const y = 0.5 - depth - lowest[1];
  const points: Expected[] = [];
  for (const [cx, cy] of corners(x, y, angle)) {
    if (cy - 0.5 < SPECULATIVE_DISTANCE) {
      points.push({ x: cx, y: 0.5 * (cy + 0.5), separation: cy - 0.5 });
    }
  }
  return {
    name,
    a: { x: 0, y: 0, angle: 0, halfWidth: 3, halfHeight: 0.5 },
    b: { x, y, angle },
    normalX: 0,
    normalY: 1,
    points,
  };
}

/**
 * The top-right corner (0.5, 0.5) of a 1 m box A presses `depth` into the bottom face of B, which
 * is turned by `angle` (clockwise when negative) so its face slopes across the corner. Analytic
 * contact: the corner moved half the depth out along B's face normal; the normal from A to B is
 * the inward normal of B's bottom face.
 */
function cornerIntoFace(name: string, angle: number, depth: number): Scene {
  const faceNormalX = Math.sin(angle);
  const faceNormalY = -Math.cos(angle);
  return {
    name,
    a: { x: 0, y: 0, angle: 0, halfWidth: 0.5, halfHeight: 0.5 },
    b: { x: 0.5 - (0.5 - depth) * faceNormalX, y: 0.5 - (0.5 - depth) * faceNormalY, angle },
    normalX: -faceNormalX,
    normalY: -faceNormalY,
    points: [
      {
        x: 0.5 + 0.5 * depth * faceNormalX,
        y: 0.5 + 0.5 * depth * faceNormalY,
        separation: -depth,
      },
    ],
  };
}

const scenes: Scene[] = [
  onGround(
    'a box resting flat on a box, 1 cm overlap: two points at the bottom corners',
    0,
    -0.2,
    0.01,
  ),
  onGround(
    'a box rotated 45 degrees, its corner pushed 2 cm into the face: one point',
    45 * DEGREE,
    0.2,
    0.02,
  ),
  onGround('a box tilted 10 degrees resting on its corner', 10 * DEGREE, 0.4, 0.005),
  onGround('a box tilted 30 degrees resting on its corner', 30 * DEGREE, -0.7, 0.003),
  onGround('a box tilted -10 degrees resting on its corner', -10 * DEGREE, 1.1, 0.008),
  onGround(
    'a box tilted 0.5 degrees: both corners, one of them speculative',
    0.5 * DEGREE,
    0,
    0.005,
  ),
  cornerIntoFace('a box corner 1 cm into the face of a box tilted -20 degrees', -20 * DEGREE, 0.01),
  cornerIntoFace(
    'a box corner 4 mm into the face of a box tilted -30 degrees',
    -30 * DEGREE,
    0.004,
  ),
];

/** Applies the rigid motion (rotate by `angle`, then translate by (tx, ty)) to a world point. */
function move(x: number, y: number, tx: number, ty: number, angle: number): [number, number] {
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  return [tx + c * x - s * y, ty + s * x + c * y];
}

describe('13. Two boxes meeting at known angles produce contact points within 1 mm of the analytic ones', () => {
  for (const scene of scenes) {
    for (const [frameName, tx, ty, turn] of [
      ['world frame', 0, 0, 0],
      ['scene turned 0.8 rad and moved to (50, -20)', 50, -20, 0.8],
    ] as const) {
      it(`${scene.name} (${frameName})`, () => {
        const a = makeBox(scene.a.halfWidth, scene.a.halfHeight, 0, 0, 0, 0, 'a');
        const b = makeBox(0.5, 0.5, 0, 0, 0, 0, 'b');
        const [ax, ay] = move(scene.a.x, scene.a.y, tx, ty, turn);
        const [bx, by] = move(scene.b.x, scene.b.y, tx, ty, turn);
        const xfA = new Transform().set(ax, ay, scene.a.angle + turn);
        const xfB = new Transform().set(bx, by, scene.b.angle + turn);
        const manifold = new Manifold();
        collidePolygons(a, xfA, b, xfB, manifold);

        const [normalX, normalY] = move(scene.normalX, scene.normalY, 0, 0, turn);
        expect(manifold.normalX).toBeCloseTo(normalX, 9);
        expect(manifold.normalY).toBeCloseTo(normalY, 9);
        expect(manifold.pointCount).toBe(scene.points.length);
        for (const expected of scene.points) {
          const [ex, ey] = move(expected.x, expected.y, tx, ty, turn);
          let nearest = Infinity;
          let separation = Number.NaN;
          for (let i = 0; i < manifold.pointCount; i++) {
            const point = manifold.points[i === 0 ? 0 : 1];
            const distance = Math.hypot(point.x - ex, point.y - ey);
            if (distance < nearest) {
              nearest = distance;
              separation = point.separation;
            }
          }
          expect(nearest).toBeLessThan(POSITION_TOLERANCE);
          expect(Math.abs(separation - expected.separation)).toBeLessThan(SEPARATION_TOLERANCE);
        }
      });
    }
  }
});
