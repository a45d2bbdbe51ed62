import { box, type Body, type World } from '@physical/engine';

/** Thickness of each wall (m): thick, so nothing fast tunnels through an edge. */
const THICKNESS = 1;

/**
 * The container's four edges as static walls around a `width` x `height` rectangle (m) whose
 * top-left corner is the world origin. Rebuilt when the container resizes.
 */
export class ContainerWalls {
  private bodies: Body[] = [];

  /** Replaces the walls with ones around a `width` x `height` (m) rectangle. */
  rebuild(world: World, width: number, height: number, friction: number): void {
    this.remove(world);
    if (!(width > 0) || !(height > 0)) return;
    const t = THICKNESS;
    const wall = (x: number, y: number, w: number, h: number): Body =>
      world.add(box({ type: 'static', position: { x, y }, width: w, height: h, friction }));
    this.bodies = [
      wall(width / 2, height + t / 2, width + 2 * t, t), // floor
      wall(width / 2, -t / 2, width + 2 * t, t), // ceiling
      wall(-t / 2, height / 2, t, height + 2 * t), // left
      wall(width + t / 2, height / 2, t, height + 2 * t), // right
    ];
  }

  /** Takes the walls out of the world. */
  remove(world: World): void {
    for (const body of this.bodies) if (world.has(body)) world.remove(body);
    this.bodies = [];
  }
}
