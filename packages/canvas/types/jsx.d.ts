// `<physical-canvas>` in React 19 JSX. Load it once: `import '@physical/canvas/jsx';` (or
// `/// <reference types="@physical/canvas/jsx" />`). React 19 sets the element's properties
// (`world`, `fit`, ...) and adds `on<event>` props as listeners of the element's own events.
import type { DetailedHTMLProps, HTMLAttributes } from 'react';
import type {
  PhysicalCanvasAttributes,
  PhysicalCanvasElement,
  PhysicalCanvasEventProps,
  PhysicalCanvasProperties,
} from '@physical/canvas';

/** The props `<physical-canvas>` takes in React 19 JSX. */
export type PhysicalCanvasJSXProps = DetailedHTMLProps<
  HTMLAttributes<PhysicalCanvasElement>,
  PhysicalCanvasElement
> &
  PhysicalCanvasProperties &
  PhysicalCanvasEventProps &
  Omit<PhysicalCanvasAttributes, keyof PhysicalCanvasProperties>;

declare module 'react' {
  namespace JSX {
    interface IntrinsicElements {
      'physical-canvas': PhysicalCanvasJSXProps;
    }
  }
}
