// `<physical-canvas>` in Svelte 5 templates (checked by svelte-check). Load it once:
// `import '@physical/canvas/svelte';`. Svelte sets the element's properties (`world={world}`)
// and adds `on<event>` attributes as listeners (`onbodytap={...}`).
import type { HTMLAttributes } from 'svelte/elements';
import type {
  PhysicalCanvasAttributes,
  PhysicalCanvasElement,
  PhysicalCanvasEventProps,
  PhysicalCanvasProperties,
} from '@physical/canvas';

/** The attributes `<physical-canvas>` takes in Svelte 5 templates. */
export type PhysicalCanvasSvelteProps = HTMLAttributes<PhysicalCanvasElement> &
  PhysicalCanvasProperties &
  PhysicalCanvasEventProps &
  Omit<PhysicalCanvasAttributes, keyof PhysicalCanvasProperties>;

declare module 'svelte/elements' {
  interface SvelteHTMLElements {
    'physical-canvas': PhysicalCanvasSvelteProps;
  }
}
