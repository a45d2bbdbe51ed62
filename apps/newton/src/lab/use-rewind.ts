import type { World } from '@physical/engine';
import { useCallback, useEffect, useMemo, useRef, useState } from 'react';
import { STEP, simulatedTime } from '../app/use-simulation.ts';
import { MeasurementLog, type Quantity } from './measurement-log.ts';
import { SnapshotHistory } from './snapshot-history.ts';
import { observeSteps } from './step-hook.ts';

/** One measured value of a moment: a CSV cell. */
export type Measured = Quantity & { readonly value: number };

/** Options of {@link useRewind}. */
export interface RewindOptions<Data> {
  /**
   * The screen's worlds, each stepped by its own canvas, in a fixed order (Forces: one per
   * track); null before the first is built. Keep the array's identity while the worlds stay.
   */
  readonly worlds: readonly World[] | null;
  /** What the screen must restore beside world `index` at the moment just stepped to. */
  readonly data: (index: number) => Data;
  /** Called just before each step of world `index` (e.g. to keep the velocity for Δv / Δt). */
  readonly before?: (index: number) => void;
  /**
   * Called just after each step of world `index`, before the moment is saved (e.g. Reactions'
   * collision record, which the saved moment keeps).
   */
  readonly after?: (index: number) => void;
  /** What world `index` measures at the moment just stepped to (and at the first moment). */
  readonly measure: (index: number) => readonly Measured[];
  /**
   * Makes the restored worlds the screen's: new worlds (the snapshot keeps no listeners and no
   * app objects), with the data saved beside each; `time` (s) is the moment shown.
   */
  readonly adopt: (worlds: readonly World[], data: readonly Data[], time: number) => void;
  /**
   * Puts back on world `index`, before a replayed step, what the screen sets before each step
   * and keeps in that step's data (e.g. Reactions' tilt): such changes need no snapshot of
   * their own, unlike those reported with `changed`.
   */
  readonly replay?: (world: World, data: Data, index: number) => void;
  /** Pauses the simulation (a seek stops at the moment sought). */
  readonly pause: () => void;
  /** Steps kept per world. Default 600: the last 10 s at 60 steps a second. */
  readonly capacity?: number;
  /** A world snapshot every this many steps (the steps between are replayed). Default 10. */
  readonly interval?: number;
}

/** What {@link useRewind} gives a screen: the rewind bar's state, the seek, the log. */
export interface Rewind {
  /** Saved moments the rewind bar runs over (read afresh at each access). */
  readonly length: number;
  /** The moment shown: `length - 1` unless stepped back (read afresh at each access). */
  readonly index: number;
  /** Whether a moment before the newest is shown (playing on starts a new future there). */
  readonly rewound: boolean;
  /** Simulated time (s) of a saved moment. */
  timeAt(index: number): number;
  /** Goes to the saved moment `index`, paused: every world restored to that time. */
  seek(index: number): void;
  /** What was measured, step by step, for the CSV. */
  readonly log: MeasurementLog;
  /** Forgets everything saved: a new scene is coming (its first moment is saved when it shows). */
  clear(): void;
  /** The worlds as they are now are the new start (e.g. forces were just switched on at t = 0). */
  restart(): void;
  /**
   * Says the screen changed its worlds between two steps (a force on or off, a push, a body
   * returned, a setting): the next saved moment gets a snapshot of its own, since replaying the
   * steps from an earlier one would miss the change. Call it after every such change.
   */
  changed(): void;
  /** `length` and `index` as a short text: a live part's watch key. */
  key(): string;
}

/**
 * Step back, scrub and measure, for any screen: one {@link SnapshotHistory} per world and one
 * {@link MeasurementLog}, filled around every step of the screen's worlds (whoever steps them:
 * the canvases' frame loops or the Step button). A seek restores every world to the sought time
 * and hands the new worlds to the screen's `adopt`; the next step of any world forgets the saved
 * future (histories, log). Worlds stepped by separate canvases may be a step apart: the rewind
 * bar runs over the world that got furthest, and the others restore to their newest moment at
 * or before its time.
 */
