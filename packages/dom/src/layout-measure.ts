import { PhysicalError } from '@physical/engine';
import { cornerRadius, parseCornerRadius } from './element-shape.ts';

/**
 * Where the container is on screen: its padding box's top-left corner in client px, and the
 * scale from the container's own CSS px to client px (CSS `zoom`, or a scaled ancestor).
 */
export interface ContainerFrame {
  /** Client x, y (CSS px of the viewport) of the padding box's top-left corner. */
  left: number;
  top: number;
  /** Client px per local CSS px (1 unless zoomed or scaled). */
  scale: number;
  /** Padding box size (local CSS px): the walls' rectangle. */
  width: number;
  height: number;
}

/** An element's layout slot, in the container's local CSS px (padding box origin). */
export interface Slot {
  /** Centre of the border box. */
  centerX: number;
  centerY: number;
  width: number;
  height: number;
  /** Corner radius (px), clamped to half the smaller side. */
  radius: number;
}

/** Reads the container's frame. Layout reads: call it outside frames only. */
export function measureContainer(container: HTMLElement, out: ContainerFrame): ContainerFrame {
  const rect = container.getBoundingClientRect();
  const layoutWidth = container.offsetWidth;
  const scale = layoutWidth > 0 && rect.width > 0 ? rect.width / layoutWidth : 1;
  out.scale = scale;
  out.left = rect.left + container.clientLeft * scale - container.scrollLeft * scale;
  out.top = rect.top + container.clientTop * scale - container.scrollTop * scale;
  out.width = container.clientWidth;
  out.height = container.clientHeight;
  return out;
}

/**
 * Measures the layout slots of `elements` in one batch: their transforms are set to `none`, all
 * boxes read (one layout), and the transforms put back, all in the same task, so nothing is ever
 * painted without its transform. Throws for an inline element, which CSS cannot transform.
 */
export function measureSlots(
  container: HTMLElement,
  elements: readonly HTMLElement[],
  frame: ContainerFrame,
  out: Slot[],
): Slot[] {
  const transforms = elements.map((element) => element.style.transform);
  for (const element of elements) element.style.transform = 'none';
  try {
    measureContainer(container, frame);
    const scale = frame.scale;
    out.length = elements.length;
    for (let i = 0; i < elements.length; i++) {
      const element = elements[i]!;
      const style = getComputedStyle(element);
      if (style.display === 'inline') {
        throw new PhysicalError(
          'elements',
          `<${element.localName}> is display: inline, which CSS cannot transform; give it display: inline-block or block.`,
        );
      }
      const rect = element.getBoundingClientRect();
      const width = rect.width / scale;
      const height = rect.height / scale;
      const radius = cornerRadius(
        [
          parseCornerRadius(style.borderTopLeftRadius, width, height),
          parseCornerRadius(style.borderTopRightRadius, width, height),
          parseCornerRadius(style.borderBottomRightRadius, width, height),
          parseCornerRadius(style.borderBottomLeftRadius, width, height),
        ],
        width,
        height,
      );
      const slot = out[i] ?? { centerX: 0, centerY: 0, width: 0, height: 0, radius: 0 };
      slot.centerX = (rect.left - frame.left) / scale + width / 2;
      slot.centerY = (rect.top - frame.top) / scale + height / 2;
      slot.width = width;
      slot.height = height;
      slot.radius = radius;
      out[i] = slot;
    }
  } finally {
    for (let i = 0; i < elements.length; i++) elements[i]!.style.transform = transforms[i]!;
  }
  return out;
}
