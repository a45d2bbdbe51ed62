import { PhysicalError } from '../core/errors.ts';
import { loadWorld } from './snapshot-load.ts';
import { saveWorld } from './snapshot-save.ts';
import type { WorldSnapshot } from './snapshot-format.ts';
import { describe } from './snapshot-values.ts';
import { World } from './world.ts';

// World snapshots: everything that decides future steps, as plain JSON-compatible data, so that
// restoring and stepping gives bit-for-bit the states of never having saved.
//
// What that takes beyond the bodies' poses and velocities: the exact transform (cosine and sine
// are not recomputed from the angle: the solver integrates them), the centre of mass and the
// step-start pose, sleep timers and island stamps, forces with the time they have left, every
// contact in list order with its manifold, warm-start impulses and reuse cache, each body's
// contact list order (removals swap-remove through it), the broad phase's three trees node by
// node (their shape decides the order in which new pairs, hence contacts, are found), shape ids
// and the free-id stack, the sensors' overlap lists, the step counters, and every joint in list
// order with its frames, settings and warm-start impulses (joint-snapshot.ts). Numbers are
// written as snapshot-values.ts describes (-0 and infinities survive JSON).
//
// Not saved: listeners, userData and the Force objects an app holds (the restored world has new
// ones, in the same order: world.bodies[i] is the body that was at i, body.forces[j] and
// world.joints[k] likewise).
//
// takeSnapshot and restoreSnapshot are free functions, not World methods, so that an app that
// never calls them bundles neither this code nor every joint kind joint-snapshot.ts imports.
//
// The files: snapshot-format.ts (format name, version, sections), snapshot-save.ts (saving),
// snapshot-load.ts (loading and the cross-references), snapshot-read-body.ts (settings, bodies,
// shapes, forces), joint-snapshot.ts (joints), snapshot-values.ts (numbers and checked readers).

export type { SnapshotNumber, SnapshotValue } from './snapshot-values.ts';
export { SNAPSHOT_FORMAT, SNAPSHOT_VERSION, type WorldSnapshot } from './snapshot-format.ts';

/**
 * Saves everything that decides the world's future as plain, JSON-compatible data: restoring it
 * with {@link restoreSnapshot} and stepping gives bit-for-bit the states this world reaches.
 * Listeners, `userData` and the app's Force objects are not saved. Not allowed during a step:
 * from a listener it throws a PhysicalError.
 *
 * @example
 * const saved = JSON.stringify(takeSnapshot(world));
 * // later, or elsewhere
 * const copy = restoreSnapshot(JSON.parse(saved));
 */
export function takeSnapshot(world: World): WorldSnapshot {
  if (!(world instanceof World)) {
    throw new PhysicalError('world', `must be a World, got ${describe(world)}.`);
  }
  if (world.isStepping) {
    throw new PhysicalError(
      'snapshot',
      'cannot be taken while the world is stepping (from a listener); take it after step().',
    );
  }
  return saveWorld(world.internals());
}

/**
 * A new world from a {@link takeSnapshot} result (a parsed JSON copy is fine), its bodies in the
 * saved order. Checks the whole snapshot first: a wrong format or version, a missing or
 * non-numeric field or a broken reference throws a PhysicalError naming the field
 * (`snapshot.bodies[2].angle`), and no world is returned.
 *
 * @example
 * const checkpoint = takeSnapshot(world);
 * world.step();
 * const rewound = restoreSnapshot(checkpoint); // the world as it was before that step
 */
export function restoreSnapshot(snapshot: WorldSnapshot): World {
  const world = new World();
  loadWorld(world.internals(), snapshot);
  return world;
}
