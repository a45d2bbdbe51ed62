import type { Body, World } from '@physical/engine';

/** What the browser check reads from a consumer page. */
export interface PageProbe {
  /** y (m) when the page set the world up, before any frame ran. */
  startY: number;
  y(): number;
  x(): number;
  collisions(): number;
  screenPoint(): { x: number; y: number; taps: number };
}

declare global {
  interface Window {
    probe?: PageProbe;
  }
}

/** Counts the body's collision events and lets the browser check read its state. */
export function expose(
  _world: World,
  body: Body,
  screenPoint: () => { x: number; y: number; taps: number },
): void {
  if (window.probe !== undefined) return; // React renders again: keep the first probe
  let collisions = 0;
  body.on('collision', () => collisions++);
  window.probe = {
    startY: body.position.y,
    y: () => body.position.y,
    x: () => body.position.x,
    collisions: () => collisions,
    screenPoint,
  };
}
