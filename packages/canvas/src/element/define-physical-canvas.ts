import { PhysicalCanvasElement } from './physical-canvas-element.ts';

// The tag's global typings (HTMLElementTagNameMap, HTMLElementEventMap) live there.
import './element-typings.ts';

/**
 * Registers `<physical-canvas>` (or the element under another tag name). Safe to call more than
 * once, and a no-op outside a browser (server rendering). Returns the element class.
 *
 * @example
 * import { define } from '@physical/canvas';
 * define();
 * document.querySelector('physical-canvas')!.world = world;
 */
export function define(tagName = 'physical-canvas'): typeof PhysicalCanvasElement {
  if (typeof customElements === 'undefined') return PhysicalCanvasElement;
  const existing = customElements.get(tagName);
  if (existing === undefined) {
    // A class can be registered once; another tag name gets a subclass.
    const registered = customElements.getName(PhysicalCanvasElement) === null;
    customElements.define(
      tagName,
      registered ? PhysicalCanvasElement : class extends PhysicalCanvasElement {},
    );
  }
  return PhysicalCanvasElement;
}
