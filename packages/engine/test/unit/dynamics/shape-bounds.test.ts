import { describe, expect, it } from 'vitest';
import { Body, World, box, capsule, particle, wall } from '@physical/engine';
// The JavaScript build of the kernel, compared here with the WebAssembly one.
import '@physical/engine/javascript-kernel';
import { AABB } from '../../../src/geometry/aabb.ts';
import { computeCircleAABB } from '../../../src/geometry/circle.ts';
import { computeCapsuleAABB } from '../../../src/geometry/capsule.ts';
import { computePolygonAABB } from '../../../src/geometry/polygon-queries.ts';
import { computeSegmentAABB } from '../../../src/geometry/segment.ts';
import type { BodyBounds } from '../../../src/dynamics/body-bounds.ts';
import { B_MAX_EXTENT, B_VX, B_VY, B_W } from '../../../src/dynamics/body-memory.ts';
import { AABB_MARGIN, SPECULATIVE_DISTANCE } from '../../../src/core/constants.ts';
import type { Shape } from '../../../src/dynamics/shape.ts';
import type { Solver } from '../../../src/dynamics/solver.ts';
import { ESCAPE_STRIDE } from '../../../src/dynamics/shape-escapes.ts';

// Finalize's broad-phase boxes are the kernel's shapeBounds (wasm/shape-bounds.ts): per awake body
// not due a sweep, each shape's tight box from its geometry row at the new pose, and the shapes
// whose speculative box left their fat box, listed for the TypeScript to move. Here, at each step,
// both builds are checked against the TypeScript: the geometry files' compute*AABB for the tight
// box, and for the escape test the speculative box as the engine defines it (below), bit for bit.

interface Seen {
  /** Per step: the kernel's escape list (id and box, as listed). */
  escapes: number[][];
  /** How many shapes' tight boxes were compared, and how many listed. */
  compared: number;
  listed: number;
  skipped: number;
}

function tightOf(shape: Shape): AABB {
  const g = shape.geometry;
  const xf = shape.body.transform;
  const out = new AABB();
  if (g.kind === 'circle') return computeCircleAABB(g, xf, out);
  if (g.kind === 'polygon') return computePolygonAABB(g, xf, out);
  if (g.kind === 'capsule') return computeCapsuleAABB(g, xf, out);
  return computeSegmentAABB(g, xf, out);
}

const bits = (box: AABB): number[] => [box.minX, box.minY, box.maxX, box.maxY];

/**
 * The speculative box, written out here as the oracle (the engine's one source is the kernel's):
 * the tight box grown by the speculative distance, plus the spin swept over the body's extent
 * when that passes the fat margin, and stretched along the velocity when the body moves farther
 * than the margin in a step of `dt`.
 */
function speculative(shape: Shape, dt: number): number[] {
  const body = shape.body;
  const d = body.store.data;
  const spin = Math.abs(d[body.base + B_W]!) * d[body.base + B_MAX_EXTENT]! * dt;
  const grow = spin > AABB_MARGIN ? SPECULATIVE_DISTANCE + spin : SPECULATIVE_DISTANCE;
  let dx = d[body.base + B_VX]! * dt;
  let dy = d[body.base + B_VY]! * dt;
  if (dx * dx + dy * dy <= AABB_MARGIN * AABB_MARGIN) {
    dx = 0;
    dy = 0;
  }
  const t = tightOf(shape);
  return [
    t.minX - grow + Math.min(dx, 0),
    t.minY - grow + Math.min(dy, 0),
    t.maxX + grow + Math.max(dx, 0),
    t.maxY + grow + Math.max(dy, 0),
  ];
}

