// @physical/react's public API. Everything not listed here is internal.

export { PhysicalCanvas } from './physical-canvas.ts';
export type { PhysicalCanvasProps } from './physical-canvas.ts';
