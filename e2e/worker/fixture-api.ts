// What the worker fixture page exposes to the tests as `window.physicalWorker`.
import { PhysicalError, World, box, particle, wall } from '@physical/engine';
import { define } from '@physical/canvas';
import { WorkerWorld, worldStateHash, type WorkerWorldOptions } from '@physical/worker';

/** The exports the tests build scenes with, in the page. */
export const workerApi = {
  PhysicalError,
  World,
  WorkerWorld,
  box,
  particle,
  wall,
  define,
  worldStateHash,
  /** A WorkerWorld in a new module worker (the fixture's physics.worker.ts). */
  createWorkerWorld(options?: WorkerWorldOptions): WorkerWorld {
    const worker = new Worker(new URL('./physics.worker.ts', import.meta.url), { type: 'module' });
    return new WorkerWorld(worker, options);
  },
  /** A WorkerWorld whose worker throws an uncaught error 100 ms after starting. */
  createCrashingWorkerWorld(): WorkerWorld {
    const worker = new Worker(new URL('./crash.worker.ts', import.meta.url), { type: 'module' });
    return new WorkerWorld(worker);
  },
};

declare global {
  interface Window {
    physicalWorker: typeof workerApi;
  }
}
