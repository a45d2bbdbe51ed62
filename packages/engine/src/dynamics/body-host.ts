import type { Body } from './body.ts';
import type { Shape } from './shape.ts';

/**
 * What bodies and shapes tell the world that holds them, and all they may ask of it: the one
 * interface through which dynamics calls up into the world at run time (the World implements
 * it). A body outside a world has no host and keeps its changes to itself.
 */
export interface BodyHost {
  /** A body was moved by hand (teleport): its boxes follow and it wakes. */
  bodyMoved(body: Body): void;
  /** Wakes the body and its island. */
  wakeBody(body: Body): void;
  /** Puts the body's island to sleep. */
  sleepBody(body: Body): void;
  /** Throws a PhysicalError naming `what` while the world steps (shapes cannot change then). */
  requireUnlocked(what: string): void;
  /** A shape joined a body of the world. */
  shapeAdded(shape: Shape): void;
  /** A shape is leaving a body of the world. */
  shapeRemoved(shape: Shape): void;
  /** A shape's collision filter changed. */
  shapeFilterChanged(shape: Shape): void;
}
