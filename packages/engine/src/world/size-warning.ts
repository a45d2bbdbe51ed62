import { MAX_MOVING_SIZE, MIN_MOVING_SIZE } from '../core/constants.ts';
import { isDevelopment } from '../core/development.ts';
import type { Body } from '../dynamics/body.ts';

// Every engine host has a console; the engine compiles without DOM or Node types.
declare const console: { warn(message: string): void };

/**
 * Development builds only: warns, once per world, when a moving (dynamic or kinematic) body is
 * added whose largest extent lies outside {@link MIN_MOVING_SIZE}..{@link MAX_MOVING_SIZE} m,
 * the range the solver is tuned for (Box2D's unit guidance). An 80 m box is most often 80
 * pixels passed as metres. Static bodies (walls, floors) may be any size.
 */
export class SizeWarning {
  private warned = false;

  /** Checks a body joining the world (not on the step's path). */
  check(body: Body): void {
    if (this.warned || body.type === 'static' || !isDevelopment()) return;
    let minX = Infinity;
    let minY = Infinity;
    let maxX = -Infinity;
    let maxY = -Infinity;
    for (const shape of body.shapes) {
      const box = shape.computeAABB(body.transform);
      minX = Math.min(minX, box.minX);
      minY = Math.min(minY, box.minY);
      maxX = Math.max(maxX, box.maxX);
      maxY = Math.max(maxY, box.maxY);
    }
    const size = Math.max(maxX - minX, maxY - minY);
    if (!(size < MIN_MOVING_SIZE || size > MAX_MOVING_SIZE)) return;
    this.warned = true;
    const hint =
      size > MAX_MOVING_SIZE
        ? ' Sizes are metres: if this is pixels, divide by your pixels per metre (<physical-canvas> draws 50 px per metre by default).'
        : '';
    console.warn(
      `Physical: a ${body.type} body ${Number(size.toPrecision(3))} m across; the solver is tuned for moving bodies of ${MIN_MOVING_SIZE} to ${MAX_MOVING_SIZE} m.${hint} (Shown once per world, in development builds only.)`,
    );
  }
}
