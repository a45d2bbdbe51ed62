// @physical/react's public API. Everything not listed here is internal.

export { PhysicalCanvas } from './physical-canvas.ts';
export type { PhysicalCanvasProps } from './physical-canvas.ts';
export { PhysicalContainer, usePhysicalUI } from './physical-ui.ts';
export type { PhysicalContainerProps } from './physical-ui.ts';
export { useWorkerWorld } from './use-worker-world.ts';