export function useRewind<Data>(options: RewindOptions<Data>): Rewind {
  const { worlds, capacity = 600, interval = 10 } = options;
  const optionsRef = useRef(options);
  optionsRef.current = options;
  const histories = useRef<SnapshotHistory<Data>[]>([]);
  const log = useMemo(() => new MeasurementLog(), []);
  /** The time (s) stepped back to, or null when live at the newest moment. */
  const [rewoundAt, setRewoundAt] = useState<{ index: number; time: number } | null>(null);
  const rewoundRef = useRef(rewoundAt);
  rewoundRef.current = rewoundAt;

  const history = useCallback(
    (index: number): SnapshotHistory<Data> =>
      (histories.current[index] ??= new SnapshotHistory<Data>({ capacity, interval, step: STEP })),
    [capacity, interval],
  );

  /** The history the rewind bar runs over: the one whose newest moment is latest. */
  const clock = (): SnapshotHistory<Data> | undefined => {
    let best: SnapshotHistory<Data> | undefined;
    for (const item of histories.current) {
      if (best === undefined || (item.last?.time ?? -1) > (best.last?.time ?? -1)) best = item;
    }
    return best;
  };

  const save = useCallback(
    (world: World, index: number): void => {
      const { data, measure } = optionsRef.current;
      const time = simulatedTime(world);
      history(index).record(world, time, data(index));
      log.add(time, measure(index));
    },
    [history, log],
  );

  const clear = useCallback((): void => {
    for (const item of histories.current) item.clear();
    log.clear();
    rewoundRef.current = null;
    setRewoundAt(null);
  }, [log]);

  const changed = useCallback((): void => {
    for (const item of histories.current) item.markChanged();
  }, []);

  // Around every step of each world: forget a rewritten future, then save the new moment.
  useEffect(() => {
    if (worlds === null) return;
    const offs = worlds.map((world, index) => {
      // The first moment of a new scene (a restored one already has its past).
      if (history(index).length === 0) save(world, index);
      return observeSteps(world, {
        before: () => {
          const rewound = rewoundRef.current;
          if (rewound !== null) {
            for (const item of histories.current) item.truncateAfter(item.indexAt(rewound.time));
            log.truncateAfter(rewound.time);
            rewoundRef.current = null;
            setRewoundAt(null);
          }
          optionsRef.current.before?.(index);
        },
        after: () => {
          optionsRef.current.after?.(index);
          save(world, index);
        },
      });
    });
    return () => {
      for (const off of offs) off();
    };
  }, [worlds, history, save, log]);

  const seek = (target: number): void => {
    const main = clock();
    if (main === undefined || main.length === 0 || worlds === null) return;
    const index = Math.min(main.length - 1, Math.max(0, target));
    const time = main.entry(index)!.time;
    const { adopt, pause, replay } = optionsRef.current;
    pause();
    const restored = worlds.map((_world, i) => {
      const item = history(i);
      return item.restore(
        Math.max(0, item.indexAt(time)),
        replay === undefined ? undefined : (world, data) => replay(world, data, i),
      );
    });
    const next = { index, time };
    rewoundRef.current = next;
    setRewoundAt(next);
    adopt(
      restored.map((item) => item.world),
      restored.map((item) => item.entry.data),
      time,
    );
  };

  return {
    get length() {
      return clock()?.length ?? 0;
    },
    get index() {
      return rewoundRef.current?.index ?? Math.max(0, (clock()?.length ?? 0) - 1);
    },
    rewound: rewoundAt !== null,
    timeAt: (index) => clock()?.entry(index)?.time ?? 0,
    seek,
    log,
    clear,
    restart: () => {
      clear();
      worlds?.forEach((world, index) => save(world, index));
    },
    changed,
    key: () => `${clock()?.length ?? 0}:${rewoundRef.current?.index ?? -1}`,
  };
}
