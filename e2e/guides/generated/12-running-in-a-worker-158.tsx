import { PhysicalCanvas, useWorkerWorld } from '@physical/react';
import { WorkerWorld } from '@physical/worker';

export function Pile() {
  const world = useWorkerWorld(
    () =>
      new WorkerWorld(
        new Worker(new URL('./physics.worker.ts', import.meta.url), { type: 'module' }),
      ),
    (world) => {
      world.add({ kind: 'wall', from: { x: 0, y: 7 }, to: { x: 10, y: 7 } });
      for (let i = 0; i < 500; i++) {
        world.add({
          kind: 'box',
          width: 0.3,
          height: 0.3,
          position: { x: 1 + (i % 25) * 0.33, y: 6 - Math.floor(i / 25) * 0.33 },
        });
      }
    },
  );
  // The element is 300 px tall unless told: give it the screen, and frame the floor.
  return (
    <PhysicalCanvas
      world={world}
      fit="contain"
      viewBox={{ x: 0, y: 0, width: 10, height: 8 }}
      style={{ height: '100vh' }}
    />
  );
}