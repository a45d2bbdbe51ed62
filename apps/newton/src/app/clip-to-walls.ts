/**
 * Saves the context and clips it to the walls' box, `width` x `height` metres from the origin
 * (the context is in world metres), so arrows end at the walls instead of poking past them.
 * Pair it with `context.restore()`.
 */
export function clipToWalls(
  context: CanvasRenderingContext2D,
  width: number,
  height: number,
): void {
  context.save();
  context.beginPath();
  context.rect(0, 0, width, height);
  context.clip();
}
