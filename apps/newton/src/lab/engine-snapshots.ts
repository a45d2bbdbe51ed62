import { restoreSnapshot, takeSnapshot } from '@physical/engine';
import type { WorldSnapshots } from './snapshot-history.ts';

/** The engine's snapshots, for a {@link SnapshotHistory} or `useRewind`'s `snapshots`. */
export const ENGINE_SNAPSHOTS: WorldSnapshots = { take: takeSnapshot, restore: restoreSnapshot };
