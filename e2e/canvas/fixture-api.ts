// What the fixture page exposes to the tests as `window.physical`.
import { Body, World, box, distanceJoint, particle, wall } from '@physical/engine';
import { ManualFrameScheduler, PhysicalCanvasElement, define } from '@physical/canvas';

/** The engine and canvas exports the tests build scenes with, in the page. */
export const physicalApi = {
  Body,
  World,
  box,
  distanceJoint,
  particle,
  wall,
  ManualFrameScheduler,
  PhysicalCanvasElement,
  define,
};

declare global {
  interface Window {
    physical: typeof physicalApi;
    /** requestAnimationFrame calls made so far (counted by an init script in some tests). */
    frameRequests?: number;
  }
}
