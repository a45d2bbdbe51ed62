// @physical/react's public API. Everything not listed here is internal.
// Physical UI (<PhysicalContainer>, usePhysicalUI) lives in the `@physical/react/ui` entry
// (src/ui.ts), so apps that only draw a world never load, or need to install, @physical/dom.

export { PhysicalCanvas } from './physical-canvas.ts';
export type { PhysicalCanvasProps } from './physical-canvas.ts';
export { useWorkerWorld } from './use-worker-world.ts';
