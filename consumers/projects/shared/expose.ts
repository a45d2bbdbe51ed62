import type { Body, World } from '@physical/engine';

/** What the browser check reads from a consumer page. */
export interface PageProbe {
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
  let collisions = 0;
  body.on('collision', () => collisions++);
  window.probe = {
    y: () => body.position.y,
    x: () => body.position.x,
    collisions: () => collisions,
    screenPoint,
  };
}
