import type { Body, Vec2 } from '@physical/engine';
import type { ResolvedBodyStyle } from './body-style.ts';
import type { DebugOverlays } from './debug-overlays.ts';
import type { DrawingSource } from './drawing-source.ts';
import type { CollisionArrowView } from './draw-collision-arrows.ts';
import type { Pose } from './pose.ts';
import type { Viewport } from './viewport.ts';

/** A point of a body held by a pointer: `local` (body frame, m) pulled to `target` (world, m). */
export interface HeldPoint {
  readonly body: Body;
  readonly local: Readonly<Vec2>;
  readonly target: Readonly<Vec2>;
}

/**
 * What a frame draws: a read-only view of the world with the poses to draw each body at and its
 * style. The draw functions take it and a context and nothing else (no DOM, no timing).
 */
export interface Scene {
  readonly viewport: Viewport;
  /** Background colour, or `'transparent'`. */
  readonly background: string;
  /** The world, for contact overlays; null draws only the background. */
  readonly world: DrawingSource | null;
  /** The bodies, as `world.bodies`. */
  readonly bodies: readonly Body[];
  /** The pose to draw `bodies[index]` at (interpolated). Writes and returns `out`. */
  poseOf(body: Body, index: number, out: Pose): Pose;
  /** The style of a body. */
  styleOf(body: Body): ResolvedBodyStyle;
  /** Debug overlays to draw. */
  readonly debug: DebugOverlays;
  /** Collision-force arrows to draw (already faded). */
  readonly collisionArrows: readonly CollisionArrowView[];
  /** Metres of arrow per newton for collision forces. */
  readonly forceScale: number;
  /** Seconds of motion a velocity arrow shows (its length is speed times this). */
  readonly velocityScale: number;
  /** Points held by pointers (the canvas's drag), drawn as joints after the world's. */
  readonly held?: readonly HeldPoint[];
  /** Whether the display should avoid decorative motion (prefers-reduced-motion). */
  readonly reducedMotion: boolean;
}
