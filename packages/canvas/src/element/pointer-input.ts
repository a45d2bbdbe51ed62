import type { Body, Vec2 } from '@physical/engine';
import { PointerVelocity } from './pointer-velocity.ts';

/** Detail of the element's pointer events. */
export interface PointerEventDetail {
  /** The body under the pointer when it was pressed; null for `backgroundtap`. */
  readonly body: Body | null;
  /** The pointer's position in the world (m, y-down). */
  readonly point: Readonly<Vec2>;
  /** The pointer event behind it (pointer type, modifiers, buttons). */
  readonly sourceEvent: PointerEvent;
}

/** The pointer may move this far (CSS px) between press and release and still make a tap. */
export const TAP_SLOP = 10;

interface Press {
  readonly pointerId: number;
  readonly body: Body | null;
  readonly clientX: number;
  readonly clientY: number;
  /** Where it pressed in the world (m): the point of the body a drag holds. */
  readonly x: number;
  readonly y: number;
  dragging: boolean;
  readonly velocity: PointerVelocity;
}

/** What {@link PointerInput} needs from its element. */
export interface PointerInputHost {
  /** The world point (m) under a client point (CSS px), or null with no world. */
  clientToWorld(clientX: number, clientY: number): Vec2 | null;
  /** The body at a world point, or null. */
  bodyAt(point: Vec2): Body | null;
  /** Sends one of the element's events. */
  emit(
    type: 'bodypress' | 'bodyrelease' | 'bodytap' | 'backgroundtap',
    detail: PointerEventDetail,
  ): void;
  /** Input arrived: the loop must run. */
  wake(): void;
  /**
   * A press on `body` moved beyond {@link TAP_SLOP}: start dragging it from the press point
   * (x, y) toward (toX, toY) (m). Returns false when it cannot be dragged (drag off, not
   * dynamic).
   */
  dragStart(pointerId: number, body: Body, x: number, y: number, toX: number, toY: number): boolean;
  /** The dragging pointer moved to (x, y) (m). */
  dragMove(pointerId: number, x: number, y: number): void;
  /** The dragging pointer let go moving at (vx, vy) (m/s), or was cancelled (`isThrow` false). */
  dragEnd(pointerId: number, vx: number, vy: number, isThrow: boolean): void;
}

/**
 * Turns pointer events on the canvas into body events, hit-tested against the world:
 * `bodypress` on press over a body, `bodyrelease` when that pointer is released or cancelled,
 * `bodytap` when it is released within {@link TAP_SLOP} of where it was pressed, and
 * `backgroundtap` for such a tap that started over no body. A press on a body that moves beyond
 * the slop drags it (see the host's `dragStart`). Each pointer is tracked on its own
 * (multi-touch), with pointer capture so a release outside the element still arrives.
 */
export class PointerInput {
  private readonly host: PointerInputHost;
  private readonly presses = new Map<number, Press>();
  private target: HTMLElement | null = null;
  private readonly velocity = { x: 0, y: 0 };

  constructor(host: PointerInputHost) {
    this.host = host;
  }

  /** Starts listening on `target`. */
  attach(target: HTMLElement): void {
    this.detach();
    this.target = target;
    target.addEventListener('pointerdown', this.onDown);
    target.addEventListener('pointermove', this.onMove);
    target.addEventListener('pointerup', this.onUp);
    target.addEventListener('pointercancel', this.onCancel);
  }

  /** Stops listening and forgets pressed pointers (drags end without a throw). */
  detach(): void {
    const target = this.target;
    if (target === null) return;
    target.removeEventListener('pointerdown', this.onDown);
    target.removeEventListener('pointermove', this.onMove);
    target.removeEventListener('pointerup', this.onUp);
    target.removeEventListener('pointercancel', this.onCancel);
    for (const press of this.presses.values()) {
      if (press.dragging) this.host.dragEnd(press.pointerId, 0, 0, false);
    }
    this.presses.clear();
    this.target = null;
  }

  private readonly onDown = (event: PointerEvent): void => {
    if (event.pointerType === 'mouse' && event.button !== 0) return;
    const point = this.host.clientToWorld(event.clientX, event.clientY);
    if (point === null) return;
    this.host.wake();
    const body = this.host.bodyAt(point);
    const velocity = new PointerVelocity();
    velocity.add(event.timeStamp, event.clientX, event.clientY);
    this.presses.set(event.pointerId, {
      pointerId: event.pointerId,
      body,
      clientX: event.clientX,
      clientY: event.clientY,
      x: point.x,
      y: point.y,
      dragging: false,
      velocity,
    });
    try {
      (event.currentTarget as HTMLElement).setPointerCapture(event.pointerId);
    } catch {
      // Synthetic events have no active pointer to capture; the release still arrives here.
    }
    if (body !== null) this.host.emit('bodypress', { body, point, sourceEvent: event });
  };

  private readonly onMove = (event: PointerEvent): void => {
    const press = this.presses.get(event.pointerId);
    if (press === undefined || press.body === null) return;
    // Moves arrive once per frame; the coalesced ones carry every sample and its time.
    const samples = event.getCoalescedEvents?.() ?? [];
    if (samples.length === 0) press.velocity.add(event.timeStamp, event.clientX, event.clientY);
    for (const sample of samples) {
      press.velocity.add(sample.timeStamp, sample.clientX, sample.clientY);
    }
    const point = this.host.clientToWorld(event.clientX, event.clientY);
    if (point === null) return;
    if (!press.dragging) {
      const moved = Math.hypot(event.clientX - press.clientX, event.clientY - press.clientY);
      if (moved <= TAP_SLOP) return;
      press.dragging = this.host.dragStart(
        press.pointerId,
        press.body,
        press.x,
        press.y,
        point.x,
        point.y,
      );
    } else {
      this.host.dragMove(press.pointerId, point.x, point.y);
    }
    this.host.wake();
  };

  private readonly onUp = (event: PointerEvent): void => {
    const press = this.presses.get(event.pointerId);
    if (press === undefined) return;
    this.presses.delete(event.pointerId);
    const point = this.host.clientToWorld(event.clientX, event.clientY);
    if (press.dragging) {
      // The finger's velocity, from client px/s to m/s through two world points.
      const velocity = press.velocity.velocity(event.timeStamp, this.velocity);
      const ahead = this.host.clientToWorld(event.clientX + velocity.x, event.clientY + velocity.y);
      const vx = point === null || ahead === null ? 0 : ahead.x - point.x;
      const vy = point === null || ahead === null ? 0 : ahead.y - point.y;
      this.host.dragEnd(press.pointerId, vx, vy, true);
      this.host.wake();
    }
    if (point === null) return;
    const moved = Math.hypot(event.clientX - press.clientX, event.clientY - press.clientY);
    const isTap = moved <= TAP_SLOP;
    if (press.body !== null) {
      this.host.emit('bodyrelease', { body: press.body, point, sourceEvent: event });
      if (isTap) this.host.emit('bodytap', { body: press.body, point, sourceEvent: event });
    } else if (isTap) {
      this.host.emit('backgroundtap', { body: null, point, sourceEvent: event });
    }
  };

  private readonly onCancel = (event: PointerEvent): void => {
    const press = this.presses.get(event.pointerId);
    if (press === undefined) return;
    this.presses.delete(event.pointerId);
    if (press.dragging) this.host.dragEnd(press.pointerId, 0, 0, false);
    const point = this.host.clientToWorld(event.clientX, event.clientY);
    if (press.body !== null && point !== null) {
      this.host.emit('bodyrelease', { body: press.body, point, sourceEvent: event });
    }
  };
}
