// `<physical-canvas>` in Vue templates (checked by vue-tsc / Volar). Load it once:
// `import '@physical/canvas/vue';`. Vue sets the element's properties (`:world="world"`) and
// listens to its events (`@bodytap="..."`); tell the compiler the tag is a custom element
// (`compilerOptions.isCustomElement`).
import type { DefineComponent } from 'vue';
import type {
  PhysicalCanvasAttributes,
  PhysicalCanvasEvents,
  PhysicalCanvasProperties,
} from '@physical/canvas';

/** `@bodytap` and the other events, as Vue's `onBodytap` props. */
export type PhysicalCanvasVueEventProps = {
  [K in keyof PhysicalCanvasEvents as `on${Capitalize<K>}`]?: (
    event: PhysicalCanvasEvents[K],
  ) => void;
};

/** The props `<physical-canvas>` takes in Vue templates. */
export type PhysicalCanvasVueProps = PhysicalCanvasProperties &
  PhysicalCanvasVueEventProps &
  Omit<PhysicalCanvasAttributes, keyof PhysicalCanvasProperties>;

declare module 'vue' {
  interface GlobalComponents {
    'physical-canvas': DefineComponent<PhysicalCanvasVueProps>;
  }
}
