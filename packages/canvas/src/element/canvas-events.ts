import type { CanvasSettingError } from './attribute-parsers.ts';
import type { PointerEventDetail } from './pointer-input.ts';

/** Detail of an `attributeerror` event: the rejected setting; the previous value stays. */
export interface AttributeErrorDetail {
  readonly error: CanvasSettingError;
}

/** Detail of a `pausechange` event (the keyboard toggled `paused`). */
export interface PauseChangeDetail {
  readonly paused: boolean;
}

/**
 * The events `<physical-canvas>` dispatches, by name. They bubble and are composed; they are also
 * in the global `HTMLElementEventMap`, so listeners on ancestors are typed too.
 */
export interface PhysicalCanvasEvents {
  /** A pointer pressed on a body. */
  bodypress: CustomEvent<PointerEventDetail>;
  /** A pointer that pressed a body was released (or cancelled). */
  bodyrelease: CustomEvent<PointerEventDetail>;
  /** A body was tapped (pressed and released without moving). */
  bodytap: CustomEvent<PointerEventDetail>;
  /** Empty space was tapped; `detail.body` is null. */
  backgroundtap: CustomEvent<PointerEventDetail>;
  /** An attribute had a value the element cannot use. */
  attributeerror: CustomEvent<AttributeErrorDetail>;
  /** The keyboard (Space) paused or resumed the simulation. */
  pausechange: CustomEvent<PauseChangeDetail>;
}

/** Every event of `<physical-canvas>`: its own ({@link PhysicalCanvasEvents}) and those of any element. */
export interface PhysicalCanvasEventMap extends HTMLElementEventMap, PhysicalCanvasEvents {}

/** Dispatches one of the element's events: bubbling and composed, so it leaves the shadow root. */
export function emit<K extends keyof PhysicalCanvasEventMap>(
  target: EventTarget,
  type: K,
  detail: PhysicalCanvasEventMap[K] extends CustomEvent<infer D> ? D : never,
): void {
  target.dispatchEvent(new CustomEvent(type, { detail, bubbles: true, composed: true }));
}
