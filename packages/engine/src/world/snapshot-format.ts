import type { BroadPhase } from '../collision/broad-phase.ts';
import type { Body } from '../dynamics/body.ts';
import type { ContactManager } from '../dynamics/contact-manager.ts';
import type { Islands } from '../dynamics/island.ts';
import type { Sensors } from '../dynamics/sensor.ts';
import type { Shape } from '../dynamics/shape.ts';
import type { ShapeTable } from '../dynamics/shape-table.ts';
import type { Joint } from '../dynamics/joints/joint.ts';
import type { SnapshotValue } from './snapshot-values.ts';
import type { ResolvedWorldOptions } from './world-options.ts';
import type { World } from './world.ts';

// The snapshot's format: its name, version and sections, and the parts of a world that saving
// (snapshot-save.ts) and loading (snapshot-load.ts) reach.

/** The format name every snapshot carries. */
export const SNAPSHOT_FORMAT = 'physical-world';
/**
 * The snapshot layout this version writes. It also reads version 1, whose contacts lack the
 * count of steps in a row they bounced (read as 0).
 */
export const SNAPSHOT_VERSION = 2;

/**
 * A saved world ({@link takeSnapshot}): plain data, safe for `JSON.stringify`. Its sections are
 * `settings`, `world` (counters), `bodies` (with their shapes and forces), `contacts`, `sensors`,
 * `broadPhase` and `joints`. Treat the contents as opaque: the layout may change with `version`.
 */
export interface WorldSnapshot {
  readonly format: typeof SNAPSHOT_FORMAT;
  readonly version: 1 | typeof SNAPSHOT_VERSION;
  readonly settings: Readonly<Record<string, SnapshotValue>>;
  readonly world: Readonly<Record<string, SnapshotValue>>;
  readonly bodies: readonly Readonly<Record<string, SnapshotValue>>[];
  readonly contacts: readonly Readonly<Record<string, SnapshotValue>>[];
  readonly sensors: readonly Readonly<Record<string, SnapshotValue>>[];
  readonly broadPhase: Readonly<Record<string, SnapshotValue>>;
  /** The joints, in `world.joints` order, their bodies named by index in `bodies`. */
  readonly joints: readonly Readonly<Record<string, SnapshotValue>>[];
}

/** @internal The parts of a world a snapshot reads and writes. */
export interface WorldInternals {
  readonly world: World;
  readonly settings: ResolvedWorldOptions;
  readonly bodies: Body[];
  readonly joints: Joint[];
  readonly broadPhase: BroadPhase;
  readonly islands: Islands;
  readonly contactManager: ContactManager;
  readonly sensors: Sensors;
  readonly shapesById: (Shape | null)[];
  readonly shapeTable: ShapeTable;
  readonly freeShapeIds: number[];
  /** Moves a loaded body's numbers into the world's body memory at world index `index`. */
  placeBody(body: Body, index: number): void;
  /** Writes a body's shape chain (WorldMembership.linkShapes) once its shapes have their rows. */
  linkShapes(body: Body): void;
  nextBodyId: number;
  stepCount: number;
  lastStep: number;
}
