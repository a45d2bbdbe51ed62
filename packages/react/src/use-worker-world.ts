import { WorkerWorld, type WorkerWorldOptions } from '@physical/worker';
import { useEffect, useState } from 'react';

/**
 * A {@link WorkerWorld} for a component's lifetime: `createWorker` starts the worker on mount
 * (in the browser only), `setup` fills the world, and unmounting terminates it. Null until
 * mounted (and during server rendering). Pass the world to `<PhysicalCanvas world={world} />`.
 *
 * ```tsx
 * const world = useWorkerWorld(
 *   () => new Worker(new URL('./physics.worker.ts', import.meta.url), { type: 'module' }),
 *   (world) => world.add({ kind: 'box', width: 1, height: 1 }),
 * );
 * return <PhysicalCanvas world={world} />;
 * ```
 *
 * `createWorker`, `setup` and `options` are read once, at mount (StrictMode's second mount makes
 * a fresh worker after terminating the first).
 */
export function useWorkerWorld(
  createWorker: () => Worker,
  setup?: (world: WorkerWorld) => void,
  options?: WorkerWorldOptions,
): WorkerWorld | null {
  const [world, setWorld] = useState<WorkerWorld | null>(null);
  useEffect(() => {
    const created = new WorkerWorld(createWorker(), options);
    setup?.(created);
    setWorld(created);
    return () => {
      created.terminate();
      setWorld(null);
    };
    // Read once at mount, as documented.
  }, []);
  return world;
}
