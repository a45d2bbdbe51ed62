// @physical/dom's public API. Everything not listed here is internal.

export { PhysicalUI } from './physical-ui.ts';
export type { ElementState, PhysicalUIOptions, ReducedMotionPolicy } from './physical-ui.ts';
export { DRAG_SLOP } from './drag-input.ts';