function run(kernel: 'auto' | 'javascript'): Seen {
  const world = new World({ kernel });
  world.add(wall({ from: { x: -30, y: 0 }, to: { x: 30, y: 0 } }));
  world.add(wall({ from: { x: -30, y: 0 }, to: { x: -30, y: -40 } }));
  // Every kind on moving bodies: boxes (one rounded), balls, capsules, a compound body, segments, fast spinning bodies and a bullet (skipped by the pass: the sweep moves them).
  for (let i = 0; i < 8; i++) {
    world.add(box({ position: { x: -10 + 1.3 * i, y: -0.5 - i }, width: 1, height: 1 }));
    world.add(particle({ position: { x: -10 + 1.3 * i, y: -12 - i }, radius: 0.3 }));
    world.add(capsule({ position: { x: 4 + i, y: -6 - i }, length: 0.8, radius: 0.2 }));
  }
  world.add(
    box({ position: { x: 12, y: -3 }, width: 1, height: 0.5, radius: 0.1, angularVelocity: 30 }),
  );
  const compound = world.add(
    new Body({
      position: { x: -4, y: -20 },
      angularVelocity: 4,
      shapes: [
        { type: 'box', width: 0.2, height: 2 },
        { type: 'circle', radius: 0.4, offset: { x: 0, y: -1 } },
      ],
    }),
  );
  // Segments (walls) move only on kinematic bodies: a turning, sliding one.
  world.add(
    new Body({
      type: 'kinematic',
      position: { x: 15, y: -15 },
      linearVelocity: { x: -0.5, y: 0 },
      angularVelocity: 1,
      shapes: [
        { type: 'segment', from: { x: -1, y: 1 }, to: { x: 1, y: 1 } },
        { type: 'segment', from: { x: 0, y: 0 }, to: { x: 0, y: 2 }, oneSided: true },
      ],
    }),
  );
  const fast = world.add(particle({ position: { x: -25, y: -5 }, radius: 0.2 }));
  fast.linearVelocity = { x: 200, y: 0 };
  const bullet = world.add(particle({ position: { x: -25, y: -8 }, radius: 0.2, bullet: true }));
  bullet.linearVelocity = { x: 150, y: 10 };

  const inner = world as unknown as { solver: Solver; bounds: BodyBounds };
  const solver = inner.solver;
  const bounds = inner.bounds;
  const seen: Seen = { escapes: [], compared: 0, listed: 0, skipped: 0 };
  // What the pass left, read where TypeScript moves the listed proxies (before any moves).
  let pending: { shape: Shape; tight: number[]; fat: AABB; placed: number[] }[] = [];
  let listed: number[] = [];
  const moveEscaped = bounds.moveEscaped.bind(bounds);
  bounds.moveEscaped = (escaped: Float64Array, count: number) => {
    listed = Array.from(escaped.subarray(0, count * ESCAPE_STRIDE));
    pending = [];
    for (let i = 0; i < solver.awakeCount; i++) {
      for (const shape of solver.awake[i]!.shapeList) {
        const tight = bits(shape.readTightBox(new AABB()));
        const fat = shape.readFatBox(new AABB());
        const placed = speculative(shape, bounds.dt);
        pending.push({ shape, tight, fat, placed });
      }
    }
    moveEscaped(escaped, count);
  };

  for (let step = 0; step < 150; step++) {
    if (step === 40)
      compound.addShape({
        type: 'capsule',
        center1: { x: 0, y: 0 },
        center2: { x: 1, y: 0 },
        radius: 0.1,
      });
    if (step === 80) compound.removeShape(compound.shapes[1]!);
    world.step(1 / 60);
    const skipped = new Set<Body>([
      ...solver.fastBodies.slice(0, solver.fastCount),
      ...solver.fastBullets.slice(0, solver.fastBulletCount),
    ]);
    const expected: number[] = [];
    for (const p of pending) {
      if (skipped.has(p.shape.body)) {
        seen.skipped++;
        continue;
      }
      // Bit for bit: toEqual tells -0 from +0.
      expect(p.tight).toEqual(bits(tightOf(p.shape)));
      seen.compared++;
      const [minX, minY, maxX, maxY] = p.placed as [number, number, number, number];
      const f = p.fat;
      if (!(f.minX <= minX && f.minY <= minY && maxX <= f.maxX && maxY <= f.maxY)) {
        expected.push(p.shape.id, minX, minY, maxX, maxY);
      }
    }
    expect(listed).toEqual(expected);
    seen.listed += listed.length / ESCAPE_STRIDE;
    seen.escapes.push(listed);
  }
  return seen;
}

describe("finalize's broad-phase boxes (the kernel's shapeBounds)", () => {
  it('give the TypeScript tight boxes and escape lists in both builds, and the same in each', () => {
    const wasm = run('auto');
    const js = run('javascript');
    expect(js.escapes).toEqual(wasm.escapes);
    // The world exercises what it means to: many boxes compared, proxies moved, sweeps skipped.
    expect(wasm.compared).toBeGreaterThan(2000);
    expect(wasm.listed).toBeGreaterThan(100);
    expect(wasm.skipped).toBeGreaterThan(0);
  });
});
