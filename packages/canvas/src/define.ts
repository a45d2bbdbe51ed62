// Side-effect entry: `import '@physical/canvas/define'` registers <physical-canvas>.
// This import keeps the tag's global typings (HTMLElementTagNameMap, HTMLElementEventMap)
// in define.d.ts, so this import alone types `document.querySelector('physical-canvas')`.
import './element/element-typings.ts';
import { define } from './element/define-physical-canvas.ts';

define();
