import { useEffect, useState } from 'react';

/**
 * A world in a worker (a `WorkerWorld` of `@physical/worker`) for a component's lifetime:
 * `create` makes it on mount (in the browser only), `setup` fills it, and unmounting terminates
 * it. Null until mounted (and during server rendering). Pass it to `<PhysicalCanvas world={world} />`.
 *
 * ```tsx
 * const world = useWorkerWorld(
 *   () => new WorkerWorld(new Worker(new URL('./physics.worker.ts', import.meta.url), { type: 'module' })),
 *   (world) => world.add({ kind: 'box', width: 1, height: 1 }),
 * );
 * return <PhysicalCanvas world={world} />;
 * ```
 *
 * `create` and `setup` are read once, at mount (StrictMode's second mount makes a fresh worker
 * after terminating the first).
 */
export function useWorkerWorld<W extends { terminate(): void }>(
  create: () => W,
  setup?: (world: W) => void,
): W | null {
  const [world, setWorld] = useState<W | null>(null);
  useEffect(() => {
    const created = create();
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
