import type { CollisionLike, DrawingSource } from '../draw/drawing-source.ts';

/** What a {@link WorldSubscription} reports to its element. */
export interface WorldListener {
  /** A body woke, joined or left: a frame is needed. */
  changed(): void;
  /** A collision of the last step (only while collisions are asked for). */
  collided(event: CollisionLike): void;
}

/**
 * The element's listeners on its world, held only while it is connected, so a detached element
 * keeps no world alive and costs the engine nothing.
 */
export class WorldSubscription {
  private offs: (() => void)[] = [];
  private readonly onChange: () => void;
  private readonly onCollision: (event: CollisionLike) => void;

  constructor(listener: WorldListener) {
    this.onChange = () => listener.changed();
    this.onCollision = (event) => listener.collided(event);
  }

  /**
   * Listens to `world` (nothing with null); collision events only when `collisions` is true,
   * since the engine builds them only for listeners (a worker world records them in the worker
   * only while someone listens, and sends them with the step's poses). Does nothing while
   * already listening.
   */
  start(world: DrawingSource | null, collisions: boolean): void {
    if (world === null || this.offs.length > 0) return;
    this.offs.push(
      world.on('wake', this.onChange),
      world.on('bodyAdded', this.onChange),
      world.on('bodyRemoved', this.onChange),
    );
    if (collisions) {
      this.offs.push(world.on('collision', this.onCollision));
    }
  }

  /** Removes every listener. */
  stop(): void {
    for (const off of this.offs) off();
    this.offs = [];
  }
}
