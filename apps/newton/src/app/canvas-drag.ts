/** A point in the world (m). */
interface Point {
  readonly x: number;
  readonly y: number;
}

/** What a screen does with a drag that starts on something of its own over the canvas. */
export interface CanvasDrag {
  /**
   * A press at `point` (world m): true to take this pointer's drag, which the canvas then never
   * sees (a tap elsewhere still adds or chooses). Only one drag at a time is taken.
   */
  readonly press: (point: Point) => boolean;
  /** The taken pointer moved to `point`. */
  readonly move: (point: Point) => void;
  /** The taken pointer was lifted or cancelled. */
  readonly release: () => void;
}

/**
 * Listens on `host` (the canvas's container) in the capture phase, before the canvas's own
 * handlers, for the drags `drag.press` takes: the pointer is captured and its events stop at
 * `host`. `toWorld` turns a page point into the world's (undefined without a canvas). Returns
 * the remover. Inertia's push and Reactions' velocity handles share it.
 */
export function listenToCanvasDrags(
  host: HTMLElement,
  toWorld: (clientX: number, clientY: number) => Point | undefined,
  drag: CanvasDrag,
): () => void {
  let pointer: number | null = null;
  const onDown = (event: PointerEvent): void => {
    if (pointer !== null) return;
    const point = toWorld(event.clientX, event.clientY);
    if (point === undefined || !drag.press(point)) return;
    pointer = event.pointerId;
    host.setPointerCapture(event.pointerId);
    event.preventDefault();
    event.stopPropagation();
  };
  const onMove = (event: PointerEvent): void => {
    if (event.pointerId !== pointer) return;
    event.stopPropagation();
    const point = toWorld(event.clientX, event.clientY);
    if (point !== undefined) drag.move(point);
  };
  const onUp = (event: PointerEvent): void => {
    if (event.pointerId !== pointer) return;
    event.stopPropagation();
    pointer = null;
    drag.release();
  };
  host.addEventListener('pointerdown', onDown, true);
  host.addEventListener('pointermove', onMove, true);
  host.addEventListener('pointerup', onUp, true);
  host.addEventListener('pointercancel', onUp, true);
  return () => {
    host.removeEventListener('pointerdown', onDown, true);
    host.removeEventListener('pointermove', onMove, true);
    host.removeEventListener('pointerup', onUp, true);
    host.removeEventListener('pointercancel', onUp, true);
  };
}
