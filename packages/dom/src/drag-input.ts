import { PointerVelocity } from '@physical/canvas';

/**
 * A press becomes a drag once the pointer moves this far (client CSS px) from where it went
 * down; anything shorter is a click and reaches the element untouched.
 */
export const DRAG_SLOP = 4;

/** A click arriving this long (ms) after a drag's release belongs to the drag and is dropped. */
const CLICK_AFTER_DRAG_MS = 500;

/** What {@link DragInput} asks of its owner. */
export interface DragHost {
  /** The physical element a pointer pressed (the target or its ancestor), or null. */
  elementAt(target: EventTarget | null): HTMLElement | null;
  /** True when drags may start (motion allowed). */
  canDrag(): boolean;
  /** A press became a drag at client (x, y); returns false to refuse it. */
  dragStart(pointerId: number, element: HTMLElement, clientX: number, clientY: number): boolean;
  /** The dragging pointer moved. */
  dragMove(pointerId: number, clientX: number, clientY: number): void;
  /** The dragging pointer let go, moving at (vx, vy) client px/s (0 when cancelled). */
  dragEnd(pointerId: number, vx: number, vy: number): void;
}

interface Press {
  readonly element: HTMLElement;
  readonly startX: number;
  readonly startY: number;
  dragging: boolean;
  readonly velocity: PointerVelocity;
}

/**
 * Pointer, touch and pen input on the physical elements: each pointer is tracked on its own (so
 * several fingers drag several elements). A press that moves less than {@link DRAG_SLOP} stays a
 * plain click; beyond it the pointer is captured, the press becomes a drag, and the click that
 * the release would send is suppressed, once.
 */
export class DragInput {
  private readonly host: DragHost;
  private readonly presses = new Map<number, Press>();
  private container: HTMLElement | null = null;
  private listening = false;
  private suppressClickUntil = -1;
  private readonly velocity = { x: 0, y: 0 };

  constructor(host: DragHost) {
    this.host = host;
  }

  /** Starts listening for presses inside `container`. */
  attach(container: HTMLElement): void {
    this.detach();
    this.container = container;
    container.addEventListener('pointerdown', this.onDown);
    container.addEventListener('selectstart', this.onSelectStart);
    container.addEventListener('dragstart', this.onSelectStart);
    window.addEventListener('click', this.onClick, true);
  }

  /** Stops listening; drags in progress end without a throw. */
  detach(): void {
    const container = this.container;
    if (container === null) return;
    for (const [pointerId, press] of this.presses) {
      if (press.dragging) this.host.dragEnd(pointerId, 0, 0);
    }
    this.presses.clear();
    this.listen(false);
    container.removeEventListener('pointerdown', this.onDown);
    container.removeEventListener('selectstart', this.onSelectStart);
    container.removeEventListener('dragstart', this.onSelectStart);
    window.removeEventListener('click', this.onClick, true);
    this.container = null;
  }

  /** Ends every drag (motion was turned off), without a throw. */
  cancelAll(): void {
    for (const [pointerId, press] of this.presses) {
      if (press.dragging) this.host.dragEnd(pointerId, 0, 0);
    }
    this.presses.clear();
    this.listen(false);
  }

  /** True while `element` is being dragged by some pointer. */
  isDragging(element: HTMLElement): boolean {
    for (const press of this.presses.values()) {
      if (press.dragging && press.element === element) return true;
    }
    return false;
  }

  private listen(on: boolean): void {
    if (on === this.listening) return;
    this.listening = on;
    if (on) {
      window.addEventListener('pointermove', this.onMove, true);
      window.addEventListener('pointerup', this.onUp, true);
      window.addEventListener('pointercancel', this.onCancel, true);
    } else {
      window.removeEventListener('pointermove', this.onMove, true);
      window.removeEventListener('pointerup', this.onUp, true);
      window.removeEventListener('pointercancel', this.onCancel, true);
    }
  }

  private readonly onDown = (event: PointerEvent): void => {
    if (event.pointerType === 'mouse' && event.button !== 0) return;
    if (!this.host.canDrag()) return;
    const element = this.host.elementAt(event.target);
    if (element === null) return;
    const velocity = new PointerVelocity();
    velocity.add(event.timeStamp, event.clientX, event.clientY);
    this.presses.set(event.pointerId, {
      element,
      startX: event.clientX,
      startY: event.clientY,
      dragging: false,
      velocity,
    });
    this.suppressClickUntil = -1;
    this.listen(true);
  };

  private readonly onMove = (event: PointerEvent): void => {
    const press = this.presses.get(event.pointerId);
    if (press === undefined) return;
    // Moves are delivered once per frame; the coalesced ones carry every sample and its time.
    const samples = event.getCoalescedEvents?.() ?? [];
    if (samples.length === 0) press.velocity.add(event.timeStamp, event.clientX, event.clientY);
    for (const sample of samples)
      press.velocity.add(sample.timeStamp, sample.clientX, sample.clientY);
    if (!press.dragging) {
      const moved = Math.hypot(event.clientX - press.startX, event.clientY - press.startY);
      if (moved <= DRAG_SLOP) return;
      if (!this.host.dragStart(event.pointerId, press.element, press.startX, press.startY)) {
        this.presses.delete(event.pointerId);
        return;
      }
      press.dragging = true;
      try {
        press.element.setPointerCapture(event.pointerId);
      } catch {
        // Synthetic pointers cannot be captured; the window listeners still hear them.
      }
    }
    this.host.dragMove(event.pointerId, event.clientX, event.clientY);
  };

  private readonly onUp = (event: PointerEvent): void => {
    const press = this.presses.get(event.pointerId);
    if (press === undefined) return;
    this.presses.delete(event.pointerId);
    if (this.presses.size === 0) this.listen(false);
    if (!press.dragging) return;
    const velocity = press.velocity.velocity(event.timeStamp, this.velocity);
    this.host.dragEnd(event.pointerId, velocity.x, velocity.y);
    this.suppressClickUntil = event.timeStamp + CLICK_AFTER_DRAG_MS;
  };

  private readonly onCancel = (event: PointerEvent): void => {
    const press = this.presses.get(event.pointerId);
    if (press === undefined) return;
    this.presses.delete(event.pointerId);
    if (this.presses.size === 0) this.listen(false);
    if (press.dragging) this.host.dragEnd(event.pointerId, 0, 0);
  };

  // Text selection and native drag-and-drop would fight the drag: off while pressing an element.
  private readonly onSelectStart = (event: Event): void => {
    if (this.presses.size > 0 || this.host.elementAt(event.target) !== null) {
      if (this.host.canDrag()) event.preventDefault();
    }
  };

  private readonly onClick = (event: MouseEvent): void => {
    // Keyboard clicks (Enter, Space: detail 0) are never a drag's.
    if (this.suppressClickUntil < 0 || event.detail === 0) return;
    const late = event.timeStamp > this.suppressClickUntil;
    this.suppressClickUntil = -1;
    if (late) return;
    event.preventDefault();
    event.stopImmediatePropagation();
  };
}
