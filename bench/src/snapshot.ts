// Rollback's cost (issue #28): takeSnapshot and restoreSnapshot on a world of 1,000 bodies with
// joints, in ms (median of the rounds), and the snapshot's size as JSON text. Physical only,
// from its tsc build like the scenes; run in the bench's own process.
import {
  World,
  box,
  restoreSnapshot,
  revoluteJoint,
  takeSnapshot,
  type Body,
} from '@physical/engine';

export interface SnapshotReport {
  bodies: number;
  joints: number;
  contacts: number;
  /** Steps run before saving (the pile settles, the chains swing). */
  stepsBefore: number;
  rounds: number;
  takeMedianMs: number;
  restoreMedianMs: number;
  /** JSON.stringify of the snapshot, then JSON.parse before restoring (as for storage). */
  stringifyMedianMs: number;
  parseMedianMs: number;
  jsonBytes: number;
}

/**
 * 600 boxes in a pile of 20 rows and 40 hanging chains of 10 hinged links: 1,000 moving bodies,
 * 400 revolute joints, and the ground and the chains' pivots.
 */
export function rollbackWorld(): World {
  const world = new World();
  world.add(box({ type: 'static', position: { x: 0, y: 0.5 }, width: 200, height: 1 }));
  for (let row = 0; row < 20; row++) {
    for (let i = 0; i < 30; i++) {
      world.add(
        box({
          position: { x: -40 + i * 1.05 + (row % 2) * 0.5, y: -0.5 - row * 1.01 },
          width: 1,
          height: 1,
        }),
      );
    }
  }
  for (let c = 0; c < 40; c++) {
    const x = 5 + c * 2;
    let previous: Body = world.add(
      box({ type: 'static', position: { x, y: -30 }, width: 0.2, height: 0.2 }),
    );
    for (let k = 0; k < 10; k++) {
      const link = world.add(
        box({ position: { x: x + 0.5 * k + 0.25, y: -30 }, width: 0.5, height: 0.1 }),
      );
      world.addJoint(
        revoluteJoint({ bodyA: previous, bodyB: link, anchor: { x: x + 0.5 * k, y: -30 } }),
      );
      previous = link;
    }
  }
  return world;
}

function median(values: number[]): number {
  const sorted = [...values].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 === 1 ? sorted[mid]! : (sorted[mid - 1]! + sorted[mid]!) / 2;
}

/** Times the four operations `rounds` times each, interleaved, after `stepsBefore` steps. */
export function measureSnapshots(stepsBefore: number, rounds: number): SnapshotReport {
  const world = rollbackWorld();
  for (let i = 0; i < stepsBefore; i++) world.step(1 / 60);
  const take: number[] = [];
  const restore: number[] = [];
  const stringify: number[] = [];
  const parse: number[] = [];
  let jsonBytes = 0;
  let contacts = 0;
  // One untimed round first: the first call of each compiles it.
  for (let r = -1; r < rounds; r++) {
    let t = performance.now();
    const snapshot = takeSnapshot(world);
    const took = performance.now() - t;
    t = performance.now();
    const text = JSON.stringify(snapshot);
    const stringified = performance.now() - t;
    t = performance.now();
    const parsed = JSON.parse(text) as typeof snapshot;
    const parsedMs = performance.now() - t;
    t = performance.now();
    const copy = restoreSnapshot(parsed);
    const restored = performance.now() - t;
    if (copy.bodies.length !== world.bodies.length) throw new Error('the copy lost bodies');
    jsonBytes = Buffer.byteLength(text);
    contacts = snapshot.contacts.length;
    if (r < 0) continue;
    take.push(took);
    stringify.push(stringified);
    parse.push(parsedMs);
    restore.push(restored);
  }
  return {
    bodies: world.bodies.filter((b) => b.type === 'dynamic').length,
    joints: world.joints.length,
    contacts,
    stepsBefore,
    rounds,
    takeMedianMs: median(take),
    restoreMedianMs: median(restore),
    stringifyMedianMs: median(stringify),
    parseMedianMs: median(parse),
    jsonBytes,
  };
}
